// Scene builders and run helpers of the bvh tests.

#include "bvh/bvh_helpers.hpp"

#include "support/scene_builders.hpp"

#include "stages/object_level.hpp"

#include <algorithm>
#include <random>

namespace collidescope::testing {
namespace {

int draw(std::mt19937_64& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

// Every triangle of `mesh` with its own three vertices, moved by a small random grid step
// (0 .. `spread` quarter cells) and some triangles dropped: a new topology every call.
MeshData fracture(std::mt19937_64& rng, const MeshData& mesh, int spread, int keep_percent) {
    MeshData out;
    for (const TriIndices& tri : mesh.triangles) {
        if (draw(rng, 0, 99) >= keep_percent) continue;
        const Vec3 move(0.25 * draw(rng, -spread, spread), 0.25 * draw(rng, -spread, spread),
                        0.25 * draw(rng, -spread, spread));
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        for (const std::uint32_t v : tri) out.vertices.push_back(mesh.vertices[v] + move);
        out.triangles.push_back({base, base + 1, base + 2});
    }
    return out;
}

}  // namespace

Scene fractured_scene(std::uint64_t seed, std::uint32_t frames) {
    std::mt19937_64 rng(seed);
    const MeshData sheet = crumpled_sheet(rng, 6, 1.0, true);
    const MeshData floor = translated(grid_sheet(8, 8.0), Vec3(-1, -1, -1));
    std::vector<std::vector<MeshData>> all;
    MeshData pieces = sheet;
    for (std::uint32_t f = 0; f < frames; ++f) {
        if (f >= 2 && f % 2 == 0) pieces = fracture(rng, pieces.triangles.empty() ? sheet : pieces, 2, 90);
        MeshData moved = translated(pieces, Vec3(0, 0, -0.25 * f));  // falls into the floor
        all.push_back({moved, floor, grid_soup(rng, 12, 4, 1.5)});
    }
    Scene scene;
    scene.name = "fractured";
    scene.source = make_memory_source({"pieces", "floor", "soup"}, std::move(all));
    return scene;
}

Scene sheets_and_degenerates_scene(std::uint64_t seed, std::uint32_t frames) {
    std::mt19937_64 rng(seed);
    std::vector<std::vector<MeshData>> all;
    const MeshData sheet = grid_sheet(5, 5.0);
    for (std::uint32_t f = 0; f < frames; ++f) {
        MeshData soup = grid_soup(rng, 40, 5);
        // Degenerate on purpose: points and segments besides grid_soup's repeated corners.
        soup.vertices.push_back(Vec3(1, 1, 0));
        soup.vertices.push_back(Vec3(3, 1, 0));
        const auto n = static_cast<std::uint32_t>(soup.vertices.size());
        soup.triangles.push_back({n - 2, n - 2, n - 2});
        soup.triangles.push_back({n - 2, n - 1, n - 1});
        const double shift = 0.5 * (f % 3);
        all.push_back({sheet, sheet, translated(sheet, Vec3(shift, 2.5, 0)), soup});
    }
    Scene scene;
    scene.name = "sheets";
    scene.source = make_memory_source({"sheet", "same_sheet", "coplanar", "soup"}, std::move(all));
    return scene;
}

std::function<void(const bvh::TreeEvent&)> TreeChecker::hook() {
    return [this](const bvh::TreeEvent& event) {
        switch (event.kind) {
            case bvh::TreeEventKind::Build: ++builds; break;
            case bvh::TreeEventKind::Refit: ++refits; break;
            case bvh::TreeEventKind::Swap: ++swaps; break;
        }
        for (const std::string& error : bvh::validate(event.tree, event.triangles, event.vertices, options)) {
            failures.push_back("object " + std::to_string(event.object) + " event " +
                               std::to_string(static_cast<int>(event.kind)) + ": " + error);
        }
    };
}

MethodRun run_method(Method& method, const std::vector<Frame>& frames, bool self_collision) {
    MethodRun run;
    for (const Frame& frame : frames) {
        const std::vector<Eigen::AlignedBox3d> boxes = compute_object_boxes(frame);
        const std::vector<ObjectPair> object_pairs = find_object_pairs(boxes, self_collision);
        const FrameContext context{frame, boxes, object_pairs, self_collision};
        std::vector<TrianglePair> pairs;
        FrameStats stats;
        method.detect(context, pairs, stats);
        std::sort(pairs.begin(), pairs.end());
        pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
        run.pairs.push_back(std::move(pairs));
        run.stats.push_back(std::move(stats));
    }
    return run;
}

MethodRun run_pipeline(const std::string& method, const std::vector<Frame>& frames, bool self_collision,
                       int threads) {
    PipelineConfig config;
    config.method = method;
    config.self_collision = self_collision;
    config.threads = threads;
    Pipeline pipeline(config);
    MethodRun run;
    for (const Frame& frame : frames) {
        FrameResult result = pipeline.process(frame);
        run.pairs.push_back(std::move(result.colliding_pairs));
        run.stats.push_back(std::move(result.stats));
    }
    return run;
}

std::vector<TrianglePair> box_pairs(const MeshData& a, const MeshData* b) {
    std::vector<TrianglePair> pairs;
    const MeshData& other = b != nullptr ? *b : a;
    for (std::uint32_t i = 0; i < a.triangles.size(); ++i) {
        const bvh::Aabb box_i = bvh::triangle_box(a.triangles, a.vertices, i);
        for (std::uint32_t j = b != nullptr ? 0 : i + 1; j < other.triangles.size(); ++j) {
            if (bvh::overlaps(box_i, bvh::triangle_box(other.triangles, other.vertices, j))) {
                pairs.push_back({0, i, b != nullptr ? 1u : 0u, j});
            }
        }
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace collidescope::testing
