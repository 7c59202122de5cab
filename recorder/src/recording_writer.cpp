// The HDF5 side of the recorder (layout: schema.hpp, docs/reference/recording.md).

#include "recording_writer.hpp"

#include "chunk_codec.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/schema.hpp"
#include "collidescope/stats.hpp"

#include <bit>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <thread>

namespace collidescope::recorder {
namespace {

// HDF5 1.10 locks the file while a process opens it. A reader that opens the recording at
// the moment `record` switches it to SWMR writing, or reopens it to mark it finished (a
// script or `inspect` polling it), makes that call fail although nothing is wrong; the
// reader's lock lasts as long as its open. So those two calls are retried for up to 5 s.
template <class Call>
auto retry_while_locked(Call call) {
    auto result = call();
    for (int attempt = 1; result < 0 && attempt < 250; ++attempt) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        result = call();
    }
    return result;
}

constexpr hsize_t k_frame_chunk = 256;       // rows per chunk of 1-D per-frame datasets (2 KiB)
constexpr hsize_t k_pair_chunk = 8192;       // pairs per chunk (128 KiB)
constexpr hsize_t k_max_chunk_rows = 1u << 20;

hsize_t chunk_rows(std::size_t rows) {
    return std::clamp<hsize_t>(static_cast<hsize_t>(rows), 1, k_max_chunk_rows);
}

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm parts{};
    gmtime_r(&now, &parts);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
    return text;
}

}  // namespace

RecordingWriter::RecordingWriter(const std::filesystem::path& path, const SessionInfo& session, const Frame& first,
                     std::span<const std::string> methods, int deflate_level)
    : m_where(path.string()),
      m_deflate(deflate_level),
      m_depth_chunk(session.depth_image_pixels > 0 ? chunk_rows(session.depth_image_pixels) : 65536),
      m_frame_times(session.frame_times) {
    h5::silence();
    const h5::Id fapl = m_where.own(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create a property list");
    // SWMR needs the latest file format.
    m_where.check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST),
                  "cannot select the latest file format");
    const h5::Id fcpl = m_where.own(H5Pcreate(H5P_FILE_CREATE), H5Pclose, "cannot create a property list");
    h5::keep_compact(m_where, fcpl.get(), "/");  // the root group: its links and its attributes
    m_file = m_where.own(H5Fcreate(m_where.file().c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), H5Fclose,
                         "cannot create the recording (is the directory writable?)");
    write_metadata(session);
    create_frames(methods);
    create_details();
    if (session.regions) create_regions();
    if (session.between_frames) create_intervals();
    create_objects(session, first, deflate_level);
    m_where.check(retry_while_locked([&] { return H5Fstart_swmr_write(m_file.get()); }),
                  "cannot start SWMR writing (another process kept the file open for 5 s?)");
    m_reserve = std::make_unique<SpaceReserve>(path);
}

RecordingWriter::Column RecordingWriter::make_column(const std::string& path, const h5::ExtensibleSpec& spec, hid_t loc) {
    Column column;
    column.path = path;
    column.dataset = h5::create_extensible(m_where, loc < 0 ? m_file.get() : loc, path, spec);
    return column;
}

