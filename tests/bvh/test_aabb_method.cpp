// The `aabb` method returns exactly the brute-force pairs: every built-in data set at the
// small preset, randomized scenes (many objects, fractured topology, degenerate triangles,
// coincident and coplanar sheets), self-collision on and off, 1, 2 and 4 threads, every
// builder and background mode; the validator passes after every build, refit and swap.

#include "bvh/bvh_helpers.hpp"

#include "support/brute_reference.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/datasets.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace collidescope::bvh {
namespace {

using testing::MethodRun;

// One configuration per thread count, so the grid covers builders and background modes.
struct Variant {
    int threads;
    Builder builder;
    BackgroundMode background;
    RebuildRule rule;
};

constexpr Variant k_variants[] = {
    {1, Builder::Sah, BackgroundMode::Off, RebuildRule::Quality},
    {2, Builder::Lbvh, BackgroundMode::NextFrame, RebuildRule::Quality},
    {4, Builder::Lbvh, BackgroundMode::Async, RebuildRule::Thesis},
};

std::string describe(const Variant& v) {
    return "threads " + std::to_string(v.threads) + (v.builder == Builder::Sah ? " sah " : " lbvh ") +
           "background " + std::to_string(static_cast<int>(v.background)) + " rule " +
           std::to_string(static_cast<int>(v.rule));
}

// Runs `frames` through a configured aabb method under a thread limit, validating every tree.
MethodRun run_aabb(const std::vector<Frame>& frames, bool self_collision, const Variant& variant,
                   testing::TreeChecker& checker) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                    static_cast<std::size_t>(variant.threads));
    AabbConfig config;
    config.build.builder = variant.builder;
    config.build.parallel_grain = 512;
    config.build.refit_grain = 64;
    config.background = variant.background;
    config.policy.rule = variant.rule;
    config.policy.quality_limit = 1.05;  // rebuild often, so swaps and rebuilds are exercised
    config.policy.payback_frames = 0;
    config.on_tree = checker.hook();
    const std::unique_ptr<Method> method = make_aabb_method(config);
    return testing::run_method(*method, frames, self_collision);
}

// Checks the aabb method against brute on every frame, for every variant and each self mode
// (both by default).
void expect_exact(const std::vector<Frame>& frames, std::uint64_t* colliding = nullptr,
                  const std::vector<bool>& self_modes = {false, true}) {
    for (const bool self_collision : self_modes) {
        const MethodRun reference = testing::run_pipeline("brute", frames, self_collision, 0);
        for (const Variant& variant : k_variants) {
            SCOPED_TRACE(describe(variant) + (self_collision ? " self" : ""));
            testing::TreeChecker checker;
            const MethodRun run = run_aabb(frames, self_collision, variant, checker);
            ASSERT_EQ(run.pairs.size(), frames.size());
            for (std::size_t f = 0; f < frames.size(); ++f) {
                ASSERT_EQ(run.pairs[f], reference.pairs[f]) << "frame " << f;
                EXPECT_EQ(run.stats[f].counts.exact_tests, run.stats[f].counts.candidate_pairs);
                // Candidates are the box-overlapping triangle pairs, as brute's prefilter finds,
                // less the adjacent pairs the traversal proved apart (adjacent_filter.hpp) and
                // the self pairs of patches proven embedded (surface_patches.hpp).
                const FrameCounts& counts = run.stats[f].counts;
                if (!self_collision) {
                    EXPECT_EQ(counts.adjacent_apart, 0u) << "frame " << f;
                }
                if (counts.self_culled_triangles == 0) {
                    EXPECT_EQ(counts.candidate_pairs + counts.adjacent_apart, reference.stats[f].counts.candidate_pairs)
                        << "frame " << f;
                } else {
                    EXPECT_LE(counts.candidate_pairs + counts.adjacent_apart, reference.stats[f].counts.candidate_pairs)
                        << "frame " << f;
                }
                if (colliding != nullptr) *colliding += run.pairs[f].size();
            }
            EXPECT_EQ(checker.failures, std::vector<std::string>{});
            EXPECT_GT(checker.builds + checker.refits, 0u);
        }
    }
}

class BuiltinScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltinScenes, MatchesBruteOnEveryFrame) {
    const Scene scene = make_builtin_scene(GetParam() + ":small");
    std::uint64_t colliding = 0;
    expect_exact(testing::all_frames(scene), &colliding);
    EXPECT_GT(colliding, 0u) << "the data set should collide somewhere";
}

INSTANTIATE_TEST_SUITE_P(SmallPreset, BuiltinScenes,
                         ::testing::Values("A", "B", "C", "D", "E1", "E2", "E3", "E4", "demo"));

// The cloth family (issue 23): flat, coplanar and near-contact self-collision, with
// self-collision on as the scenes say (two of them are one object, which without it has
// nothing to test); some scenes never collide, by construction.
class ClothFamily : public ::testing::TestWithParam<std::string> {};

TEST_P(ClothFamily, MatchesBruteOnEveryFrame) {
    expect_exact(testing::all_frames(make_builtin_scene(GetParam() + ":small")), nullptr, {true});
}

INSTANTIATE_TEST_SUITE_P(SmallPreset, ClothFamily,
                         ::testing::Values("cloth-rest", "cloth-drape", "cloth-crumple", "cloth-slide"));
// The contact family (issue 37): near contact at a small gap, and coplanar overlap.
INSTANTIATE_TEST_SUITE_P(ContactFamily, ClothFamily,
                         ::testing::Values("contact-layers", "contact-spheres", "contact-rods", "contact-rollers",
                                           "coplanar-stack"));

// Self-collision culling must not hide contact inside a flat or one-way patch: sheets folded
// onto themselves, slit (lips touching by position only), pinched (two vertices at one point),
// ramps winding over themselves (coplanar double cover, crossing layers), two flat sheets of
// one object meeting at a corner; each over frames that move it, so refit updates the sides.
TEST(AabbMethod, SelfCullingKeepsFoldsPinchesAndPiercings) {
    using Place = std::function<Vec3(double, double)>;
    const auto frames_of = [](const std::function<MeshData(double)>& at) {
        std::vector<std::vector<MeshData>> frames;
        for (int f = 0; f < 4; ++f) frames.push_back({at(0.1 * f)});
        Scene scene;
        scene.name = "self-cull";
        scene.source = make_memory_source({"sheet"}, std::move(frames));
        return testing::all_frames(scene);
    };
    const auto turned = [](MeshData mesh, double angle) {  // about z, so flat stays flat
        for (Vec3& v : mesh.vertices) v = Vec3(std::cos(angle) * v.x() - std::sin(angle) * v.y(),
                                               std::sin(angle) * v.x() + std::cos(angle) * v.y(), v.z());
        return mesh;
    };
    struct Case {
        std::string name;
        std::vector<Frame> frames;
    };
    std::vector<Case> cases;
    cases.push_back({"folded", frames_of([&](double t) {
        return turned(testing::surface_grid(16, 8, Place([](double u, double v) { return Vec3(u <= 0.5 ? u : 1 - u, v, 0); })), t);
    })});
    cases.push_back({"folded-tilted", frames_of([&](double t) {  // the flap lifted at its hinge by t
        return testing::surface_grid(16, 8, Place([t](double u, double v) { return Vec3(u <= 0.5 ? u : 1 - u, v, u <= 0.5 ? 0 : t * (u - 0.5)); }));
    })});
    cases.push_back({"slit", frames_of([&](double t) { return turned(testing::slit_sheet(12, 6), t); })});
    cases.push_back({"pinched", frames_of([&](double t) {
        return turned(testing::surface_grid(12, 12, Place([](double u, double v) {
            return Vec3(u + (v == 0.5 && u == 0.5 ? 1.0 / 12 : 0.0), v, 0);
        })), t);
    })});
    cases.push_back({"ramp-flat", frames_of([&](double t) { return turned(testing::helix_ramp(1.5, [](double) { return 0.0; }), t); })});
    cases.push_back({"ramp-rising", frames_of([&](double t) { return testing::helix_ramp(1.5, [t](double a) { return (0.1 + t) * a; }); })});
    cases.push_back({"ramp-piercing", frames_of([&](double t) {
        return testing::helix_ramp(1.75, [t](double a) { return (0.5 + t) * std::sin(0.75 * a); });
    })});
    cases.push_back({"corner-touch", frames_of([&](double t) {
        MeshData a = testing::grid_sheet(4, 4.0), b = testing::grid_sheet(4, 4.0, Vec3(4, 4, 0));
        const auto base = static_cast<std::uint32_t>(a.vertices.size());
        a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
        for (TriIndices tri : b.triangles) a.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
        return turned(a, t);
    })});
    for (const Case& c : cases) {
        const std::string& name = c.name;
        const std::vector<Frame>& frames = c.frames;
        SCOPED_TRACE(name);
        std::uint64_t colliding = 0;
        expect_exact(frames, &colliding, {true});
        std::printf("%s: %llu colliding pairs over %zu frames\n", name.c_str(), static_cast<unsigned long long>(colliding), frames.size());
        if (name != "ramp-rising") {
            EXPECT_GT(colliding, 0u);
        }
    }
}

