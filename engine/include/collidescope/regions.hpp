#pragma once
/// Interpenetration regions (engine/src/regions): one level above the pair list.
///
/// For every colliding pair, the intersection of its two triangles (a segment or a point, or
/// a convex polygon when they are coplanar), constructed in double from exactly decided signs;
/// the segments chained into curves through the mesh edges they cross (closed loops where
/// closed surfaces cross, open chains ending on a border); the pairs grouped into regions
/// (pairs of one object pair connected through a shared vertex on either side); and the
/// regions followed over frames, with stable ids, splits and merges (RegionTracker).
/// docs/explanation/regions.md says what is computed and where it is not defined.

#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace collidescope {

/// The intersection of one colliding pair's triangles.
struct PairIntersection {
    enum class Kind : std::uint8_t { Point, Segment, Polygon };
    Kind kind = Kind::Point;
    /// Point: 1 point; Segment: its 2 ends; Polygon (coplanar overlap): its 3 to 6 corners in order.
    std::vector<Vec3> points;
    /// Polygon: its area; 0 otherwise.
    double area = 0;
};

/// The intersection of the triangles of `pair` in `frame` (the pair must collide).
PairIntersection intersect_pair(const Frame& frame, const TrianglePair& pair);

/// A chain of intersection segments: closed (a loop; the last point joins the first) or open
/// (both ends on a border of a mesh, or where the chaining could not decide, see regions.md).
struct IntersectionCurve {
    std::vector<Vec3> points;
    bool closed = false;
    double length = 0;
};

/// A connected set of colliding pairs of one object pair (obj_a == obj_b for self-contact).
struct Region {
    std::uint32_t obj_a = 0;
    std::uint32_t obj_b = 0;
    std::uint32_t pairs = 0;
    std::vector<std::uint32_t> triangles_a;  ///< obj_a's colliding triangles, ascending
    std::vector<std::uint32_t> triangles_b;  ///< obj_b's (self: empty, all in triangles_a)
    std::vector<IntersectionCurve> curves;
    std::uint32_t loops = 0;         ///< closed curves
    double curve_length = 0;         ///< the curves' total length
    double coplanar_area = 0;        ///< area of the coplanar overlap (Polygon intersections)
    Eigen::AlignedBox3d box;         ///< bounds of the curves and the coplanar polygons
    /// Area of obj_a's surface inside obj_b (NaN unless obj_b is closed; see regions.md).
    double inside_area_a = std::numeric_limits<double>::quiet_NaN();
    /// Area of obj_b's surface inside obj_a (NaN unless obj_a is closed).
    double inside_area_b = std::numeric_limits<double>::quiet_NaN();
    /// Penetration depth: the largest distance from a vertex of one object inside the other
    /// (reached from this region's curves) to the other's surface; NaN when neither object is
    /// closed or for self-contact. A lower bound of the deepest point; regions.md says how close.
    double depth = std::numeric_limits<double>::quiet_NaN();
    /// Its colliding pairs (indices into the frame's pair list, ascending).
    std::vector<std::uint32_t> pair_indices;

    // Over time (RegionTracker::update fills these; 0 / empty before).
    std::uint32_t id = 0;                      ///< stable id, from 1
    std::vector<std::uint32_t> predecessors;   ///< ids of last frame's regions it continues, strongest first
};

/// What find_regions measures.
struct RegionOptions {
    bool curves = true;   ///< chain the segments into curves (length, loops); off: counts and box only
    bool penetration = true;  ///< measure the inside areas and the depth (closed objects only)
};

/// The regions of one frame's colliding pairs (in any order; each pair once), ordered by their
/// first pair. Runs on TBB's threads.
std::vector<Region> find_regions(const Frame& frame, std::span<const TrianglePair> pairs,
                                 const RegionOptions& options = {});

/// One region followed over frames.
struct RegionTrack {
    std::uint32_t id = 0;
    std::uint32_t obj_a = 0;
    std::uint32_t obj_b = 0;
    std::uint32_t first_frame = 0;
    std::uint32_t last_frame = 0;
    std::uint32_t frames = 0;                 ///< frames it was present on
    double max_curve_length = 0;
    std::uint32_t max_curve_length_frame = 0;
    std::uint32_t max_pairs = 0;
    double max_depth = std::numeric_limits<double>::quiet_NaN();  ///< NaN: never defined
    std::uint32_t max_depth_frame = 0;
    std::uint32_t split_from = 0;             ///< the id of the region it split off (0: none)
    std::uint32_t merged_into = 0;            ///< the id of the region it merged into (0: none)
};

/// Gives regions stable ids over consecutive frames: a region continues last frame's regions of
/// the same objects that share a colliding triangle with it, or, when none does, whose boxes
/// overlap its box. Of several successors, the one sharing the most triangles keeps the id and
/// the others start tracks with split_from set (the predecessor they share most with); of
/// several predecessors, the one sharing the most keeps its id and the others end with
/// merged_into set (the first region of the frame that continues them).
class RegionTracker {
public:
    /// Assigns ids and predecessors to `regions` (find_regions of frame `frame`).
    void update(std::uint32_t frame, std::vector<Region>& regions);
    /// Every track so far, by id.
    const std::vector<RegionTrack>& tracks() const { return m_tracks; }

private:
    struct Previous {
        std::uint32_t id;
        std::uint32_t obj_a, obj_b;
        Eigen::AlignedBox3d box;
        std::vector<std::uint32_t> triangles_a, triangles_b;
    };
    std::vector<Previous> m_previous;
    /// Last frame's regions by triangle, per (objects, side): current where stamp == m_stamp.
    struct OwnerIndex {
        std::vector<std::uint32_t> stamp, previous;
    };
    std::map<std::pair<std::uint64_t, std::uint32_t>, OwnerIndex> m_owners;
    std::uint32_t m_stamp = 0;
    std::vector<RegionTrack> m_tracks;
    std::uint32_t m_last_frame = 0;
    bool m_any = false;
};

}  // namespace collidescope