void RecordingWriter::write_metadata(const SessionInfo& session) {
    const hid_t root = m_file.get();
    h5::write_attr(m_where, root, schema::k_attr_schema, std::string(schema::k_schema_name));
    h5::write_attr(m_where, root, schema::k_attr_version_major, schema::k_version_major);
    h5::write_attr(m_where, root, schema::k_attr_version_minor, schema::k_version_minor);
    h5::write_attr(m_where, root, "tool_version", session.tool_version);
    h5::write_attr(m_where, root, "git_revision", session.git_revision);
    h5::write_attr(m_where, root, "created", utc_now());
    h5::write_attr(m_where, root, "scene", session.scene);
    h5::write_attr(m_where, root, "scene_preset", session.preset);
    h5::write_attr(m_where, root, "scene_seed", static_cast<std::int64_t>(session.seed));
    h5::write_attr(m_where, root, "method", session.method);
    h5::write_attr(m_where, root, "self_collision", std::int64_t{session.self_collision ? 1 : 0});
    h5::write_attr(m_where, root, "threads", std::int64_t{session.threads});
    h5::write_attr(m_where, root, "hardware_threads", std::int64_t{std::thread::hardware_concurrency()});
    h5::write_attr(m_where, root, "frame_begin", std::int64_t{session.frame_begin});
    h5::write_attr(m_where, root, "frame_end", std::int64_t{session.frame_end});
    h5::write_attr(m_where, root, "depth", session.depth);
    h5::write_attr(m_where, root, "gl_renderer", session.gl_renderer);
    h5::write_attr(m_where, root, "object_count", static_cast<std::int64_t>(session.object_names.size()));
    // Schema 1.4: only what the inputs say, so an untimed scene's file has none of them.
    if (session.fps > 0) h5::write_attr(m_where, root, schema::k_attr_fps, session.fps);
    if (!session.clip.empty()) h5::write_attr(m_where, root, schema::k_attr_clip, session.clip);
    if (session.up_axis != 0) h5::write_attr(m_where, root, schema::k_attr_up_axis, std::string(1, session.up_axis));
    if (session.regions) h5::write_attr(m_where, root, schema::k_attr_regions, std::int64_t{1});  // 1.5
    if (session.between_frames) {  // 1.7
        h5::write_attr(m_where, root, schema::k_attr_between_frames, std::int64_t{1});
        h5::write_attr(m_where, root, schema::k_attr_ccd_tolerance, session.ccd_tolerance);
    }
}

void RecordingWriter::create_frames(std::span<const std::string> methods) {
    h5::create_group(m_where, m_file.get(), schema::k_frames);
    m_index = make_column(schema::k_frame_index, {H5T_STD_U32LE, 1, k_frame_chunk, 0, schema::k_unit_none});
    if (!m_frame_times.empty()) {
        m_time = make_column(schema::k_frame_time, {H5T_IEEE_F64LE, 1, k_frame_chunk, 0, schema::k_unit_seconds});
    }
    m_method_type = m_where.own(H5Tenum_create(H5T_NATIVE_UINT8), H5Tclose, "cannot create the method enum");
    for (std::size_t code = 0; code < methods.size(); ++code) {
        const auto value = static_cast<std::uint8_t>(code);
        m_where.check(H5Tenum_insert(m_method_type.get(), methods[code].c_str(), &value),
                      "cannot add method " + methods[code] + " to the enum");
    }
    m_method = make_column(schema::k_frame_method, {m_method_type.get(), 1, k_frame_chunk, 0, schema::k_unit_none});
    h5::create_group(m_where, m_file.get(), schema::k_frame_ms);
    for_each_stage(StageTimes{}, [&](const char* name, double) {
        m_ms.push_back(make_column(std::string(schema::k_frame_ms) + "/" + name,
                                   {H5T_IEEE_F64LE, 1, k_frame_chunk, 0, schema::k_unit_ms}));
    });
    h5::create_group(m_where, m_file.get(), schema::k_frame_counts);
    for_each_count(FrameCounts{}, [&](const char* name, std::uint64_t) {
        m_counts.push_back(make_column(std::string(schema::k_frame_counts) + "/" + name,
                                       {H5T_STD_U64LE, 1, k_frame_chunk, 0, schema::k_unit_none}));
    });
    h5::create_group(m_where, m_file.get(), schema::k_collisions);
    m_pairs = make_column(schema::k_pairs, {H5T_STD_U32LE, 4, k_pair_chunk, m_deflate, schema::k_unit_none});
    m_pair_offsets = make_column(schema::k_pair_offsets, {H5T_STD_U64LE, 1, k_frame_chunk, 0, schema::k_unit_none});
    const std::uint64_t zero = 0;
    append_value(m_pair_offsets, H5T_NATIVE_UINT64, &zero);
}

