#pragma once
/// Reading a recording back (schema.hpp, docs/reference/recording.md).
///
/// Opening checks that the file is HDF5, is a collidescope recording and has a schema major
/// version this reader knows, and counts the complete frames: the smallest length over every
/// per-frame dataset, so a recording killed mid-frame reads up to its last finished frame. Every
/// failure is an InputError that names the file (and the dataset or frame). Reads go to the
/// file on each call; one thread at a time.

#include "collidescope/recorder/recording_info.hpp"

#include "collidescope/gpu_cull.hpp"
#include "collidescope/types.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace collidescope::recorder {

struct RecordingState;

class Recording {
public:
    /// Opens `path` read-only (SWMR read when the file allows it, so a recording being
    /// written or killed opens too). Throws InputError naming the file; for a virtual join,
    /// also when a part file it maps is missing, unreadable or short (naming part and dataset).
    explicit Recording(const std::filesystem::path& path);
    ~Recording();
    Recording(Recording&&) noexcept;
    Recording& operator=(Recording&&) noexcept;

    const std::string& path() const;
    std::int64_t version_major() const;
    std::int64_t version_minor() const;
    /// True when the writer closed the file cleanly (attribute `finished`).
    bool finished() const;
    /// The signal that stopped a finished run before its last frame (attribute `interrupted`,
    /// schema 1.3: "SIGINT", "SIGTERM"); "" when it ran to the end or did not finish.
    const std::string& interrupted() const;
    /// Frames the session asked for (attributes frame_end - frame_begin).
    std::uint64_t frames_requested() const;
    /// Why the file is partial, in words ("stopped by SIGINT after 12 of 60 frames", "not
    /// finished (the writer was killed, ...)"); "" for a complete recording.
    std::string partial_reason() const;
    /// Frames whose every dataset row is present.
    std::uint64_t frames_complete() const;
    /// Root attributes as text, in the file's order.
    std::vector<std::pair<std::string, std::string>> metadata() const;

    const std::vector<ObjectInfo>& objects() const;
    /// Scene frame number of every complete frame.
    std::vector<std::uint32_t> frame_indices() const;
    /// True when the file has /frames/time (schema 1.4, a scene whose inputs carry time).
    bool has_frame_times() const;
    /// Seconds from the clip's start of every complete frame (/frames/time); empty when absent.
    std::vector<double> frame_times() const;
    /// Frames per second of the source animation (attribute `fps`); 0 when the file does not say.
    double fps() const;
    /// The source animation clip's name (attribute `clip`); "" when none.
    const std::string& clip() const;
    /// The axis the inputs call up ('x', 'y', 'z'; attribute `up_axis`); 0 when the file does not say.
    char up_axis() const;
    /// Method name of every complete frame.
    std::vector<std::string> frame_methods() const;
    std::vector<Series<double>> stage_ms() const;
    std::vector<Series<std::uint64_t>> counts() const;
    /// Per-frame values of one group under /frames ("gpu", "aabb", "decision", "hybrid"), one Series per dataset in the order the for_each_*_value visitor lists them; empty when the file has no such group. Frames whose method did not set that optional hold NaN.
    std::vector<Series<double>> frame_values(const std::string& group) const;
    /// The cull passes of complete frame `row` (empty when its method ran no GPU cull).
    std::vector<GpuPassInfo> gpu_passes(std::uint64_t row) const;
    /// (object, triangle) of every triangle still in the GPU cull's PCS after culling at frame `row`, ascending (GpuFrameInfo::survivors); empty when none were recorded.
    std::vector<std::array<std::uint32_t, 2>> survivors(std::uint64_t row) const;
    /// The depth images recorded for frame `row` (GpuFrameInfo::depth_images); empty when none.
    std::vector<GpuDepthImage> depth_images(std::uint64_t row) const;

    /// Colliding pairs of recorded frame `row` (< frames_complete()).
    std::vector<TrianglePair> pairs(std::uint64_t row) const;
    /// True when the recording holds /regions (record --regions; schema 1.5).
    bool has_regions() const;
    /// Frame row `row`'s regions (empty without /regions); `curves` false leaves each region's
    /// curves empty and reads only the table, measures and predecessors (summaries).
    std::vector<RecordedRegion> regions(std::uint64_t row, bool curves = true) const;
    /// True when the recording holds /intervals (record --between-frames; schema 1.7).
    bool has_intervals() const;
    /// The interval from row `row - 1` to row `row` (1 <= row < frames_complete()); with
    /// `contacts` false, only its stats. Throws InputError without /intervals, for row 0, or
    /// on a corrupt file (naming the dataset and row).
    RecordedInterval interval(std::uint64_t row, bool contacts = true) const;
    /// Every complete row's interval stats at once (row 0: zeros and a NaN tolerance); empty
    /// without /intervals.
    std::vector<IntervalStats> interval_stats() const;
    /// Number of colliding pairs per complete frame (from the offsets).
    std::vector<std::uint64_t> pair_counts() const;
    /// x y z per vertex of object `object` at row `row`; empty when --budget dropped them.
    std::vector<float> positions(std::uint32_t object, std::uint64_t row) const;
    /// Index into objects()[object].topologies of the topology in force at scene frame `frame`.
    std::size_t topology_at(std::uint32_t object, std::uint32_t frame) const;
    /// Triangles of one topology of one object.
    std::vector<TriIndices> triangles(std::uint32_t object, std::size_t topology) const;

    /// Every dataset's path, in the file (for validate and inspect).
    std::vector<std::string> dataset_paths() const;
    /// The `unit` attribute of a dataset ("" when missing).
    std::string unit_of(const std::string& dataset) const;
    /// Rows (first dimension) of a dataset.
    std::uint64_t rows_of(const std::string& dataset) const;
    /// Bytes a dataset occupies in the file.
    std::uint64_t storage_of(const std::string& dataset) const;
    /// Reads a whole 1-D integer dataset (offsets, indices) converted to uint64.
    std::vector<std::uint64_t> read_u64(const std::string& dataset) const;
    /// The mappings of its virtual datasets (empty but for a virtual join). Opening checked
    /// that every part file they name is there and holds the rows they need: HDF5 itself would
    /// read a missing one as zeros.
    const std::vector<VirtualSource>& virtual_sources() const;

private:
    std::unique_ptr<RecordingState> m_impl;  ///< recorder/src/recording_state.hpp
};

}  // namespace collidescope::recorder
