#pragma once
// Helpers of the facade's tests: run a SceneFrames through a Session, pairs as check's TSV rows.

#include "support/cli_runner.hpp"

#include "collidescope/scene_frames.hpp"
#include "collidescope/session.hpp"

#include <algorithm>
#include <vector>

namespace collidescope::testing {

/// Declares every object of `scene` (triangles of frame 0) in `session`.
inline void declare_objects(Session& session, SceneFrames& scene) {
    scene.load(0);
    for (std::uint32_t k = 0; k < scene.object_count(); ++k) session.add_object(scene.triangles(k), scene.object_name(k));
}

/// Steps `session` through every frame of `scene` (packed double views; set_triangles where
/// an object's triangles change) and returns every frame's pairs as `check --pairs` rows.
inline std::vector<FramePair> session_pairs(Session& session, SceneFrames& scene) {
    std::vector<FramePair> rows;
    std::vector<std::vector<std::array<std::uint32_t, 3>>> in_force(scene.object_count());
    for (std::uint32_t f = 0; f < scene.frame_count(); ++f) {
        scene.load(f);
        for (std::uint32_t k = 0; k < scene.object_count(); ++k) {
            const auto triangles = scene.triangles(k);
            if (f > 0 && !std::equal(triangles.begin(), triangles.end(), in_force[k].begin(), in_force[k].end())) {
                session.set_triangles(k, triangles);
            }
            in_force[k].assign(triangles.begin(), triangles.end());
        }
        std::vector<VertexView> views;
        for (std::uint32_t k = 0; k < scene.object_count(); ++k) views.push_back(vertex_view(scene.positions(k)));
        for (const CollidingPair& p : session.step(views)) rows.push_back({f, {p.obj_a, p.tri_a, p.obj_b, p.tri_b}});
    }
    return rows;
}

}  // namespace collidescope::testing