// Closed surfaces in one object, as rod and n-body simulations export them: thin tubes with
// capped ends lying across each other and spheres pressed into each other, jittered per frame
// (a printed seed). Their adjacent pairs wrap all the way round (no patch holds a whole ring),
// so the traversal's adjacent_apart decides most of them; the contact between neighbours
// (touching, grazing, piercing) must come out exactly as brute's.
// A closed UV sphere: `rings` latitude bands of `segments` quads, fans at the two poles.
MeshData uv_sphere(int rings, int segments, double radius) {
    MeshData mesh;
    mesh.vertices.push_back(Vec3(0, 0, radius));
    for (int j = 1; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const double polar = std::numbers::pi * j / rings, a = 2 * std::numbers::pi * i / segments;
            mesh.vertices.push_back(radius * Vec3(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar)));
        }
    mesh.vertices.push_back(Vec3(0, 0, -radius));
    const auto id = [&](int i, int j) { return static_cast<std::uint32_t>(1 + (j - 1) * segments + (i % segments)); };
    const auto south = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    for (int i = 0; i < segments; ++i) {
        mesh.triangles.push_back({0, id(i, 1), id(i + 1, 1)});
        mesh.triangles.push_back({south, id(i + 1, rings - 1), id(i, rings - 1)});
        for (int j = 1; j + 1 < rings; ++j) {
            mesh.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
            mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
        }
    }
    return mesh;
}

MeshData tubes_and_spheres(std::mt19937_64& rng, double t) {
    MeshData mesh;
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    const auto add = [&](const std::vector<Vec3>& vertices, const std::vector<TriIndices>& triangles) {
        const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), vertices.begin(), vertices.end());
        for (const TriIndices& tri : triangles) mesh.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    };
    const int around = 6, along = 10;
    const double r = 0.1;
    for (int k = 0; k < 6; ++k) {  // two layers of three tubes, crossing, the layers 1.9 r apart
        std::vector<Vec3> v;
        std::vector<TriIndices> tris;
        const bool cross = k >= 3;
        const double offset = (k % 3 - 1) * 2.1 * r + jitter(rng), z = cross ? 1.9 * r + t * 0.05 : 0.0;
        for (int j = 0; j < along; ++j)
            for (int i = 0; i < around; ++i) {
                const double s = -0.5 + double(j) / (along - 1), a = 2 * std::numbers::pi * i / around + t;
                const Vec3 p(s, offset + r * std::cos(a), z + r * std::sin(a) + 0.3 * r * std::sin(4 * s + k));
                v.push_back(cross ? Vec3(p.y(), p.x(), p.z()) : p);
            }
        const auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * around + (i % around)); };
        for (int j = 0; j + 1 < along; ++j)
            for (int i = 0; i < around; ++i) {
                tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        for (int end = 0; end < 2; ++end) {  // fan caps round a centre vertex
            Vec3 centre = Vec3::Zero();
            for (int i = 0; i < around; ++i) centre += v[id(i, end * (along - 1))];
            v.push_back(centre / around);
            const auto c = static_cast<std::uint32_t>(v.size() - 1);
            for (int i = 0; i < around; ++i)
                tris.push_back(end == 0 ? TriIndices{c, id(i + 1, 0), id(i, 0)} : TriIndices{c, id(i, along - 1), id(i + 1, along - 1)});
        }
        add(v, tris);
    }
    const MeshData sphere = uv_sphere(8, 12, 0.2);
    for (int k = 0; k < 4; ++k) {  // spheres 0.39 apart with radius 0.2: pressed into each other
        std::vector<Vec3> v = sphere.vertices;
        const Vec3 centre(-0.6 + 0.39 * k + jitter(rng), 0.8, 0.1 * t);
        for (Vec3& p : v) p += centre;
        add(v, sphere.triangles);
    }
    return mesh;
}

