#pragma once
// The HDF5 side of the recorder: creates the whole layout up front, switches to SWMR writing,
// then appends one frame at a time and flushes. Used by one thread at a time.

#include "frame_queue.hpp"
#include "h5.hpp"

#include "collidescope/recorder/recorder.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace collidescope::recorder {

class TraceFile {
public:
    /// Creates `path` (latest file format, needed by SWMR), every group, dataset and attribute,
    /// then starts SWMR writing. `first` sizes the chunks (positions: one frame per chunk).
    TraceFile(const std::filesystem::path& path, const SessionInfo& session, const Frame& first,
              std::span<const std::string> methods, int deflate_level);

    /// Appends one frame (positions only when `keep_positions`), the frame index last, and
    /// flushes the file.
    void append(const FrameRecord& record, bool keep_positions);
    /// Current size of the file in bytes.
    std::uint64_t file_bytes() const;
    /// Bytes the positions datasets occupy (all objects).
    std::uint64_t positions_bytes() const;
    /// Closes the file (SWMR ends). Throws when the final flush fails.
    void close();

    /// Reopens a closed recording and adds the `finished` attributes.
    static void mark_finished(const std::filesystem::path& path, std::uint64_t frames, std::uint32_t positions_stride);

private:
    struct Column {
        h5::Id dataset;
        std::string path;
        hsize_t length = 0;
    };
    struct ObjectColumns {
        Column triangles, topology_offsets, topology_from_frame, topology_vertex_count, positions, vertex_offsets;
    };

    Column make_column(const std::string& path, const h5::ExtensibleSpec& spec, hid_t loc = -1);
    void write_metadata(const SessionInfo& session);
    void create_frames(std::span<const std::string> methods);
    void create_details();
    void append_details(const FrameRecord& record);
    void create_objects(const SessionInfo& session, const Frame& first, int deflate_level);
    void append_topology(ObjectColumns& columns, const Topology& topology, std::uint32_t frame);
    void append_value(Column& column, hid_t mem_type, const void* value);

    h5::Where m_where;
    h5::Id m_file;
    h5::Id m_method_type;  ///< the enum of method names
    Column m_index, m_method, m_pairs, m_pair_offsets;
    std::vector<Column> m_ms, m_counts;
    std::vector<Column> m_gpu, m_aabb;        ///< schema 1.1 details
    Column m_gpu_present, m_aabb_present, m_gpu_passes, m_gpu_pass_offsets;
    std::vector<ObjectColumns> m_objects;
    int m_deflate;
};

}  // namespace collidescope::recorder
