#pragma once
/// Between the frames (engine/src/ccd): continuous collision detection over the interval from
/// one frame to the next, every vertex moving on the straight line between its two positions.
///
/// A triangle pair is reported for the interval when the two triangles touch at some time t in
/// [0, 1]: they already touch at t = 0 (the exact per-frame test, with the self rule for
/// triangles of one object), or one of the pair's primitive queries (each vertex of one
/// against the other's face, each edge of one against each edge of the other) finds contact.
/// The queries are conservative, never exact-or-nothing: a pair that touches is always
/// reported, and a reported pair comes within `tolerance` of touching (docs/explanation/
/// between-frames.md says how, and the one case, marked `resolved` false, where that bound
/// is not proven).

#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace collidescope {

/// Options of between-frames detection.
struct BetweenFramesOptions {
    /// δ in scene units: a reported pair comes within δ (in each coordinate) of touching. 0:
    /// 1e-6 times the largest extent of the interval's bounding box (both frames).
    double tolerance = 0;
    /// Pairs of triangles of one object too (the self rule: features that share a vertex
    /// index are not queried, see between-frames.md).
    bool self_collision = false;
    /// Boxes one primitive query may refine before it stops and reports contact at the
    /// earliest time it has not excluded (conservative; counted as unresolved). A query asked
    /// after another of its pair found contact gets at most 4096. At least 1.
    std::uint32_t max_boxes = 50000;
};

/// One pair reported for an interval.
struct IntervalContact {
    TrianglePair pair;
    /// A lower bound of the earliest time of contact in [0, 1] (0: touching at the start); at
    /// this time the two triangles are within the tolerance of each other.
    double toi = 0;
    /// Apart at both ends of the interval: the contact a per-frame check cannot see.
    bool pass_through = false;
    /// False when a query spent its budget (max_boxes) before deciding: toi is then still a
    /// lower bound of the first contact, but the pair is not proven within the tolerance at
    /// toi (if another of its queries found contact, the pair is proven within it at some
    /// later time). Still reported.
    bool resolved = true;

    friend bool operator==(const IntervalContact&, const IntervalContact&) = default;
};

/// What one interval's detection did. Counts do not depend on the thread count.
struct IntervalStats {
    double tolerance = 0;                 ///< δ used (scene units)
    double ms = 0;                        ///< wall time of the whole interval
    double broad_ms = 0;                  ///< the swept trees: refit (or build) at both ends
    double narrow_ms = 0;                 ///< traversal and the pairs' tests
    std::uint64_t candidate_pairs = 0;    ///< triangle pairs whose swept boxes overlap
    std::uint64_t start_contacts = 0;     ///< pairs touching at t = 0
    /// Vertex-face and edge-edge queries the pairs asked (after their box test and filters). A
    /// query that several pairs ask is solved once where they meet on one thread and counted
    /// at each pair, as its boxes are below, so that the counts do not depend on the threads.
    std::uint64_t primitive_queries = 0;
    std::uint64_t inclusion_boxes = 0;    ///< boxes of those queries' solutions
    std::uint64_t contacts = 0;           ///< pairs reported
    std::uint64_t pass_throughs = 0;      ///< of them, apart at both ends
    std::uint64_t unresolved = 0;         ///< of them, with a query that hit max_boxes
};

/// The pairs of one interval, sorted by pair, each once, and what it took.
struct IntervalResult {
    std::vector<IntervalContact> contacts;
    IntervalStats stats;
};

/// Between-frames detection over consecutive intervals: keeps each object's swept-box tree
/// from interval to interval (refit, not rebuilt, while the topology stays). Not thread-safe:
/// one interval at a time (each runs in parallel inside, TBB).
class BetweenFrames {
public:
    explicit BetweenFrames(BetweenFramesOptions options = {});
    ~BetweenFrames();
    BetweenFrames(const BetweenFrames&) = delete;
    BetweenFrames& operator=(const BetweenFrames&) = delete;

    /// The interval from `from` to `to`. Throws InputError when the two frames' objects differ
    /// in number or topology, or a coordinate is not finite or above 1e100 (naming the object
    /// and frame).
    IntervalResult detect(const Frame& from, const Frame& to);

private:
    struct State;
    BetweenFramesOptions m_options;
    std::unique_ptr<State> m_state;
};

/// `message` (a BetweenFrames::detect error) with each "object N" followed by its name from
/// `names` ("object 1 ('hand')"), for the tools that know the names.
std::string with_object_names(const std::string& message, const std::vector<std::string>& names);

/// The slow, obviously correct evaluation that the tests hold BetweenFrames to: every
/// triangle pair (no trees; only the box of each triangle's corners at both ends), each query
/// by plain interval bisection with outward rounding after every operation. Same options and
/// contract; quadratic in the triangles.
IntervalResult between_frames_reference(const Frame& from, const Frame& to, const BetweenFramesOptions& options);

}  // namespace collidescope
