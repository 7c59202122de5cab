#pragma once
// Helpers of the facade's tests: run a SceneFrames through a Session, pairs as check's TSV rows.

#include "support/cli_runner.hpp"

#include "collidescope/scene_frames.hpp"
#include "collidescope/session.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace collidescope::testing {

/// Declares every object of `scene` (triangles of frame 0) in `session`.
inline void declare_objects(Session& session, SceneFrames& scene) {
    scene.load(0);
    for (std::uint32_t k = 0; k < scene.object_count(); ++k) session.add_object(scene.triangles(k), scene.object_name(k));
}

/// How a test hands positions to Session::step.
enum class Layout {
    Packed,   ///< packed x y z doubles: the engine views them in place (no copy)
    Float32,  ///< packed x y z floats: converted (the data sets' coordinates are float32 values)
    Padded,   ///< doubles, 4 per row (x y z and a pad): strided, converted
};

/// One object's positions of one frame in `layout`, in a buffer of the caller's own.
struct CallerPositions {
    std::vector<double> doubles;
    std::vector<float> floats;
    VertexView view;

    CallerPositions(std::span<const double> xyz, Layout layout) {
        const std::size_t count = xyz.size() / 3;
        if (layout == Layout::Float32) {
            floats.assign(xyz.begin(), xyz.end());
            for (std::size_t i = 0; i < xyz.size(); ++i) {
                if (static_cast<double>(floats[i]) != xyz[i]) ADD_FAILURE() << "coordinate " << i << " is not a float32 value";
            }
            view = vertex_view(std::span<const float>(floats));
        } else if (layout == Layout::Padded) {
            doubles.assign(count * 4, 0.0);
            for (std::size_t v = 0; v < count; ++v) std::copy_n(xyz.begin() + 3 * v, 3, doubles.begin() + 4 * v);
            view = vertex_view(doubles.data(), count, 4 * sizeof(double));
        } else {
            doubles.assign(xyz.begin(), xyz.end());
            view = vertex_view(std::span<const double>(doubles));
        }
    }
    /// What Session::step converts: 0 for packed doubles, 24 bytes per vertex otherwise.
    std::uint64_t expected_copied_bytes(Layout layout) const {
        return layout == Layout::Packed ? 0 : view.count * 3 * sizeof(double);
    }
    /// Overwrites the buffer with NaN (after the step: nothing may read it any more).
    void poison() {
        std::fill(doubles.begin(), doubles.end(), std::nan(""));
        std::fill(floats.begin(), floats.end(), std::nanf(""));
    }
};

/// Steps `session` through every frame of `scene` (set_triangles where an object's triangles
/// change) and returns every frame's pairs as `check --pairs` rows. Each frame's positions
/// are in fresh buffers of `layout`, overwritten with NaN and freed right after the step, so
/// anything that read them after step() returned would see NaN (or, under ASan, freed memory).
/// Checks each step's counts.positions_copied_bytes against the layout.
inline std::vector<FramePair> session_pairs(Session& session, SceneFrames& scene, Layout layout = Layout::Packed) {
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
        std::vector<CallerPositions> positions;
        positions.reserve(scene.object_count());
        std::vector<VertexView> views;
        std::uint64_t expected_copied = 0;
        for (std::uint32_t k = 0; k < scene.object_count(); ++k) {
            positions.emplace_back(scene.positions(k), layout);
            views.push_back(positions.back().view);
            expected_copied += positions.back().expected_copied_bytes(layout);
        }
        for (const CollidingPair& p : session.step(views)) rows.push_back({f, {p.obj_a, p.tri_a, p.obj_b, p.tri_b}});
        EXPECT_EQ(session.stats().counts.positions_copied_bytes, expected_copied) << "frame " << f;
        for (CallerPositions& object : positions) object.poison();
    }
    return rows;
}

}  // namespace collidescope::testing
