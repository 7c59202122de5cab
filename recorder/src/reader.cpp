// Reading a recording back.

#include "collidescope/recorder/reader.hpp"

#include "recording_state.hpp"
#include "virtual_sources.hpp"

#include "collidescope/recorder/schema.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collidescope::recorder {

namespace {

constexpr unsigned k_swmr_read_attempts = 8;

}  // namespace

void RecordingState::open_file() {
    h5::silence();
    const std::string& path = where.file();
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) where.fail("no such file");
    if (H5Fis_hdf5(path.c_str()) <= 0) {
        where.fail("not an HDF5 file (or a corrupt or truncated one)");
    }
    // SWMR read opens a file still being written or left by a killed writer; files in older
    // formats refuse it and open plainly.
    // A SWMR reader retries a metadata read whose checksum fails (a writer may be mid-flush),
    // 100 times by default with growing sleeps: minutes on a corrupt file. A few retries
    // cover a live writer's flush.
    const h5::Id fapl = where.own(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create a property list");
    where.check(H5Pset_metadata_read_attempts(fapl.get(), k_swmr_read_attempts), "cannot set read attempts");
    hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, fapl.get());
    if (id < 0) id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) {
        const std::string detail = h5::error_detail();
        where.fail("cannot open the HDF5 file (corrupt or truncated?)" + (detail.empty() ? "" : ": " + detail));
    }
    file = h5::Id(id, H5Fclose);
    // A virtual join's rows live in its parts; HDF5 reads a missing part as zeros, silently.
    virtual_sources = recorder::virtual_sources::list(where, file.get());
    recorder::virtual_sources::check(where, virtual_sources);
}

void RecordingState::check_schema() {
    const std::optional<std::string> name = h5::read_string_attr(where, file.get(), schema::k_attr_schema);
    if (!name || *name != schema::k_schema_name) {
        where.fail("not a collidescope recording (no '" + std::string(schema::k_attr_schema) + "' = '" +
                   schema::k_schema_name + "' attribute on /)");
    }
    const std::optional<std::int64_t> major = h5::read_int_attr(where, file.get(), schema::k_attr_version_major);
    const std::optional<std::int64_t> minor = h5::read_int_attr(where, file.get(), schema::k_attr_version_minor);
    if (!major || !minor) where.fail("recording without a schema version");
    version_major = *major;
    version_minor = *minor;
    if (*major > schema::k_version_major) {
        where.fail("recording schema version " + std::to_string(*major) + "." + std::to_string(*minor) +
                   " is newer than this collidescope reads (" + std::to_string(schema::k_version_major) +
                   ".x); use a newer collidescope");
    }
    if (*major < 1) where.fail("bad schema version " + std::to_string(*major));
    finished = h5::read_int_attr(where, file.get(), schema::k_attr_finished).value_or(0) == 1;
    interrupted = h5::read_string_attr(where, file.get(), schema::k_attr_interrupted).value_or("");
    const std::int64_t begin = h5::read_int_attr(where, file.get(), "frame_begin").value_or(0);
    const std::int64_t end = h5::read_int_attr(where, file.get(), "frame_end").value_or(0);
    frames_requested = end > begin ? static_cast<std::uint64_t>(end - begin) : 0;
    read_time_attributes();
}

void RecordingState::read_time_attributes() {
    fps = h5::read_double_attr(where, file.get(), schema::k_attr_fps).value_or(0);
    if (!(fps >= 0) || !std::isfinite(fps)) {
        where.fail("attribute " + std::string(schema::k_attr_fps) + " is not a positive number");
    }
    clip = h5::read_string_attr(where, file.get(), schema::k_attr_clip).value_or("");
    const std::string up = h5::read_string_attr(where, file.get(), schema::k_attr_up_axis).value_or("");
    if (!up.empty() && (up.size() != 1 || (up != "x" && up != "y" && up != "z"))) {
        where.fail("attribute " + std::string(schema::k_attr_up_axis) + " is '" + up + "', not x, y or z");
    }
    up_axis = up.empty() ? 0 : up[0];
}

