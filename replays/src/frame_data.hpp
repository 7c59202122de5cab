#pragma once
// What the replayer reads from a recording (replays/src, private): the session's metadata and
// per-frame series, read once, and one frame's geometry and culling state, read on demand.
// The reader is single-threaded (HDF5), so RecordingData is used under one lock.

#include "collidescope/gpu_cull.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/replays/camera.hpp"
#include "collidescope/types.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace collidescope::replays {

/// What a triangle shows (the fragment shader's colour choice, legend order).
enum TriangleState : std::uint8_t {
    k_state_plain = 0,      ///< no culling state recorded for this frame's method
    k_state_culled = 1,     ///< removed by the GPU cull (dimmed)
    k_state_pcs = 2,        ///< still in the PCS after the GPU cull
    k_state_colliding = 3,  ///< in a colliding pair
    k_state_only_here = 4,  ///< --diff: in a colliding pair only this recording found
};

/// One object of one frame.
struct ObjectFrame {
    std::vector<float> positions;  ///< x y z per vertex; empty when --budget dropped them
    std::shared_ptr<const std::vector<TriIndices>> triangles;
    std::size_t topology = 0;           ///< index of the topology in force (GL buffers are cached by it)
    std::vector<std::uint8_t> states;   ///< TriangleState per triangle
};

using NamedValues = std::vector<std::pair<std::string, double>>;

/// The moment of first contact between two recorded frames (replay --contact-moments; record
/// --between-frames): the earliest pass-through of the interval whose time is proven within the
/// tolerance (resolved), or the earliest unresolved one when it has no other.
struct ContactMoment {
    std::uint32_t to_frame = 0;       ///< the interval's second frame (FrameData::frame is its first)
    double toi = 0;                   ///< the first pass-through's time of contact (a lower bound)
    bool resolved = true;             ///< false: every pass-through of the interval is unresolved
    std::vector<TrianglePair> first;  ///< the pairs with that time (FrameData::colliding too)
    std::uint64_t contacts = 0;       ///< the interval's pairs
    std::uint64_t pass_throughs = 0;  ///< of them, apart at both frames
    std::array<double, 3> point{};    ///< the first pair's centre at toi (where the overlay marks it)
    /// The first pair's six corners at toi (triangle a, then b), outlined over the meshes.
    std::array<std::array<double, 3>, 6> corners{};
    bool point_known = false;         ///< false when positions were dropped
};

/// One recorded frame, everything the image shows.
struct FrameData {
    std::uint64_t row = 0;      ///< row in the recording
    std::uint32_t frame = 0;    ///< scene frame number
    std::uint64_t ordinal = 0;  ///< position among the replayed frames
    std::string method;
    std::vector<ObjectFrame> objects;
    NamedValues stage_ms;  ///< every stage, for_each_stage order
    NamedValues counts;    ///< every count, for_each_count order
    NamedValues gpu;       ///< for_each_gpu_value; empty when the frame ran no GPU cull
    NamedValues decision;  ///< for_each_decision_value; empty when not recorded
    NamedValues aabb;      ///< for_each_aabb_value; empty when not recorded
    NamedValues hybrid;    ///< for_each_hybrid_value; empty when not recorded
    std::vector<GpuPassInfo> passes;
    std::vector<GpuDepthImage> depth_images;
    std::vector<TrianglePair> colliding;  ///< the frame's colliding pairs, sorted
    std::vector<recorder::RecordedRegion> regions;  ///< record --regions; empty otherwise
    std::optional<ContactMoment> moment;  ///< set when the image is an interval's moment of contact
    std::uint64_t only_here = 0;  ///< --diff: pairs only this recording found
    bool pcs_recorded = false;    ///< survivors known (the frame ran the GPU cull)
    bool positions_dropped = false;
};

/// A region's lifetime over the recording's rows (first and last row, inclusive; record --regions).
struct RegionLife {
    std::uint32_t id = 0;
    std::uint64_t first = 0;
    std::uint64_t last = 0;
};

