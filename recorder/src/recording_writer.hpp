#pragma once
// The HDF5 side of the recorder: creates the whole layout up front, switches to SWMR writing,
// then appends one frame at a time and flushes. Used by one thread at a time.

#include "frame_queue.hpp"
#include "h5.hpp"
#include "space_reserve.hpp"

#include "collidescope/recorder/session_info.hpp"

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace collidescope::recorder {

class RecordingWriter {
public:
    /// Creates `path` (latest file format, needed by SWMR), every group, dataset and attribute,
    /// then starts SWMR writing. `first` sizes the chunks (positions: one frame per chunk).
    RecordingWriter(const std::filesystem::path& path, const SessionInfo& session, const Frame& first,
              std::span<const std::string> methods, int deflate_level);

    /// What --budget keeps of one frame.
    struct Keep {
        bool positions = true;
        bool depth = true;  ///< the depth images (GpuFrameInfo::depth_images)
    };
    /// Reserves the frames' disk space (space_reserve.hpp), then appends them (positions and
    /// depth images only as `keeps` say, one Keep per frame), each dataset's rows of all the
    /// frames at once, the frame index last, and flushes the file once (group commit: the
    /// writer passes every frame waiting for it). When the group's disk space cannot be
    /// reserved, its frames are appended one at a time, so that every frame that fits is kept.
    /// Throws InputError naming the file, the frame(s) and, for a failed write, the system's
    /// reason.
    void append(std::span<const FrameRecord> records, std::span<const Keep> keeps);
    /// True once a write failed inside a frame (after its space was reserved: should not
    /// happen): HDF5 may have written part of it, and the file may not open.
    bool damaged() const { return m_damaged; }
    /// Frames appended and flushed so far.
    std::uint64_t frames_written() const { return m_frames_written; }
    /// Current size of the file in bytes.
    std::uint64_t file_bytes() const;
    /// Bytes the positions datasets occupy (all objects).
    std::uint64_t positions_bytes() const;
    /// Bytes the depth images' pixels occupy.
    std::uint64_t depth_bytes() const;
    /// Closes the file (SWMR ends). Throws when the final flush fails.
    void close();

    /// Reopens a closed recording and adds the `finished` attributes (and `interrupted` when
    /// not empty: the signal that stopped the run early).
    static void mark_finished(const std::filesystem::path& path, std::uint64_t frames, std::uint32_t positions_stride,
                              const std::string& interrupted);

private:
    struct Column {
        h5::Id dataset;
        std::string path;
        hsize_t length = 0;
    };
    struct ObjectColumns {
        Column triangles, topology_offsets, topology_from_frame, topology_vertex_count, positions, vertex_offsets;
        hsize_t positions_chunk_rows = 0;  ///< vertices of the first frame: one frame per chunk
        /// The rows written so far of the last, partly filled positions chunk (x y z from its
        /// first row): a frame whose vertex count differs from the first frame's leaves one, and
        /// the next frame rewrites it whole with its own rows added.
        std::vector<float> partial_chunk;
    };

    void reserve_space(std::span<const FrameRecord> records);
    void write_frames(std::span<const FrameRecord> records, std::span<const Keep> keeps);
    Column make_column(const std::string& path, const h5::ExtensibleSpec& spec, hid_t loc = -1);
    void write_metadata(const SessionInfo& session);
    void create_frames(std::span<const std::string> methods);
    /// A /frames details group: `present` plus one float64 column per visited value.
    struct DetailGroup {
        Column present;
        std::vector<Column> values;
    };
    struct DepthColumns {
        Column image_offsets, info, range, pixel_offsets, pixels;
    };
    /// /regions (schema 1.5, record --regions): write_regions.cpp.
    struct RegionColumns {
        Column offsets, table, measures, penetration, curve_offsets, curve_closed, point_offsets, points, predecessor_offsets,
            predecessors;
        bool present = false;
    };
    void create_regions();
    void append_regions(std::span<const FrameRecord> records);
    /// /intervals (schema 1.7, record --between-frames): write_intervals.cpp.
    struct IntervalColumns {
        Column offsets, counts, ms, tolerance, pairs, toi, flags;
        bool present = false;
    };
    void create_intervals();
    void append_intervals(std::span<const FrameRecord> records);
    DetailGroup create_detail_group(const std::string& group, const std::vector<std::pair<std::string, std::string>>& columns);
    /// One row per frame of `present` and of every value column; `member` picks a
    /// FrameRecord's (present flag, values) pair.
    template <class Member>
    void append_detail_group(DetailGroup& group, std::span<const FrameRecord> records, Member member);
    void create_details();
    void append_details(std::span<const FrameRecord> records, std::span<const Keep> keeps);
    void append_depth(const std::vector<GpuDepthImage>& images);
    void create_objects(const SessionInfo& session, const Frame& first, int deflate_level);
    void append_topology(ObjectColumns& columns, const Topology& topology, std::uint32_t frame);
    void append_value(Column& column, hid_t mem_type, const void* value);
    /// Appends one row per frame: `value(record)` of each, as `T` (a native type of `mem_type`).
    template <class T, class Value>
    void append_per_frame(Column& column, hid_t mem_type, std::span<const FrameRecord> records, Value value) {
        std::vector<T> rows;
        rows.reserve(records.size());
        for (const FrameRecord& record : records) rows.push_back(static_cast<T>(value(record)));
        h5::append_rows(m_where, column.dataset.get(), column.path, column.length, mem_type, rows.size(), rows.data());
    }
    /// One frame of an object's positions, every chunk it touches encoded here (chunk_codec.hpp)
    /// and written raw; through HDF5's own path only when uncompressed.
    void append_positions(ObjectColumns& columns, std::span<const float> xyz);

    h5::Where m_where;
    h5::Id m_file;
    h5::Id m_method_type;  ///< the enum of method names
    Column m_index, m_method, m_pairs, m_pair_offsets;
    Column m_time;                      ///< /frames/time (1.4), only with m_frame_times
    std::vector<Column> m_ms, m_counts;
    DetailGroup m_gpu, m_aabb, m_decision, m_hybrid;  ///< schema 1.1 (gpu, aabb) and 1.2 details
    Column m_gpu_passes, m_gpu_pass_offsets;
    Column m_gpu_survivors, m_gpu_survivor_offsets;   ///< 1.2
    DepthColumns m_depth;                             ///< 1.2
    RegionColumns m_regions;                          ///< 1.5, with SessionInfo::regions
    IntervalColumns m_intervals;                      ///< 1.7, with SessionInfo::between_frames
    std::vector<std::uint16_t> m_pixels;              ///< scratch: one image quantised
    std::vector<unsigned char> m_encoded;             ///< scratch: one positions chunk encoded
    std::vector<ObjectColumns> m_objects;
    std::unique_ptr<SpaceReserve> m_reserve;  ///< opened once SWMR writing started
    int m_deflate;
    bool m_damaged = false;
    std::uint64_t m_frames_written = 0;
    hsize_t m_depth_chunk;  ///< pixels per chunk of /gpu/depth/pixels: one image
    std::vector<double> m_frame_times;  ///< seconds per scene frame (SessionInfo::frame_times)
};

}  // namespace collidescope::recorder
