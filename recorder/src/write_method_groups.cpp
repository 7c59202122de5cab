// The HDF5 side of the methods' own details (schema 1.1 and 1.2; docs/reference/recording.md): the
// /frames/<method> groups, the GPU cull's passes, survivors and depth images.

#include "recording_writer.hpp"

#include "collidescope/recorder/schema.hpp"
#include "collidescope/stats.hpp"

#include <cmath>

namespace collidescope::recorder {
namespace {

// The methods' details are many small columns, most of them zeros for a given method: small
// chunks keep their first allocation from dominating a short recording's size.
constexpr hsize_t k_detail_chunk = 32;
constexpr hsize_t k_survivor_chunk = 8192;   // survivors per chunk (64 KiB)

/// (name, unit) of every value a for_each_*_value visitor lists for `info`.
template <class Info, class ForEach>
std::vector<std::pair<std::string, std::string>> columns_of(const Info& info, ForEach for_each) {
    std::vector<std::pair<std::string, std::string>> columns;
    for_each(info, [&](const char* name, double, const char* unit) { columns.emplace_back(name, unit); });
    return columns;
}

std::size_t pass_field_count() {
    std::size_t fields = 0;
    for_each_pass_field(GpuPassInfo{}, [&](const char*, std::uint64_t) { ++fields; });
    return fields;
}

/// Window depth in [0, 1] -> uint16: 65535 only for depth 1 (nothing drawn) or beyond (and
/// NaN); drawn pixels round to at most 65534, so "nothing drawn" stays exact.
std::uint16_t quantise_depth(float depth) {
    if (!(depth < 1.0f)) return 65535;
    const double scaled = std::round(std::max(0.0, static_cast<double>(depth)) * schema::k_depth_scale);
    return static_cast<std::uint16_t>(std::min(scaled, schema::k_depth_scale - 1));
}

}  // namespace

RecordingWriter::DetailGroup RecordingWriter::create_detail_group(const std::string& group,
                                                      const std::vector<std::pair<std::string, std::string>>& columns) {
    h5::create_group(m_where, m_file.get(), group);
    DetailGroup out;
    out.present = make_column(group + "/" + schema::k_present, {H5T_STD_U8LE, 1, k_detail_chunk, 0, schema::k_unit_none});
    for (const auto& [name, unit] : columns) {
        out.values.push_back(make_column(group + "/" + name, {H5T_IEEE_F64LE, 1, k_detail_chunk, 0, unit.c_str()}));
    }
    return out;
}

template <class Member>
void RecordingWriter::append_detail_group(DetailGroup& group, std::span<const FrameRecord> records, Member member) {
    append_per_frame<std::uint8_t>(group.present, H5T_NATIVE_UINT8, records,
                                   [&](const FrameRecord& record) { return member(record).first ? 1 : 0; });
    for (std::size_t i = 0; i < group.values.size(); ++i) {
        append_per_frame<double>(group.values[i], H5T_NATIVE_DOUBLE, records,
                                 [&](const FrameRecord& record) { return member(record).second[i]; });
    }
}

void RecordingWriter::create_details() {
    m_gpu = create_detail_group(schema::k_frame_gpu,
                                columns_of(GpuFrameInfo{}, [](const auto& i, auto&& v) { for_each_gpu_value(i, v); }));
    m_aabb = create_detail_group(schema::k_frame_aabb,
                                 columns_of(AabbFrameInfo{}, [](const auto& i, auto&& v) { for_each_aabb_value(i, v); }));
    m_decision = create_detail_group(
        schema::k_frame_decision, columns_of(DecisionInfo{}, [](const auto& i, auto&& v) { for_each_decision_value(i, v); }));
    m_hybrid = create_detail_group(
        schema::k_frame_hybrid, columns_of(HybridFrameInfo{}, [](const auto& i, auto&& v) { for_each_hybrid_value(i, v); }));

    h5::create_group(m_where, m_file.get(), schema::k_gpu);
    m_gpu_passes = make_column(schema::k_gpu_passes, {H5T_STD_U64LE, pass_field_count(), k_detail_chunk, 0, schema::k_unit_none});
    m_gpu_pass_offsets = make_column(schema::k_gpu_pass_offsets, {H5T_STD_U64LE, 1, k_detail_chunk, 0, schema::k_unit_none});
    const int deflate = std::max(m_deflate, 1);
    m_gpu_survivors = make_column(schema::k_gpu_survivors, {H5T_STD_U32LE, 2, k_survivor_chunk, deflate, schema::k_unit_none});
    m_gpu_survivor_offsets =
        make_column(schema::k_gpu_survivor_offsets, {H5T_STD_U64LE, 1, k_detail_chunk, 0, schema::k_unit_none});

    h5::create_group(m_where, m_file.get(), schema::k_gpu_depth);
    m_depth.image_offsets = make_column(schema::k_depth_image_offsets, {H5T_STD_U64LE, 1, k_detail_chunk, 0, schema::k_unit_none});
    m_depth.info = make_column(schema::k_depth_info, {H5T_STD_U32LE, 4, k_detail_chunk, 0, schema::k_unit_none});
    m_depth.range = make_column(schema::k_depth_range, {H5T_IEEE_F64LE, 2, k_detail_chunk, 0, schema::k_unit_length});
    m_depth.pixel_offsets = make_column(schema::k_depth_pixel_offsets, {H5T_STD_U64LE, 1, k_detail_chunk, 0, schema::k_unit_none});
    // One image per chunk: a chunk filled over several frames would be rewritten (and its old
    // copy left behind in the file) at every flush. Compressed always: the background (65535)
    // dominates most views.
    m_depth.pixels = make_column(schema::k_depth_pixels, {H5T_STD_U16LE, 1, m_depth_chunk, deflate, "1/65535 window depth"});

    const std::uint64_t zero = 0;
    for (Column* offsets : {&m_gpu_pass_offsets, &m_gpu_survivor_offsets, &m_depth.image_offsets, &m_depth.pixel_offsets}) {
        append_value(*offsets, H5T_NATIVE_UINT64, &zero);
    }
}

void RecordingWriter::append_depth(const std::vector<GpuDepthImage>& images) {
    for (const GpuDepthImage& image : images) {
        if (image.depth.size() != std::size_t{image.width} * image.height) {
            m_where.fail("depth image " + std::to_string(image.width) + "x" + std::to_string(image.height) + " holds " +
                         std::to_string(image.depth.size()) + " pixels");
        }
        m_pixels.resize(image.depth.size());
        for (std::size_t p = 0; p < image.depth.size(); ++p) m_pixels[p] = quantise_depth(image.depth[p]);
        h5::append_rows(m_where, m_depth.pixels.dataset.get(), m_depth.pixels.path, m_depth.pixels.length,
                        H5T_NATIVE_UINT16, m_pixels.size(), m_pixels.data());
        const std::uint64_t pixels_end = m_depth.pixels.length;
        append_value(m_depth.pixel_offsets, H5T_NATIVE_UINT64, &pixels_end);
        const std::uint32_t info[4] = {image.level, image.view, image.width, image.height};
        append_value(m_depth.info, H5T_NATIVE_UINT32, info);
        const double range[2] = {image.depth_near, image.depth_far};
        append_value(m_depth.range, H5T_NATIVE_DOUBLE, range);
    }
}

void RecordingWriter::append_details(std::span<const FrameRecord> records, std::span<const Keep> keeps) {
    using Member = std::pair<bool, const std::vector<double>&>;
    append_detail_group(m_gpu, records, [](const FrameRecord& r) { return Member(r.has_gpu, r.gpu); });
    append_detail_group(m_aabb, records, [](const FrameRecord& r) { return Member(r.has_aabb, r.aabb); });
    append_detail_group(m_decision, records, [](const FrameRecord& r) { return Member(r.has_decision, r.decision); });
    append_detail_group(m_hybrid, records, [](const FrameRecord& r) { return Member(r.has_hybrid, r.hybrid); });

    const hsize_t fields = pass_field_count();
    std::vector<std::uint64_t> passes;
    for (const FrameRecord& record : records) passes.insert(passes.end(), record.gpu_passes.begin(), record.gpu_passes.end());
    std::uint64_t passes_end = m_gpu_passes.length;
    h5::append_rows(m_where, m_gpu_passes.dataset.get(), m_gpu_passes.path, m_gpu_passes.length, H5T_NATIVE_UINT64,
                    passes.size() / fields, passes.data());
    append_per_frame<std::uint64_t>(m_gpu_pass_offsets, H5T_NATIVE_UINT64, records, [&](const FrameRecord& record) {
        return passes_end += record.gpu_passes.size() / fields;
    });

    std::vector<std::array<std::uint32_t, 2>> survivors;
    for (const FrameRecord& record : records) survivors.insert(survivors.end(), record.survivors.begin(), record.survivors.end());
    std::uint64_t survivors_end = m_gpu_survivors.length;
    h5::append_rows(m_where, m_gpu_survivors.dataset.get(), m_gpu_survivors.path, m_gpu_survivors.length,
                    H5T_NATIVE_UINT32, survivors.size(), survivors.data());
    append_per_frame<std::uint64_t>(m_gpu_survivor_offsets, H5T_NATIVE_UINT64, records,
                                    [&](const FrameRecord& record) { return survivors_end += record.survivors.size(); });

    std::vector<std::uint64_t> images_end;
    for (std::size_t i = 0; i < records.size(); ++i) {
        if (keeps[i].depth) append_depth(records[i].depth_images);
        images_end.push_back(m_depth.info.length);
    }
    h5::append_rows(m_where, m_depth.image_offsets.dataset.get(), m_depth.image_offsets.path, m_depth.image_offsets.length,
                    H5T_NATIVE_UINT64, images_end.size(), images_end.data());
}

std::uint64_t RecordingWriter::depth_bytes() const { return H5Dget_storage_size(m_depth.pixels.dataset.get()); }

}  // namespace collidescope::recorder