void RecordingState::count_frames() {
    std::uint64_t n = rows(schema::k_frame_index);
    n = std::min(n, rows(schema::k_frame_method));
    if (h5::exists(file.get(), schema::k_frame_time)) n = std::min(n, rows(schema::k_frame_time));
    for (const char* group : {schema::k_frame_ms, schema::k_frame_counts}) {
        for (const std::string& member : group_members(group)) n = std::min(n, rows(std::string(group) + "/" + member));
    }
    // Offsets hold one more entry than frames.
    const auto offset_frames = [&](const std::string& path) {
        const std::uint64_t r = rows(path);
        if (r == 0) where.fail(path + " is empty (it starts with 0)");
        return r - 1;
    };
    n = std::min(n, offset_frames(schema::k_pair_offsets));
    // The methods' details, in the files whose minor has them.
    for (const char* group : {schema::k_frame_gpu, schema::k_frame_aabb, schema::k_frame_decision, schema::k_frame_hybrid}) {
        if (!h5::exists(file.get(), group)) continue;
        for (const std::string& member : group_members(group)) n = std::min(n, rows(std::string(group) + "/" + member));
    }
    for (const char* offsets : {schema::k_gpu_pass_offsets, schema::k_gpu_survivor_offsets, schema::k_depth_image_offsets,
                                schema::k_region_offsets, schema::k_interval_offsets}) {
        if (h5::exists(file.get(), offsets)) n = std::min(n, offset_frames(offsets));
    }
    if (h5::exists(file.get(), schema::k_interval_offsets)) {  // 1.7: one row per frame
        for (const char* path : {schema::k_interval_counts, schema::k_interval_ms, schema::k_interval_tolerance}) {
            n = std::min(n, rows(path));
        }
    }
    const std::vector<std::string> objects_listed = group_members(schema::k_objects);
    for (std::uint32_t k = 0; k < objects_listed.size(); ++k) {
        n = std::min(n, offset_frames(schema::object_group(k) + "/" + schema::k_vertex_offsets));
    }
    frames = n;
}

void RecordingState::read_objects() {
    const std::size_t count = group_members(schema::k_objects).size();
    for (std::uint32_t k = 0; k < count; ++k) {
        const std::string prefix = schema::object_group(k) + "/";
        ObjectInfo info;
        const h5::Id group = h5::open_group(where, file.get(), schema::object_group(k));
        info.name = h5::read_string_attr(where, group.get(), schema::k_attr_name).value_or(std::to_string(k));
        const std::vector<std::uint64_t> offsets =
            read_all<std::uint64_t>(prefix + schema::k_topology_offsets, H5T_NATIVE_UINT64, 1u << 24);
        const std::vector<std::uint32_t> from =
            read_all<std::uint32_t>(prefix + schema::k_topology_from_frame, H5T_NATIVE_UINT32, 1u << 24);
        const std::vector<std::uint32_t> vertices =
            read_all<std::uint32_t>(prefix + schema::k_topology_vertex_count, H5T_NATIVE_UINT32, 1u << 24);
        const std::uint64_t triangle_rows = rows(prefix + schema::k_triangles);
        // A writer killed mid-topology may leave trailing entries: keep the complete ones.
        std::size_t revisions = std::min({from.size(), vertices.size(), offsets.empty() ? 0 : offsets.size() - 1});
        // In a file still being written, or left by a killed writer, a topology that no complete
        // frame uses may be on disk in part (SWMR orders each dataset's own writes, not the
        // triangles' against the offsets'): only those from the last complete frame back count.
        if (!finished) {
            std::size_t used = 0;
            if (frames > 0) {
                const std::uint32_t last = last_frame_index();
                while (used < revisions && from[used] <= last) ++used;
            }
            revisions = used;
        }
        for (std::size_t r = 0; r < revisions; ++r) {
            if (offsets[r] > offsets[r + 1] || offsets[r + 1] > triangle_rows) {
                where.fail(prefix + std::string(schema::k_topology_offsets) + ": entry " + std::to_string(r + 1) +
                           " out of range");
            }
            info.topologies.push_back({from[r], vertices[r], offsets[r], offsets[r + 1] - offsets[r]});
        }
        objects.push_back(std::move(info));
    }
}

Recording::Recording(const std::filesystem::path& path) : m_impl(std::make_unique<RecordingState>(path.string())) {
    m_impl->open_file();
    m_impl->check_schema();
    m_impl->count_frames();
    m_impl->read_objects();
}

