#pragma once
// Reading a block of rows of a dataset, and a run of CSR offsets checked against the rows they
// point into (recorder/src, private; read_regions.cpp, read_intervals.cpp).

#include "recording_state.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace collidescope::recorder {

// rows [first, first + count) of a dataset of `width` columns.
template <class T>
inline std::vector<T> read_block(const RecordingState& impl, const char* path, hid_t type, std::uint64_t first,
                                 std::uint64_t count, std::uint64_t width) {
    const h5::Id d = impl.dataset(path);
    const std::vector<hsize_t> dims = h5::shape(impl.where, d.get(), path);
    const std::uint64_t columns = dims.size() == 2 ? dims[1] : 1;
    if (dims.empty() || columns != width || first + count > dims[0]) {
        impl.where.fail(std::string(path) + ": rows " + std::to_string(first) + ".." + std::to_string(first + count) +
                        " of " + std::to_string(width) + " columns are not in the dataset (corrupt recording)");
    }
    std::vector<T> values(count * width);
    if (count > 0) h5::read_rows(impl.where, d.get(), path, type, first, count, values.data());
    return values;
}

// offsets[first .. first + count] (count + 1 entries), ascending and within `limit`.
inline std::vector<std::uint64_t> read_offsets(const RecordingState& impl, const char* path, std::uint64_t first,
                                               std::uint64_t count, const char* into) {
    std::vector<std::uint64_t> offsets = read_block<std::uint64_t>(impl, path, H5T_NATIVE_UINT64, first, count + 1, 1);
    const std::uint64_t limit = impl.rows(into);
    for (std::size_t i = 0; i < offsets.size(); ++i) {
        if ((i > 0 && offsets[i] < offsets[i - 1]) || offsets[i] > limit) {
            impl.where.fail(std::string(path) + ": entry " + std::to_string(first + i) + " (" + std::to_string(offsets[i]) +
                            ") is out of order or past " + into + " (corrupt recording)");
        }
    }
    return offsets;
}

}  // namespace collidescope::recorder
