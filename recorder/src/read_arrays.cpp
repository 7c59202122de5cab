// Reading a recording back: flat arrays through their offsets, metadata, dataset listing.

#include "collidescope/recorder/reader.hpp"

#include "recording_state.hpp"

#include "collidescope/recorder/schema.hpp"

#include <algorithm>

namespace collidescope::recorder {

// Reads offsets[row] and offsets[row + 1] of a CSR offsets dataset and checks them against the
// flat array's rows.
std::pair<std::uint64_t, std::uint64_t> offset_range(const h5::Where& where, hid_t file, const std::string& offsets_path,
                                                     const std::string& flat_path, std::uint64_t row) {
    const h5::Id offsets = h5::open_dataset(where, file, offsets_path);
    std::uint64_t range[2] = {0, 0};
    h5::read_rows(where, offsets.get(), offsets_path, H5T_NATIVE_UINT64, row, 2, range);
    const h5::Id flat = h5::open_dataset(where, file, flat_path);
    const std::vector<hsize_t> dims = h5::shape(where, flat.get(), flat_path);
    if (range[0] > range[1] || dims.empty() || range[1] > dims[0]) {
        where.fail(offsets_path + ": frame row " + std::to_string(row) + " has offsets " + std::to_string(range[0]) +
                   ".." + std::to_string(range[1]) + " outside " + flat_path + " (corrupt recording)");
    }
    return {range[0], range[1]};
}

std::vector<TrianglePair> Recording::pairs(std::uint64_t row) const {
    const RecordingState& impl = *m_impl;
    if (row >= impl.frames) impl.where.fail("frame row " + std::to_string(row) + " is not complete");
    const auto [begin, end] = offset_range(impl.where, impl.file.get(), schema::k_pair_offsets, schema::k_pairs, row);
    std::vector<TrianglePair> out(end - begin);
    const h5::Id d = impl.dataset(schema::k_pairs);
    h5::read_rows(impl.where, d.get(), schema::k_pairs, H5T_NATIVE_UINT32, begin, out.size(), out.data());
    return out;
}

std::vector<std::uint64_t> Recording::pair_counts() const {
    std::vector<std::uint64_t> offsets = read_u64(schema::k_pair_offsets);
    offsets.resize(std::min<std::size_t>(offsets.size(), m_impl->frames + 1));
    std::vector<std::uint64_t> counts;
    for (std::size_t r = 0; r + 1 < offsets.size(); ++r) {
        if (offsets[r + 1] < offsets[r]) m_impl->where.fail(std::string(schema::k_pair_offsets) + " decreases at entry " + std::to_string(r + 1));
        counts.push_back(offsets[r + 1] - offsets[r]);
    }
    return counts;
}

std::vector<float> Recording::positions(std::uint32_t object, std::uint64_t row) const {
    const RecordingState& impl = *m_impl;
    if (object >= impl.objects.size()) impl.where.fail("no object " + std::to_string(object));
    if (row >= impl.frames) impl.where.fail("frame row " + std::to_string(row) + " is not complete");
    const std::string prefix = schema::object_group(object) + "/";
    const auto [begin, end] = offset_range(impl.where, impl.file.get(), prefix + schema::k_vertex_offsets,
                                           prefix + schema::k_positions, row);
    std::vector<float> out((end - begin) * 3);
    const h5::Id d = impl.dataset(prefix + schema::k_positions);
    h5::read_rows(impl.where, d.get(), prefix + schema::k_positions, H5T_NATIVE_FLOAT, begin, end - begin, out.data());
    return out;
}

std::size_t Recording::topology_at(std::uint32_t object, std::uint32_t frame) const {
    const RecordingState& impl = *m_impl;
    if (object >= impl.objects.size()) impl.where.fail("no object " + std::to_string(object));
    const std::vector<TopologyInfo>& topologies = impl.objects[object].topologies;
    std::size_t found = topologies.size();
    for (std::size_t r = 0; r < topologies.size() && topologies[r].from_frame <= frame; ++r) found = r;
    if (found == topologies.size()) {
        impl.where.fail("object " + std::to_string(object) + " has no topology for frame " + std::to_string(frame));
    }
    return found;
}

std::vector<TriIndices> Recording::triangles(std::uint32_t object, std::size_t topology) const {
    const RecordingState& impl = *m_impl;
    if (object >= impl.objects.size() || topology >= impl.objects[object].topologies.size()) {
        impl.where.fail("no topology " + std::to_string(topology) + " of object " + std::to_string(object));
    }
    const TopologyInfo& info = impl.objects[object].topologies[topology];
    const std::string path = schema::object_group(object) + "/" + schema::k_triangles;
    std::vector<TriIndices> out(info.triangle_count);
    const h5::Id d = impl.dataset(path);
    h5::read_rows(impl.where, d.get(), path, H5T_NATIVE_UINT32, info.first_row, info.triangle_count, out.data());
    return out;
}

namespace {

herr_t collect_attr_name(hid_t, const char* name, const H5A_info_t*, void* data) {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> Recording::metadata() const {
    const RecordingState& impl = *m_impl;
    std::vector<std::string> names;
    hsize_t index = 0;
    if (H5Aiterate2(impl.file.get(), H5_INDEX_CRT_ORDER, H5_ITER_INC, &index, collect_attr_name, &names) < 0) {
        names.clear();
        index = 0;
        impl.where.check(H5Aiterate2(impl.file.get(), H5_INDEX_NAME, H5_ITER_INC, &index, collect_attr_name, &names),
                         "cannot list the root attributes");
    }
    std::vector<std::pair<std::string, std::string>> out;
    for (const std::string& name : names) {
        const h5::Id attr = impl.where.own(H5Aopen(impl.file.get(), name.c_str(), H5P_DEFAULT), H5Aclose,
                                           "cannot open attribute " + name);
        const h5::Id type = impl.where.own(H5Aget_type(attr.get()), H5Tclose, "cannot read attribute " + name);
        const H5T_class_t type_class = H5Tget_class(type.get());
        if (type_class == H5T_STRING) {
            out.emplace_back(name, h5::read_string_attr(impl.where, impl.file.get(), name).value_or(""));
        } else if (type_class == H5T_INTEGER) {
            out.emplace_back(name, std::to_string(h5::read_int_attr(impl.where, impl.file.get(), name).value_or(0)));
        } else {
            out.emplace_back(name, "(not text or integer)");
        }
    }
    return out;
}

std::vector<std::string> Recording::dataset_paths() const {
    std::vector<std::string> paths;
    m_impl->where.check(H5Ovisit2(m_impl->file.get(), H5_INDEX_NAME, H5_ITER_INC, h5::collect_dataset, &paths, H5O_INFO_BASIC),
                        "cannot list the datasets");
    return paths;
}

std::string Recording::unit_of(const std::string& dataset) const {
    const h5::Id d = m_impl->dataset(dataset);
    return h5::read_string_attr(m_impl->where, d.get(), schema::k_attr_unit).value_or("");
}

std::uint64_t Recording::rows_of(const std::string& dataset) const { return m_impl->rows(dataset); }

std::uint64_t Recording::storage_of(const std::string& dataset) const {
    const h5::Id d = m_impl->dataset(dataset);
    return H5Dget_storage_size(d.get());
}

}  // namespace collidescope::recorder
