#pragma once
/// The embedding facade: collision detection called from the user's own simulation loop (api/).
///
///     collidescope::Session session({.method = "aabb", .record = "run.h5"});
///     session.add_object(cloth_triangles);             // triangles once, per object
///     session.add_object(body_triangles);
///     for (;;) {                                        // the user's loop
///         simulate(...);
///         const collidescope::VertexView views[] = {collidescope::vertex_view(cloth_xyz),
///                                                   collidescope::vertex_view(body_xyz)};
///         for (const collidescope::CollidingPair& pair : session.step(views)) { ... }
///     }
///
/// Pairs are exactly those `collidescope check --pairs` reports for the same frames; with
/// `record`, the session writes the HDF5 file `collidescope record` writes (docs/reference/recording.md),
/// which `replay`, `inspect` and collidescope.open read. docs/reference/embedding.md is the reference.
/// Not thread-safe: one thread drives a session; the engine parallelises inside step(). A
/// moved-from session may only be destroyed or assigned to.

#include "collidescope/step_regions.hpp"
#include "collidescope/step_stats.hpp"
#include "collidescope/vertex_view.hpp"

#include "collidescope/export.hpp"

#include <array>
#include <compare>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace collidescope {

/// Options of a Session: the command line's --method, --policy, --self, --threads, -o.
struct SessionOptions {
    /// Collision method: a name `collidescope check --method` accepts (adaptive, aabb, brute,
    /// gpu, gpu-naive, aabb-thesis, hybrid).
    std::string method = "adaptive";
    std::string policy = "cost";   ///< the decision system's policy (adaptive): "cost" or "thesis"
    bool self_collision = false;   ///< also report pairs within one object (DESIGN.md's rule)
    /// Worker threads, >= 0; 0 = all hardware threads. Process-wide while the session lives
    /// (a tbb::global_control; with several sessions alive, the smallest limit wins).
    int threads = 0;
    /// An HDF5 file to record every frame to, replaced if it exists ("" = no recording).
    std::string record;
    std::string scene = "session";  ///< the recording's `scene` attribute
    /// Find each step's interpenetration regions and follow them over steps (regions()), and
    /// record them when recording (`/regions`).
    bool regions = false;
};

/// One colliding triangle pair: objects numbered from 0 in add_object order, triangles in the
/// order given; (obj_a, tri_a) < (obj_b, tri_b).
struct CollidingPair {
    std::uint32_t obj_a = 0;
    std::uint32_t tri_a = 0;
    std::uint32_t obj_b = 0;
    std::uint32_t tri_b = 0;

    friend auto operator<=>(const CollidingPair&, const CollidingPair&) = default;
};

class COLLIDESCOPE_API Session {
public:
    /// Throws std::invalid_argument on an unknown method or policy or a negative thread
    /// count, and UnavailableError (collidescope/error.hpp) when the method needs a GL context
    /// the machine lacks.
    explicit Session(SessionOptions options = {});
    /// Finishes the recording (as close(), errors swallowed).
    ~Session();
    Session(Session&&) noexcept;
    Session& operator=(Session&&) noexcept;

    /// Declares the next object: its triangles (vertex indices, copied) and a name for the
    /// recording ("" = "object<k>"). Only before the first step. Returns the object's index.
    /// Indices are checked against the vertex count at the first step.
    std::uint32_t add_object(std::span<const std::array<std::uint32_t, 3>> triangles, std::string name = {});
    /// The same over packed indices, 3 per triangle (size must be a multiple of 3).
    std::uint32_t add_object(std::span<const std::uint32_t> triangles, std::string name = {});

    /// Replaces object `object`'s triangles (a topology change: fracture, remeshing) from the
    /// next step on, whose positions may then have another vertex count. Throws InputError on
    /// an unknown object or no triangles; indices are checked at that step.
    void set_triangles(std::uint32_t object, std::span<const std::array<std::uint32_t, 3>> triangles);

    /// Runs one frame: `positions[k]` holds object k's vertices (as many every frame as at the
    /// step its triangles took effect). Packed x y z doubles at a double's alignment are read
    /// where they lie, with no copy; other layouts (float32, strided) are converted once
    /// (stats().counts.positions_copied_bytes: 0, or 24 bytes per vertex converted). The
    /// memory is read during the call only, never after it returns.
    /// Returns the colliding pairs, sorted; the span lives until the next step or
    /// close. Throws InputError naming the object and element on bad input (wrong object or
    /// vertex count, a non-finite coordinate, a triangle index past the vertices), before
    /// the engine sees the frame; the session stays usable. Recording errors (a full disk)
    /// throw InputError naming the file and frame.
    std::span<const CollidingPair> step(std::span<const VertexView> positions);

    /// The last step's profile: its stage times and counts, as `check --stats` reports them
    /// (zero before the first step).
    const StepStats& stats() const;
    /// The last step's interpenetration regions (SessionOptions::regions; empty otherwise),
    /// as `check --regions` reports them; the span lives until the next step or close.
    std::span<const StepRegion> regions() const;
    /// The last step's stats as `check --stats` writes them, the methods' own parts included
    /// (hierarchies, GPU cull, decision): one JSON object, one line.
    std::string stats_json() const;
    /// Frames stepped so far; the next frame's number.
    std::uint32_t frame_count() const;
    std::uint32_t object_count() const;
    const SessionOptions& options() const;

    /// Writes what the recording has queued and closes it (marked finished); then step()
    /// throws. Idempotent. Throws InputError on a write failure. Without a recording, it only
    /// ends the session.
    void close();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace collidescope
