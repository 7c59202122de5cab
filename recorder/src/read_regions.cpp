// Reading /regions (schema 1.5; /regions/penetration from 1.6): a frame's table rows, then each region's curves and their
// points, and its predecessors, through three levels of CSR offsets, each checked against the
// rows it points into.

#include "read_blocks.hpp"
#include "recording_state.hpp"

#include "collidescope/recorder/reader.hpp"

namespace collidescope::recorder {

bool Recording::has_regions() const { return h5::exists(m_impl->file.get(), schema::k_region_offsets); }

std::vector<RecordedRegion> Recording::regions(std::uint64_t row, bool with_curves) const {
    const RecordingState& impl = *m_impl;
    impl.check_row(row);
    if (!has_regions()) return {};
    const std::vector<std::uint64_t> frame = read_offsets(impl, schema::k_region_offsets, row, 1, schema::k_region_table);
    const std::uint64_t first = frame[0], count = frame[1] - frame[0];
    const auto table = read_block<std::uint32_t>(impl, schema::k_region_table, H5T_NATIVE_UINT32, first, count, 7);
    const auto measures = read_block<double>(impl, schema::k_region_measures, H5T_NATIVE_DOUBLE, first, count, 8);
    // Schema 1.6; a 1.5 recording has none (NaN: not known).
    const bool has_penetration = h5::exists(impl.file.get(), schema::k_region_penetration);
    const auto penetration = has_penetration ? read_block<double>(impl, schema::k_region_penetration, H5T_NATIVE_DOUBLE,
                                                                  first, count, 3)
                                             : std::vector<double>{};
    const auto preds =
        read_offsets(impl, schema::k_region_predecessor_offsets, first, count, schema::k_region_predecessors);
    // Curves: offsets per region into the curves, per curve into the points (read only when asked).
    std::vector<std::uint64_t> curves(count + 1, 0), points{0};
    std::vector<std::uint8_t> closed;
    std::vector<double> xyz;
    if (with_curves) {
        curves = read_offsets(impl, schema::k_region_curve_offsets, first, count, schema::k_region_curve_closed);
        const std::uint64_t curve_count = curves.back() - curves.front();
        closed = read_block<std::uint8_t>(impl, schema::k_region_curve_closed, H5T_NATIVE_UINT8, curves.front(),
                                          curve_count, 1);
        points = read_offsets(impl, schema::k_region_point_offsets, curves.front(), curve_count, schema::k_region_points);
        xyz = read_block<double>(impl, schema::k_region_points, H5T_NATIVE_DOUBLE, points.front(),
                                 points.back() - points.front(), 3);
    }
    const auto predecessors = read_block<std::uint32_t>(impl, schema::k_region_predecessors, H5T_NATIVE_UINT32,
                                                        preds.front(), preds.back() - preds.front(), 1);
    std::vector<RecordedRegion> out(count);
    for (std::uint64_t r = 0; r < count; ++r) {
        RecordedRegion& region = out[r];
        const std::uint32_t* t = &table[7 * r];
        region.id = t[0], region.obj_a = t[1], region.obj_b = t[2], region.pairs = t[3];
        region.triangles_a = t[4], region.triangles_b = t[5], region.loops = t[6];
        region.curve_length = measures[8 * r];
        region.coplanar_area = measures[8 * r + 1];
        for (int k = 0; k < 6; ++k) region.box[k] = measures[8 * r + 2 + k];
        if (has_penetration) {
            region.inside_area_a = penetration[3 * r];
            region.inside_area_b = penetration[3 * r + 1];
            region.depth = penetration[3 * r + 2];
        }
        for (std::uint64_t c = curves[r]; c < curves[r + 1]; ++c) {
            const std::uint64_t local = c - curves.front();
            RecordedRegion::Curve curve;
            curve.closed = closed[local] != 0;
            curve.xyz.assign(xyz.begin() + 3 * (points[local] - points.front()),
                             xyz.begin() + 3 * (points[local + 1] - points.front()));
            region.curves.push_back(std::move(curve));
        }
        region.predecessors.assign(predecessors.begin() + (preds[r] - preds.front()),
                                   predecessors.begin() + (preds[r + 1] - preds.front()));
    }
    return out;
}

}  // namespace collidescope::recorder