void RecordingWriter::create_objects(const SessionInfo& session, const Frame& first, int deflate_level) {
    h5::create_group(m_where, m_file.get(), schema::k_objects);
    for (std::uint32_t k = 0; k < first.objects.size(); ++k) {
        const std::string group_path = schema::object_group(k);
        const h5::Id group = h5::create_group(m_where, m_file.get(), group_path);
        h5::write_attr(m_where, group.get(), schema::k_attr_name,
                       k < session.object_names.size() ? session.object_names[k] : std::to_string(k));
        const ObjectFrame& object = first.objects[k];
        const std::string prefix = group_path + "/";
        ObjectColumns columns;
        columns.triangles = make_column(prefix + schema::k_triangles,
                                        {H5T_STD_U32LE, 3, chunk_rows(object.triangle_count()), deflate_level,
                                         schema::k_unit_none});
        columns.topology_offsets = make_column(prefix + schema::k_topology_offsets,
                                               {H5T_STD_U64LE, 1, 64, 0, schema::k_unit_none});
        columns.topology_from_frame = make_column(prefix + schema::k_topology_from_frame,
                                                  {H5T_STD_U32LE, 1, 64, 0, schema::k_unit_none});
        columns.topology_vertex_count = make_column(prefix + schema::k_topology_vertex_count,
                                                    {H5T_STD_U32LE, 1, 64, 0, schema::k_unit_none});
        // Chunk = one frame of this object, compressed: the layout the issue fixes.
        columns.positions = make_column(prefix + schema::k_positions,
                                        {H5T_IEEE_F32LE, 3, chunk_rows(object.vertices.size()), deflate_level,
                                         schema::k_unit_length});
        columns.positions_chunk_rows = chunk_rows(object.vertices.size());
        columns.vertex_offsets = make_column(prefix + schema::k_vertex_offsets,
                                             {H5T_STD_U64LE, 1, k_frame_chunk, 0, schema::k_unit_none});
        const std::uint64_t zero = 0;
        append_value(columns.topology_offsets, H5T_NATIVE_UINT64, &zero);
        append_value(columns.vertex_offsets, H5T_NATIVE_UINT64, &zero);
        m_objects.push_back(std::move(columns));
    }
}

void RecordingWriter::append_value(Column& column, hid_t mem_type, const void* value) {
    h5::append_rows(m_where, column.dataset.get(), column.path, column.length, mem_type, 1, value);
}

void RecordingWriter::append_positions(ObjectColumns& columns, std::span<const float> xyz) {
    Column& column = columns.positions;
    if (m_deflate == 0) {
        h5::append_rows(m_where, column.dataset.get(), column.path, column.length, H5T_NATIVE_FLOAT, xyz.size() / 3,
                        xyz.data());
        return;
    }
    // Raw chunks skip HDF5's type conversion: memory order must be the file's (F32LE).
    static_assert(std::endian::native == std::endian::little);
    const hsize_t chunk = columns.positions_chunk_rows;
    const hsize_t begin = column.length;
    const hsize_t end = begin + xyz.size() / 3;
    if (end == begin) return;
    h5::extend(m_where, column.dataset.get(), column.path, end);
    std::vector<float>& partial = columns.partial_chunk;
    for (hsize_t row = begin; row < end;) {
        const hsize_t first = row / chunk * chunk;
        const hsize_t stop = std::min(end, first + chunk);
        const std::span<const float> rows = xyz.subspan(3 * (row - begin), 3 * (stop - row));
        std::span<const float> chunk_rows = rows;  // the chunk's rows from its first
        if (row != first || stop != first + chunk) {  // partly filled: add to what it holds
            if (row == first) partial.clear();
            if (partial.size() != 3 * (row - first)) m_where.fail(column.path + ": lost track of a partial chunk");
            partial.insert(partial.end(), rows.begin(), rows.end());
            chunk_rows = partial;
        }
        encode_shuffle_deflate(std::as_bytes(chunk_rows), sizeof(float), m_deflate, m_encoded,
                               3 * chunk * sizeof(float));
        h5::write_encoded_chunk(m_where, column.dataset.get(), column.path, first, m_encoded);
        row = stop;
    }
    column.length = end;
}

void RecordingWriter::append_topology(ObjectColumns& columns, const Topology& topology, std::uint32_t frame) {
    // Rows first, then the offset that makes them visible, then what describes them.
    h5::append_rows(m_where, columns.triangles.dataset.get(), columns.triangles.path, columns.triangles.length,
                    H5T_NATIVE_UINT32, topology.triangles.size(), topology.triangles.data());
    const std::uint64_t end = columns.triangles.length;
    append_value(columns.topology_offsets, H5T_NATIVE_UINT64, &end);
    append_value(columns.topology_from_frame, H5T_NATIVE_UINT32, &frame);
    append_value(columns.topology_vertex_count, H5T_NATIVE_UINT32, &topology.vertex_count);
}

