// Reading the methods' own details back (schema 1.1 and 1.2): the /frames/<method> groups, the
// GPU cull's passes, survivors and depth images. Files of older minors lack some of them: those
// read as empty.

#include "collidescope/recorder/reader.hpp"

#include "recording_state.hpp"

#include "collidescope/recorder/schema.hpp"
#include "collidescope/stats.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace collidescope::recorder {
namespace {

/// The value names of a known details group, in its visitor's order; nullopt for other groups.
std::optional<std::vector<std::string>> visitor_names(const std::string& group) {
    std::vector<std::string> names;
    const auto add = [&](const char* name, double, const char*) { names.emplace_back(name); };
    if (group == "gpu") for_each_gpu_value(GpuFrameInfo{}, add);
    else if (group == "aabb") for_each_aabb_value(AabbFrameInfo{}, add);
    else if (group == "decision") for_each_decision_value(DecisionInfo{}, add);
    else if (group == "hybrid") for_each_hybrid_value(HybridFrameInfo{}, add);
    else return std::nullopt;
    return names;
}

// The decision values that hold codes (DecisionInfo's uint8 fields). Readers turn them back
// into integers (inspect's names, replay's mode), so a value that is no uint8 is refused here:
// converting it would be undefined behaviour.
bool is_code_column(const std::string& group, const std::string& name) {
    return group == "decision" && (name == "policy" || name == "mode" || name == "action" || name == "reason");
}

bool is_code(double value) {
    return std::isnan(value) || (value >= 0 && value <= 255 && value == std::floor(value));
}

GpuPassInfo pass_from_row(const std::uint64_t* row) {
    // for_each_pass_field's order; the round-trip tests compare every field with the engine's.
    GpuPassInfo pass;
    pass.level = static_cast<std::uint8_t>(row[0]);
    pass.view = static_cast<std::uint8_t>(row[1]);
    pass.reverse = static_cast<std::uint8_t>(row[2]);
    pass.items_tested = static_cast<std::uint32_t>(row[3]);
    pass.items_hidden = static_cast<std::uint32_t>(row[4]);
    pass.queries = static_cast<std::uint32_t>(row[5]);
    pass.samples_passed = row[6];
    pass.triangles_per_query = static_cast<std::uint32_t>(row[7]);
    return pass;
}

}  // namespace

std::vector<Series<double>> Recording::frame_values(const std::string& group) const {
    const RecordingState& impl = *m_impl;
    const std::string path = std::string(schema::k_frames) + "/" + group;
    if (group.empty() || group.find('/') != std::string::npos || !h5::exists(impl.file.get(), path)) return {};
    std::vector<std::string> names;
    if (auto known = visitor_names(group)) {
        names = std::move(*known);
    } else {
        for (std::string& name : impl.group_members(path)) {
            if (name != schema::k_present) names.push_back(std::move(name));
        }
    }
    std::vector<std::uint8_t> present(impl.frames, 1);
    const std::string present_path = path + "/" + schema::k_present;
    if (h5::exists(impl.file.get(), present_path)) {
        present = impl.read_all<std::uint8_t>(present_path, H5T_NATIVE_UINT8, impl.frames);
        if (present.size() < impl.frames) impl.where.fail(present_path + " is shorter than the frames");
    }
    std::vector<Series<double>> out;
    for (const std::string& name : names) {
        const std::string column = path + "/" + name;
        if (!h5::exists(impl.file.get(), column)) continue;  // a value added after the file's minor
        Series<double> series{name, unit_of(column), impl.read_all<double>(column, H5T_NATIVE_DOUBLE, impl.frames)};
        if (series.values.size() < impl.frames) impl.where.fail(column + " is shorter than the frames");
        for (std::size_t r = 0; r < series.values.size(); ++r) {
            if (present[r] == 0) series.values[r] = std::numeric_limits<double>::quiet_NaN();
            if (is_code_column(group, name) && !is_code(series.values[r])) {
                char value[32];
                std::snprintf(value, sizeof value, "%g", series.values[r]);
                impl.where.fail(column + ": frame row " + std::to_string(r) + " holds " + value +
                                ", not a code 0..255 (corrupt recording)");
            }
        }
        out.push_back(std::move(series));
    }
    return out;
}

