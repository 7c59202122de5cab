// /regions (schema 1.5; 1.6 adds /regions/penetration: the inside areas and the depth): each frame's interpenetration regions, written only by `record
// --regions`. Rows first, offsets after them, so an offset never points past its rows.

#include "recording_writer.hpp"

#include "collidescope/recorder/schema.hpp"

namespace collidescope::recorder {
namespace {

constexpr hsize_t k_region_chunk = 1024;   // regions per chunk
constexpr hsize_t k_point_chunk = 8192;    // curve points per chunk
constexpr const char* k_unit_measures =
    "input length unit (curve_length and the box; coplanar_area: its square)";
constexpr const char* k_unit_penetration = "input length unit (depth; inside_area_a and inside_area_b: its square)";

}  // namespace

void RecordingWriter::create_regions() {
    h5::create_group(m_where, m_file.get(), schema::k_regions);
    RegionColumns& r = m_regions;
    const auto offsets = [&](const char* path, hsize_t chunk) {
        Column column = make_column(path, {H5T_STD_U64LE, 1, chunk, 0, schema::k_unit_none});
        const std::uint64_t zero = 0;
        append_value(column, H5T_NATIVE_UINT64, &zero);
        return column;
    };
    r.offsets = offsets(schema::k_region_offsets, 256);
    r.table = make_column(schema::k_region_table, {H5T_STD_U32LE, 7, k_region_chunk, m_deflate, schema::k_unit_none});
    r.measures = make_column(schema::k_region_measures, {H5T_IEEE_F64LE, 8, k_region_chunk, m_deflate, k_unit_measures});
    r.penetration =
        make_column(schema::k_region_penetration, {H5T_IEEE_F64LE, 3, k_region_chunk, m_deflate, k_unit_penetration});
    r.curve_offsets = offsets(schema::k_region_curve_offsets, k_region_chunk);
    r.curve_closed = make_column(schema::k_region_curve_closed, {H5T_STD_U8LE, 1, k_region_chunk, 0, schema::k_unit_none});
    r.point_offsets = offsets(schema::k_region_point_offsets, k_region_chunk);
    r.points = make_column(schema::k_region_points, {H5T_IEEE_F64LE, 3, k_point_chunk, m_deflate, schema::k_unit_length});
    r.predecessor_offsets = offsets(schema::k_region_predecessor_offsets, k_region_chunk);
    r.predecessors =
        make_column(schema::k_region_predecessors, {H5T_STD_U32LE, 1, k_region_chunk, 0, schema::k_unit_none});
    r.present = true;
}

void RecordingWriter::append_regions(std::span<const FrameRecord> records) {
    RegionColumns& r = m_regions;
    // Every level's running end, turned into the next level's offsets.
    std::vector<std::uint32_t> table, predecessors;
    std::vector<double> measures, penetration, xyz;
    std::vector<std::uint8_t> closed;
    std::vector<std::uint64_t> frame_ends, curve_ends, point_ends, predecessor_ends;
    std::uint64_t regions = r.table.length, curves = r.curve_closed.length, points = r.points.length,
                  preds = r.predecessors.length;
    for (const FrameRecord& record : records) {
        const RegionsRecord& f = record.regions;
        table.insert(table.end(), f.table.begin(), f.table.end());
        measures.insert(measures.end(), f.measures.begin(), f.measures.end());
        penetration.insert(penetration.end(), f.penetration.begin(), f.penetration.end());
        closed.insert(closed.end(), f.closed.begin(), f.closed.end());
        xyz.insert(xyz.end(), f.xyz.begin(), f.xyz.end());
        predecessors.insert(predecessors.end(), f.predecessors.begin(), f.predecessors.end());
        for (const std::uint64_t n : f.curves) curve_ends.push_back(curves += n);
        for (const std::uint64_t n : f.points) point_ends.push_back(points += n);
        for (const std::uint64_t n : f.predecessor_counts) predecessor_ends.push_back(preds += n);
        frame_ends.push_back(regions += f.table.size() / 7);
    }
    const auto rows = [&](Column& column, hid_t type, std::size_t count, const void* data) {
        h5::append_rows(m_where, column.dataset.get(), column.path, column.length, type, count, data);
    };
    rows(r.points, H5T_NATIVE_DOUBLE, xyz.size() / 3, xyz.data());
    rows(r.point_offsets, H5T_NATIVE_UINT64, point_ends.size(), point_ends.data());
    rows(r.curve_closed, H5T_NATIVE_UINT8, closed.size(), closed.data());
    rows(r.curve_offsets, H5T_NATIVE_UINT64, curve_ends.size(), curve_ends.data());
    rows(r.predecessors, H5T_NATIVE_UINT32, predecessors.size(), predecessors.data());
    rows(r.predecessor_offsets, H5T_NATIVE_UINT64, predecessor_ends.size(), predecessor_ends.data());
    rows(r.penetration, H5T_NATIVE_DOUBLE, penetration.size() / 3, penetration.data());
    rows(r.measures, H5T_NATIVE_DOUBLE, measures.size() / 8, measures.data());
    rows(r.table, H5T_NATIVE_UINT32, table.size() / 7, table.data());
    rows(r.offsets, H5T_NATIVE_UINT64, frame_ends.size(), frame_ends.data());
}

}  // namespace collidescope::recorder