void RecordingWriter::append(std::span<const FrameRecord> records, std::span<const Keep> keeps) {
    if (records.empty()) return;
    const std::string frames = records.size() == 1 ? "frame " + std::to_string(records.front().frame)
                                                   : "frames " + std::to_string(records.front().frame) + "-" +
                                                         std::to_string(records.back().frame);
    try {
        reserve_space(records);
    } catch (const InputError& error) {  // nothing of the frames written: the file is as it was
        if (records.size() > 1) {
            // Keep every frame that fits, and name the one that does not: one at a time.
            for (std::size_t i = 0; i < records.size(); ++i) append(records.subspan(i, 1), keeps.subspan(i, 1));
            return;
        }
        throw InputError(m_where.file() + ": " + frames + ": " + std::string(error.what()).substr(m_where.file().size() + 2));
    }
    errno = 0;
    try {
        write_frames(records, keeps);
        m_frames_written += records.size();
    } catch (const InputError& error) {
        m_damaged = true;
        // HDF5 reports a failed write without its reason; errno still holds the system's.
        const int system_error = errno;
        std::string line = m_where.file() + ": " + frames + ": " + std::string(error.what()).substr(m_where.file().size() + 2);
        if (system_error == ENOSPC || system_error == EFBIG || system_error == EDQUOT || system_error == EIO) {
            line += " (" + std::string(std::strerror(system_error)) + ")";
        }
        throw InputError(line);
    }
}

void RecordingWriter::reserve_space(std::span<const FrameRecord> records) {
    haddr_t end = 0;
    m_where.check(H5Fget_eoa(m_file.get(), &end), "cannot read the end of the file");
    // The frames' uncompressed bytes bound their chunks, except where a frame fills positions
    // chunks only partly (its vertex count is not the first frame's): then the chunk at
    // either end is rewritten whole. Chunk indexes and object headers grow by far less than
    // the margin.
    constexpr std::uint64_t k_margin = 256u << 10;
    std::uint64_t bytes = 0;
    for (const FrameRecord& record : records) {
        bytes += record.bytes();
        for (std::size_t k = 0; k < m_objects.size() && k < record.objects.size(); ++k) {
            const hsize_t chunk = m_objects[k].positions_chunk_rows;
            if (record.objects[k].positions.size() / 3 != chunk) bytes += 2 * chunk * 3 * sizeof(float);
        }
    }
    m_reserve->reserve(end, bytes + bytes / 16 + k_margin);
}

void RecordingWriter::write_frames(std::span<const FrameRecord> records, std::span<const Keep> keeps) {
    for (const FrameRecord& record : records) {
        if (record.objects.size() != m_objects.size()) {
            m_where.fail("frame " + std::to_string(record.frame) + " has " + std::to_string(record.objects.size()) +
                         " objects, the recording " + std::to_string(m_objects.size()));
        }
    }
    for (std::size_t k = 0; k < m_objects.size(); ++k) {
        ObjectColumns& columns = m_objects[k];
        std::vector<std::uint64_t> ends;
        for (std::size_t i = 0; i < records.size(); ++i) {
            const ObjectRecord& object = records[i].objects[k];
            if (object.new_topology) append_topology(columns, *object.new_topology, records[i].frame);
            if (keeps[i].positions) append_positions(columns, object.positions);
            ends.push_back(columns.positions.length);
        }
        h5::append_rows(m_where, columns.vertex_offsets.dataset.get(), columns.vertex_offsets.path,
                        columns.vertex_offsets.length, H5T_NATIVE_UINT64, ends.size(), ends.data());
    }
    static_assert(sizeof(TrianglePair) == 4 * sizeof(std::uint32_t));
    std::uint64_t pairs_end = m_pairs.length;
    std::vector<TrianglePair> pairs;
    for (const FrameRecord& record : records) pairs.insert(pairs.end(), record.pairs.begin(), record.pairs.end());
    h5::append_rows(m_where, m_pairs.dataset.get(), m_pairs.path, m_pairs.length, H5T_NATIVE_UINT32, pairs.size(),
                    pairs.data());
    append_per_frame<std::uint64_t>(m_pair_offsets, H5T_NATIVE_UINT64, records,
                                    [&](const FrameRecord& record) { return pairs_end += record.pairs.size(); });
    for (std::size_t s = 0; s < m_ms.size(); ++s) {
        append_per_frame<double>(m_ms[s], H5T_NATIVE_DOUBLE, records, [s](const FrameRecord& record) { return record.ms[s]; });
    }
    for (std::size_t c = 0; c < m_counts.size(); ++c) {
        append_per_frame<std::uint64_t>(m_counts[c], H5T_NATIVE_UINT64, records,
                                        [c](const FrameRecord& record) { return record.counts[c]; });
    }
    append_per_frame<std::uint8_t>(m_method, m_method_type.get(), records,
                                   [](const FrameRecord& record) { return record.method; });
    append_details(records, keeps);
    if (m_regions.present) append_regions(records);
    if (m_intervals.present) append_intervals(records);
    if (!m_frame_times.empty()) {
        append_per_frame<double>(m_time, H5T_NATIVE_DOUBLE, records, [&](const FrameRecord& record) {
            if (record.frame >= m_frame_times.size()) {
                m_where.fail("frame " + std::to_string(record.frame) + " has no time (the scene gave " +
                             std::to_string(m_frame_times.size()) + ")");
            }
            return m_frame_times[record.frame];
        });
    }
    // The frame index last, after a flush: a reader counts a frame complete when every dataset
    // has its row, and SWMR orders only each dataset's own writes (its rows before its extent),
    // not one dataset's against another's. Without this flush a process killed mid-flush can
    // leave /collisions/offsets grown on disk but /collisions/pairs not. With it the index rows
    // reach the disk only after every other row of their frames is there.
    m_where.check(H5Fflush(m_file.get(), H5F_SCOPE_LOCAL), "cannot flush the file");
    append_per_frame<std::uint32_t>(m_index, H5T_NATIVE_UINT32, records,
                                    [](const FrameRecord& record) { return record.frame; });
    m_where.check(H5Fflush(m_file.get(), H5F_SCOPE_LOCAL), "cannot flush the file");
}