std::vector<GpuPassInfo> Recording::gpu_passes(std::uint64_t row) const {
    const RecordingState& impl = *m_impl;
    impl.check_row(row);
    if (!h5::exists(impl.file.get(), schema::k_gpu_pass_offsets)) return {};
    const auto [begin, end] = offset_range(impl.where, impl.file.get(), schema::k_gpu_pass_offsets, schema::k_gpu_passes, row);
    const h5::Id d = impl.dataset(schema::k_gpu_passes);
    const std::vector<hsize_t> dims = h5::shape(impl.where, d.get(), schema::k_gpu_passes);
    constexpr hsize_t k_fields = 8;
    if (dims.size() != 2 || dims[1] != k_fields) impl.where.fail(std::string(schema::k_gpu_passes) + " is not (N, 8)");
    std::vector<std::uint64_t> values((end - begin) * k_fields);
    h5::read_rows(impl.where, d.get(), schema::k_gpu_passes, H5T_NATIVE_UINT64, begin, end - begin, values.data());
    std::vector<GpuPassInfo> out;
    for (std::uint64_t p = 0; p < end - begin; ++p) out.push_back(pass_from_row(&values[p * k_fields]));
    return out;
}

std::vector<std::array<std::uint32_t, 2>> Recording::survivors(std::uint64_t row) const {
    const RecordingState& impl = *m_impl;
    impl.check_row(row);
    if (!h5::exists(impl.file.get(), schema::k_gpu_survivor_offsets)) return {};
    const auto [begin, end] =
        offset_range(impl.where, impl.file.get(), schema::k_gpu_survivor_offsets, schema::k_gpu_survivors, row);
    const h5::Id d = impl.dataset(schema::k_gpu_survivors);
    const std::vector<hsize_t> dims = h5::shape(impl.where, d.get(), schema::k_gpu_survivors);
    if (dims.size() != 2 || dims[1] != 2) impl.where.fail(std::string(schema::k_gpu_survivors) + " is not (N, 2)");
    std::vector<std::array<std::uint32_t, 2>> out(end - begin);
    h5::read_rows(impl.where, d.get(), schema::k_gpu_survivors, H5T_NATIVE_UINT32, begin, out.size(), out.data());
    return out;
}

std::vector<GpuDepthImage> Recording::depth_images(std::uint64_t row) const {
    const RecordingState& impl = *m_impl;
    impl.check_row(row);
    if (!h5::exists(impl.file.get(), schema::k_depth_image_offsets)) return {};
    const auto [begin, end] =
        offset_range(impl.where, impl.file.get(), schema::k_depth_image_offsets, schema::k_depth_info, row);
    const std::uint64_t count = end - begin;
    if (count == 0) return {};
    std::vector<std::uint32_t> info(count * 4);
    std::vector<double> range(count * 2);
    std::vector<std::uint64_t> pixel_offsets(count + 1);
    // A copy of `begin`: clang before 16 cannot capture a structured binding.
    const auto read = [&, first = begin](const char* path, hid_t type, std::uint64_t rows, void* out) {
        const h5::Id d = impl.dataset(path);
        h5::read_rows(impl.where, d.get(), path, type, first, rows, out);
    };
    read(schema::k_depth_info, H5T_NATIVE_UINT32, count, info.data());
    read(schema::k_depth_range, H5T_NATIVE_DOUBLE, count, range.data());
    read(schema::k_depth_pixel_offsets, H5T_NATIVE_UINT64, count + 1, pixel_offsets.data());
    const h5::Id pixels = impl.dataset(schema::k_depth_pixels);
    const std::uint64_t pixel_rows = impl.rows(schema::k_depth_pixels);
    std::vector<GpuDepthImage> out;
    std::vector<std::uint16_t> quantised;
    for (std::uint64_t i = 0; i < count; ++i) {
        GpuDepthImage image;
        image.level = static_cast<std::uint8_t>(info[4 * i]);
        image.view = static_cast<std::uint8_t>(info[4 * i + 1]);
        image.width = info[4 * i + 2];
        image.height = info[4 * i + 3];
        image.depth_near = range[2 * i];
        image.depth_far = range[2 * i + 1];
        const std::uint64_t first = pixel_offsets[i];
        const std::uint64_t last = pixel_offsets[i + 1];
        if (first > last || last > pixel_rows || last - first != std::uint64_t{image.width} * image.height) {
            impl.where.fail(std::string(schema::k_depth_pixel_offsets) + ": image " + std::to_string(begin + i) + " (" +
                            std::to_string(image.width) + "x" + std::to_string(image.height) + ") has pixels " +
                            std::to_string(first) + ".." + std::to_string(last) + " (corrupt recording)");
        }
        quantised.resize(last - first);
        h5::read_rows(impl.where, pixels.get(), schema::k_depth_pixels, H5T_NATIVE_UINT16, first, last - first,
                      quantised.data());
        image.depth.resize(quantised.size());
        for (std::size_t p = 0; p < quantised.size(); ++p) {
            image.depth[p] = static_cast<float>(quantised[p] / schema::k_depth_scale);
        }
        out.push_back(std::move(image));
    }
    return out;
}

}  // namespace collidescope::recorder