TEST(AabbMethod, MatchesBruteOnTubesAndSpheresInOneObject) {
    const std::uint64_t seed = 0x7B5;
    std::mt19937_64 rng(seed);
    std::vector<std::vector<MeshData>> frames;
    for (int f = 0; f < 4; ++f) frames.push_back({tubes_and_spheres(rng, 0.1 * f)});
    Scene scene;
    scene.name = "tubes-and-spheres";
    scene.source = make_memory_source({"pile"}, std::move(frames));
    std::uint64_t colliding = 0;
    std::printf("seed %#llx\n", static_cast<unsigned long long>(seed));
    const std::vector<Frame> all = testing::all_frames(scene);
    expect_exact(all, &colliding, {true});
    EXPECT_GT(colliding, 0u);
    testing::TreeChecker checker;
    const MethodRun run = run_aabb(all, true, k_variants[1], checker);
    for (const FrameStats& stats : run.stats) EXPECT_GT(stats.counts.adjacent_apart, stats.counts.candidate_pairs);
}

TEST(AabbMethod, MatchesBruteOnRandomScenes) {
    std::uint64_t colliding = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        expect_exact(testing::all_frames(testing::random_scene(seed, {8, 4, 120, 8})), &colliding);
    }
    EXPECT_GT(colliding, 100u);
}

TEST(AabbMethod, MatchesBruteWithFracturedTopology) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const std::vector<Frame> frames = testing::all_frames(testing::fractured_scene(seed));
        // The scene does change topology (or this test would not test rebuilds).
        ASSERT_NE(frames.front().objects[0].topology->revision, frames.back().objects[0].topology->revision);
        expect_exact(frames);
        testing::TreeChecker checker;
        const MethodRun run = run_aabb(frames, true, k_variants[0], checker);
        std::uint8_t reasons = 0;
        for (const FrameStats& stats : run.stats) reasons |= stats.aabb->rebuild_reasons;
        EXPECT_NE(reasons & k_rebuild_topology, 0);
    }
}

TEST(AabbMethod, MatchesBruteOnCoincidentCoplanarAndDegenerate) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::uint64_t colliding = 0;
        expect_exact(testing::all_frames(testing::sheets_and_degenerates_scene(seed)), &colliding);
        EXPECT_GT(colliding, 0u);
    }
}

TEST(AabbMethod, ByNameThroughThePipeline) {
    const std::vector<Frame> frames = testing::all_frames(make_builtin_scene("demo:small"));
    for (const int threads : {1, 2}) {
        const MethodRun aabb = testing::run_pipeline("aabb", frames, true, threads);
        const MethodRun brute = testing::run_pipeline("brute", frames, true, threads);
        EXPECT_EQ(aabb.pairs, brute.pairs);
        for (const FrameStats& stats : aabb.stats) {
            EXPECT_EQ(stats.method, "aabb");
            ASSERT_TRUE(stats.aabb.has_value());
        }
    }
}

}  // namespace
}  // namespace collidescope::bvh
