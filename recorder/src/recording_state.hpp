#pragma once
// The reader's state (Recording's), shared by reader.cpp, read_arrays.cpp and
// read_method_groups.cpp.

#include "h5.hpp"

#include "collidescope/recorder/recording_info.hpp"
#include "collidescope/recorder/schema.hpp"

#include <algorithm>

namespace collidescope::recorder {

/// Reads offsets[row] and offsets[row + 1] of a CSR offsets dataset and checks them against the
/// flat array's rows (fails naming both datasets when they disagree).
std::pair<std::uint64_t, std::uint64_t> offset_range(const h5::Where& where, hid_t file, const std::string& offsets_path,
                                                     const std::string& flat_path, std::uint64_t row);

struct RecordingState {
    h5::Where where;
    h5::Id file;
    std::int64_t version_major = 0;
    std::int64_t version_minor = 0;
    bool finished = false;
    std::string interrupted;            ///< attribute `interrupted` ("" when absent)
    std::uint64_t frames_requested = 0; ///< frame_end - frame_begin (0 when absent)
    double fps = 0;                     ///< attribute `fps` (1.4; 0 when absent)
    std::string clip;                   ///< attribute `clip` (1.4; "" when absent)
    char up_axis = 0;                   ///< attribute `up_axis` (1.4; 0 when absent)
    std::uint64_t frames = 0;
    std::vector<ObjectInfo> objects;
    std::vector<VirtualSource> virtual_sources;  ///< a virtual join's mappings, checked at open

    explicit RecordingState(const std::string& path) : where(path) {}

    h5::Id dataset(const std::string& path) const { return h5::open_dataset(where, file.get(), path); }
    std::uint64_t rows(const std::string& path) const {
        const h5::Id d = dataset(path);
        const std::vector<hsize_t> dims = h5::shape(where, d.get(), path);
        return dims.empty() ? 0 : dims[0];
    }
    template <class T>
    std::vector<T> read_all(const std::string& path, hid_t mem_type, std::uint64_t limit) const {
        const h5::Id d = dataset(path);
        const std::vector<hsize_t> dims = h5::shape(where, d.get(), path);
        if (dims.size() != 1) where.fail(path + " is not 1-D");
        std::vector<T> values(std::min<std::uint64_t>(dims[0], limit));
        h5::read_rows(where, d.get(), path, mem_type, 0, values.size(), values.data());
        return values;
    }

    /// /frames/index of the last complete frame (frames > 0).
    std::uint32_t last_frame_index() const {
        const h5::Id d = dataset(schema::k_frame_index);
        std::uint32_t value = 0;
        h5::read_rows(where, d.get(), schema::k_frame_index, H5T_NATIVE_UINT32, frames - 1, 1, &value);
        return value;
    }

    void open_file();
    void check_schema();
    void read_time_attributes();
    void count_frames();
    void read_objects();
    /// Fails unless `row` is a complete frame.
    void check_row(std::uint64_t row) const {
        if (row >= frames) where.fail("frame row " + std::to_string(row) + " is not complete");
    }
    std::vector<std::string> group_members(const std::string& group) const {
        const h5::Id g = h5::open_group(where, file.get(), group);
        return h5::member_names(where, g.get(), group);
    }
};

}  // namespace collidescope::recorder