/// Lifetimes of every region in the first `rows` rows (empty without /regions), by id.
std::vector<RegionLife> region_lives(const recorder::Recording& recording, std::uint64_t rows);

/// Value of `name` in `values`, or NaN.
double value_of(const NamedValues& values, const std::string& name);

/// The thesis mode a frame ran in: the decision's mode when recorded, else from the method
/// (aabb 1, gpu 2, hybrid 3 = "hybrid", others 0).
int frame_mode(const std::string& method, const NamedValues& decision);

/// A recording opened for replay: metadata and per-frame series read at once.
class RecordingData {
public:
    /// Throws InputError naming the file when it cannot be read as a recording.
    explicit RecordingData(const std::filesystem::path& path);

    const std::string& path() const { return m_path; }
    const recorder::Recording& recording() const { return m_recording; }
    std::uint64_t rows() const { return m_indices.size(); }
    const std::vector<std::uint32_t>& indices() const { return m_indices; }
    const std::vector<std::string>& methods() const { return m_methods; }
    const std::vector<double>& totals() const { return m_totals; }  ///< ms.total per row
    const std::vector<int>& modes() const { return m_modes; }       ///< frame_mode per row
    const std::vector<RegionLife>& lives() const { return m_lives; }  ///< every region's rows (record --regions)
    const std::vector<std::uint64_t>& pair_counts() const { return m_pair_counts; }
    /// Rows r whose interval (from row r - 1 to row r; record --between-frames) has pass-throughs.
    const std::vector<std::uint64_t>& pass_through_rows() const { return m_pass_through_rows; }
    std::size_t object_count() const { return m_recording.objects().size(); }
    std::vector<std::string> object_names() const;
    /// A root attribute as text ("" when missing).
    std::string attribute(const std::string& name) const;
    /// Rows whose scene frame lies in [begin, end).
    std::vector<std::uint64_t> rows_in(std::uint32_t begin, std::uint32_t end) const;
    /// The bounds of every vertex of the given rows.
    Bounds bounds(const std::vector<std::uint64_t>& rows);
    /// Per row, the box of the vertices of its colliding triangles (empty: no pairs, or their
    /// positions were not recorded): what `--camera focus` frames.
    std::vector<Bounds> collision_bounds(const std::vector<std::uint64_t>& rows);
    /// Everything of row `row`; the culling state in ObjectFrame::states.
    FrameData load(std::uint64_t row, std::uint64_t ordinal);
    /// The moment of first contact of the interval from row `row - 1` to row `row` (one of
    /// pass_through_rows()): the meshes interpolated to its first pass-through's time, that
    /// pair's triangles colliding and nothing else marked; FrameData::moment set. The panel's
    /// stats are row `row - 1`'s.
    FrameData load_moment(std::uint64_t row, std::uint64_t ordinal);

private:
    std::shared_ptr<const std::vector<TriIndices>> topology(std::uint32_t object, std::size_t index);
    static NamedValues row_of(const std::vector<recorder::Series<double>>& series, std::uint64_t row);

    std::string m_path;
    recorder::Recording m_recording;
    std::vector<std::pair<std::string, std::string>> m_metadata;
    std::vector<std::uint32_t> m_indices;
    std::vector<std::string> m_methods;
    std::vector<recorder::Series<double>> m_stage_ms;
    std::vector<recorder::Series<std::uint64_t>> m_counts;
    std::vector<recorder::Series<double>> m_gpu, m_decision, m_aabb, m_hybrid;
    std::vector<double> m_totals;
    std::vector<RegionLife> m_lives;
    std::vector<int> m_modes;
    std::vector<std::uint64_t> m_pair_counts;
    std::vector<std::uint64_t> m_pass_through_rows;
    std::map<std::pair<std::uint32_t, std::size_t>, std::shared_ptr<const std::vector<TriIndices>>> m_topologies;
};

}  // namespace collidescope::replays