std::uint64_t RecordingWriter::file_bytes() const {
    hsize_t size = 0;
    m_where.check(H5Fget_filesize(m_file.get(), &size), "cannot read the file size");
    return size;
}

std::uint64_t RecordingWriter::positions_bytes() const {
    std::uint64_t total = 0;
    for (const ObjectColumns& columns : m_objects) total += H5Dget_storage_size(columns.positions.dataset.get());
    return total;
}

void RecordingWriter::close() {
    m_index.dataset.reset();
    m_time.dataset.reset();
    m_method.dataset.reset();
    m_pairs.dataset.reset();
    m_pair_offsets.dataset.reset();
    m_ms.clear();
    m_counts.clear();
    m_objects.clear();
    m_method_type.reset();
    for (DetailGroup* group : {&m_gpu, &m_aabb, &m_decision, &m_hybrid}) *group = DetailGroup{};
    m_gpu_passes.dataset.reset();
    m_gpu_pass_offsets.dataset.reset();
    m_gpu_survivors.dataset.reset();
    m_gpu_survivor_offsets.dataset.reset();
    m_depth = DepthColumns{};
    m_regions = RegionColumns{};
    m_intervals = IntervalColumns{};
    if (m_reserve) m_reserve->close();
    if (m_file.valid() && !m_file.reset()) m_where.fail("cannot close the recording (disk full?)");
}

void RecordingWriter::mark_finished(const std::filesystem::path& path, std::uint64_t frames, std::uint32_t positions_stride,
                              const std::string& interrupted) {
    const h5::Where where(path.string());
    // Reopened for SWMR writing, as it was written: a process killed in here leaves the file's
    // superblock marked "open for SWMR writing", which SWMR readers open. A plain read-write
    // open marks it "open for writing", and then nothing opens it until h5clear clears the mark.
    const unsigned flags = H5F_ACC_RDWR | H5F_ACC_SWMR_WRITE;
    const h5::Id file = where.own(retry_while_locked([&] { return H5Fopen(path.c_str(), flags, H5P_DEFAULT); }),
                                  H5Fclose,
                                  "cannot reopen the recording to mark it finished (another process kept it open for 5 s?)");
    h5::write_attr(where, file.get(), schema::k_attr_frames_recorded, static_cast<std::int64_t>(frames));
    h5::write_attr(where, file.get(), schema::k_attr_positions_stride, std::int64_t{positions_stride});
    if (!interrupted.empty()) h5::write_attr(where, file.get(), schema::k_attr_interrupted, interrupted);
    h5::write_attr(where, file.get(), schema::k_attr_finished, std::int64_t{1});
}

}  // namespace collidescope::recorder
