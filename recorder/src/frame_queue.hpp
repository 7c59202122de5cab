#pragma once
// A frame as the writer thread needs it (copied off the engine's spans), and the bounded queue
// between the engine's thread and the writer thread.

#include "collidescope/gpu_cull.hpp"
#include "collidescope/large_blocks.hpp"
#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <array>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace collidescope::recorder {

/// A frame buffer: the platform's large blocks, unmapped when the writer thread frees them
/// (collidescope/large_blocks.hpp, BlockReuse::Release).
template <class T>
using LargeVector = detail::LargeVector<T, detail::BlockReuse::Release>;

/// One object of one frame.
struct ObjectRecord {
    std::shared_ptr<const Topology> new_topology;  ///< set when the topology changed (or frame 0)
    LargeVector<float> positions;                  ///< x y z per vertex, float32
};

/// One frame's regions, flattened as /regions stores them (schema.hpp).
struct RegionsRecord {
    std::vector<std::uint32_t> table;            ///< 7 per region
    std::vector<double> measures;                ///< 8 per region
    std::vector<double> penetration;             ///< 3 per region
    std::vector<std::uint64_t> curves;           ///< curves per region
    std::vector<std::uint8_t> closed;            ///< per curve
    std::vector<std::uint64_t> points;           ///< points per curve
    std::vector<double> xyz;                     ///< 3 per point
    std::vector<std::uint64_t> predecessor_counts;  ///< per region
    std::vector<std::uint32_t> predecessors;
    std::size_t bytes() const {
        return table.size() * 4 + measures.size() * 8 + penetration.size() * 8 + curves.size() * 8 + closed.size() + points.size() * 8 +
               xyz.size() * 8 + predecessor_counts.size() * 8 + predecessors.size() * 4;
    }
};

/// The interval that ends at a frame (record --between-frames), as /intervals stores it.
struct IntervalRecord {
    std::uint64_t counts[7] = {};   ///< schema::k_interval_counts order
    double ms[3] = {};              ///< broad, narrow, total
    double tolerance = std::numeric_limits<double>::quiet_NaN();  ///< NaN: no interval (the first frame)
    std::vector<TrianglePair> pairs;
    std::vector<double> toi;
    std::vector<std::uint8_t> flags;
    std::size_t bytes() const { return pairs.size() * sizeof(TrianglePair) + toi.size() * 8 + flags.size(); }
};

/// One frame, owned.
struct FrameRecord {
    std::uint32_t frame = 0;              ///< scene frame number
    std::uint8_t method = 0;              ///< code in the method enum
    std::vector<double> ms;               ///< for_each_stage order
    std::vector<std::uint64_t> counts;    ///< for_each_count order
    LargeVector<TrianglePair> pairs;
    std::vector<ObjectRecord> objects;
    bool has_gpu = false;                 ///< stats.gpu was set
    std::vector<double> gpu;              ///< for_each_gpu_value order (zeros without)
    std::vector<std::uint64_t> gpu_passes;  ///< for_each_pass_field order, row after row
    bool has_aabb = false;                ///< stats.aabb was set
    std::vector<double> aabb;             ///< for_each_aabb_value order (zeros without)
    bool has_decision = false;            ///< stats.decision was set (schema 1.2)
    std::vector<double> decision;         ///< for_each_decision_value order (zeros without)
    bool has_hybrid = false;              ///< stats.hybrid was set (schema 1.2)
    std::vector<double> hybrid;           ///< for_each_hybrid_value order (zeros without)
    LargeVector<std::array<std::uint32_t, 2>> survivors;  ///< GpuFrameInfo::survivors
    std::vector<GpuDepthImage> depth_images;              ///< GpuFrameInfo::depth_images
    RegionsRecord regions;                                ///< record --regions only
    IntervalRecord interval;                              ///< record --between-frames only

    /// Bytes held (what the queue's cap counts).
    std::size_t bytes() const;
};

/// Bounded by bytes, the frames queued and the frames the writer took but has not written yet:
/// push blocks while they hold more than the cap (a frame is always admitted into an empty
/// queue, so a frame larger than the cap still passes). close() ends the stream.
class FrameQueue {
public:
    explicit FrameQueue(std::size_t cap_bytes) : m_cap(cap_bytes) {}

    /// Blocks while full; returns false (dropping the frame) once closed.
    bool push(FrameRecord record);
    /// Frames taken by the writer: they still count against the cap until released.
    struct Taken {
        std::vector<FrameRecord> records;
        std::size_t bytes = 0;
    };
    /// Blocks until a frame or close, then takes every frame waiting, at most `max_frames`
    /// (at least 1); no records when closed and empty. Release the bytes once written.
    Taken take_waiting(std::size_t max_frames);
    /// The frames of a take are written: their bytes leave the cap.
    void release(std::size_t bytes);
    /// No more pushes; pop drains what is left. With `discard`, what is queued is dropped.
    void close(bool discard = false);
    std::size_t peak_bytes() const;

private:
    mutable std::mutex m_mutex;
    std::condition_variable m_not_full;
    std::condition_variable m_not_empty;
    std::deque<std::pair<FrameRecord, std::size_t>> m_frames;
    std::size_t m_cap;
    std::size_t m_bytes = 0;
    std::size_t m_peak = 0;
    bool m_closed = false;
};

}  // namespace collidescope::recorder