Recording::~Recording() = default;
Recording::Recording(Recording&&) noexcept = default;
Recording& Recording::operator=(Recording&&) noexcept = default;

const std::string& Recording::path() const { return m_impl->where.file(); }
std::int64_t Recording::version_major() const { return m_impl->version_major; }
std::int64_t Recording::version_minor() const { return m_impl->version_minor; }
bool Recording::finished() const { return m_impl->finished; }
const std::string& Recording::interrupted() const { return m_impl->interrupted; }
std::uint64_t Recording::frames_requested() const { return m_impl->frames_requested; }
const std::vector<VirtualSource>& Recording::virtual_sources() const { return m_impl->virtual_sources; }

std::string Recording::partial_reason() const {
    const std::string frames = std::to_string(m_impl->frames);
    if (!m_impl->finished) {
        return "not finished (the writer was killed, crashed or failed to write)";
    }
    if (!m_impl->interrupted.empty()) {
        return "stopped by " + m_impl->interrupted + " after " + frames + " of " +
               std::to_string(m_impl->frames_requested) + " frames";
    }
    return {};
}
std::uint64_t Recording::frames_complete() const { return m_impl->frames; }
const std::vector<ObjectInfo>& Recording::objects() const { return m_impl->objects; }

std::vector<std::uint32_t> Recording::frame_indices() const {
    return m_impl->read_all<std::uint32_t>(schema::k_frame_index, H5T_NATIVE_UINT32, m_impl->frames);
}

bool Recording::has_frame_times() const { return h5::exists(m_impl->file.get(), schema::k_frame_time); }

std::vector<double> Recording::frame_times() const {
    if (!has_frame_times()) return {};
    return m_impl->read_all<double>(schema::k_frame_time, H5T_NATIVE_DOUBLE, m_impl->frames);
}

double Recording::fps() const { return m_impl->fps; }
const std::string& Recording::clip() const { return m_impl->clip; }
char Recording::up_axis() const { return m_impl->up_axis; }

std::vector<std::uint64_t> Recording::read_u64(const std::string& dataset) const {
    return m_impl->read_all<std::uint64_t>(dataset, H5T_NATIVE_UINT64, std::numeric_limits<std::uint64_t>::max());
}

std::vector<std::string> Recording::frame_methods() const {
    const RecordingState& impl = *m_impl;
    const std::string path = schema::k_frame_method;
    const h5::Id d = impl.dataset(path);
    const h5::Id type = impl.where.own(H5Dget_type(d.get()), H5Tclose, "cannot read the type of " + path);
    if (H5Tget_class(type.get()) != H5T_ENUM || H5Tget_size(type.get()) != 1) impl.where.fail(path + " is not a uint8 enum");
    const h5::Id native = impl.where.own(H5Tget_native_type(type.get(), H5T_DIR_ASCEND), H5Tclose, "bad type of " + path);
    std::vector<std::uint8_t> codes(impl.frames);
    h5::read_rows(impl.where, d.get(), path, native.get(), 0, codes.size(), codes.data());
    std::vector<std::string> names;
    for (const std::uint8_t code : codes) {
        char name[256] = {};
        if (H5Tenum_nameof(native.get(), &code, name, sizeof name) < 0) {
            impl.where.fail(path + ": value " + std::to_string(code) + " is not in its enum");
        }
        names.emplace_back(name);
    }
    return names;
}

std::vector<Series<double>> Recording::stage_ms() const {
    std::vector<Series<double>> out;
    for (const std::string& name : m_impl->group_members(schema::k_frame_ms)) {
        const std::string path = std::string(schema::k_frame_ms) + "/" + name;
        out.push_back({name, unit_of(path), m_impl->read_all<double>(path, H5T_NATIVE_DOUBLE, m_impl->frames)});
    }
    return out;
}

std::vector<Series<std::uint64_t>> Recording::counts() const {
    std::vector<Series<std::uint64_t>> out;
    for (const std::string& name : m_impl->group_members(schema::k_frame_counts)) {
        const std::string path = std::string(schema::k_frame_counts) + "/" + name;
        out.push_back({name, unit_of(path), m_impl->read_all<std::uint64_t>(path, H5T_NATIVE_UINT64, m_impl->frames)});
    }
    return out;
}

}  // namespace collidescope::recorder
