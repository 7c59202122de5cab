// Between-frames detection on whole frames: handcrafted pass-throughs, the self rule, bad
// input, and BetweenFrames against between_frames_reference on random scenes (soups snapped to
// a grid: exact touches, coplanar contact and motions along the grid; crumpled sheets with
// self-contact) at 1, 2 and 4 threads, seeds printed.

#include "ccd/contacts_by_pair.hpp"
#include "support/scene_builders.hpp"
#include "support/sweep_size.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/error.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <random>

namespace collidescope {
namespace {

using testing::grid_sheet;
using testing::translated;

// Two frames of the same meshes (positions from `from` and `to`).
std::pair<Frame, Frame> interval(std::vector<MeshData> from, std::vector<MeshData> to) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < from.size(); ++i) names.push_back("object" + std::to_string(i));
    auto source = make_memory_source(names, {std::move(from), std::move(to)});
    return {source->frame(0), source->frame(1)};
}

MeshData one_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    MeshData mesh;
    mesh.vertices = {a, b, c};
    mesh.triangles = {{0, 1, 2}};
    return mesh;
}

TEST(BetweenFrames, ATriangleThatPassesThroughASheetBetweenTwoFramesIsAPassThrough) {
    const MeshData sheet = grid_sheet(4, 4.0);  // z = 0, from (0, 0) to (4, 4)
    const MeshData small = one_triangle({1.2, 1.3, 0}, {1.6, 1.3, 0}, {1.3, 1.7, 0});
    const auto [from, to] = interval({sheet, translated(small, {0, 0, 1})}, {sheet, translated(small, {0, 0, -3})});
    BetweenFrames detector;
    const IntervalResult result = detector.detect(from, to);
    ASSERT_FALSE(result.contacts.empty());
    for (const IntervalContact& c : result.contacts) {
        EXPECT_TRUE(c.pass_through);
        EXPECT_LE(c.toi, 0.25);  // reaches z = 0 at t = 1/4
        EXPECT_GE(c.toi, 0.25 - 1e-3);
    }
    EXPECT_EQ(result.stats.pass_throughs, result.contacts.size());
    const IntervalResult reference = between_frames_reference(from, to, {});
    ASSERT_EQ(reference.contacts.size(), result.contacts.size());
    for (std::size_t i = 0; i < reference.contacts.size(); ++i) EXPECT_EQ(reference.contacts[i].pair, result.contacts[i].pair);
}

TEST(BetweenFrames, ContactAtAnEndIsNotAPassThroughAndAStillPairTouchingAtTheStartHasToiZero) {
    const MeshData sheet = grid_sheet(2, 2.0);
    const MeshData small = one_triangle({0.3, 0.3, 0}, {0.6, 0.3, 0}, {0.3, 0.6, 0});
    {  // ends on the sheet
        const auto [from, to] = interval({sheet, translated(small, {0, 0, 1})}, {sheet, small});
        const IntervalResult r = BetweenFrames().detect(from, to);
        ASSERT_FALSE(r.contacts.empty());
        for (const IntervalContact& c : r.contacts) EXPECT_FALSE(c.pass_through);
    }
    {  // lies on it throughout
        const auto [from, to] = interval({sheet, small}, {sheet, small});
        const IntervalResult r = BetweenFrames().detect(from, to);
        ASSERT_FALSE(r.contacts.empty());
        for (const IntervalContact& c : r.contacts) {
            EXPECT_EQ(c.toi, 0);
            EXPECT_FALSE(c.pass_through);
        }
        EXPECT_EQ(r.stats.start_contacts, r.contacts.size());
    }
}

TEST(BetweenFrames, AFoldThroughItselfBetweenFramesIsFoundWithSelfCollisionAndNeighboursAreNot) {
    // A strip of two triangles sharing an edge: still, nothing (the self rule); one folded
    // through the other between the frames, a pass-through of the pair.
    MeshData strip;
    strip.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    strip.triangles = {{0, 1, 2}, {1, 3, 2}};
    MeshData folded = strip;
    folded.vertices[3] = {-0.5, -0.5, -0.2};  // through triangle 0, below its plane
    MeshData above = strip;
    above.vertices[3] = {-0.5, -0.5, 0.3};
    BetweenFramesOptions self;
    self.self_collision = true;
    {
        const auto [from, to] = interval({strip}, {strip});
        EXPECT_TRUE(BetweenFrames(self).detect(from, to).contacts.empty());
    }
    {
        // Vertex 3 swings from (1, 1, 0) up over the shared edge and down through triangle 0.
        const auto [from, to] = interval({above}, {folded});
        const IntervalResult r = BetweenFrames(self).detect(from, to);
        const IntervalResult reference = between_frames_reference(from, to, self);
        ASSERT_EQ(r.contacts.size(), 1u);
        ASSERT_EQ(reference.contacts.size(), 1u);
        EXPECT_EQ(r.contacts[0].pair, reference.contacts[0].pair);
        EXPECT_TRUE(r.contacts[0].pass_through);
    }
}

// A sheet that bends and slides a little between the frames: its patches stay embedded
// throughout (swept_patches.hpp), so the self walk tests next to none of its neighbouring
// pairs, and the answer is the reference's (nothing). Folded through itself instead, the
// fold is found: its patches are not proven.
TEST(BetweenFrames, AGentlyMovingSheetIsSkippedByItsPatchesAndAFoldIsStillFound) {
    const MeshData flat = grid_sheet(12, 1.0);
    MeshData bent = flat;
    for (Vec3& p : bent.vertices) p += Vec3(0.05 * p.y(), 0.02, 0.1 * std::sin(3 * p.x()));
    BetweenFramesOptions self;
    self.self_collision = true;
    const auto [from, to] = interval({flat}, {bent});
    const IntervalResult r = BetweenFrames(self).detect(from, to);
    const IntervalResult reference = between_frames_reference(from, to, self);
    EXPECT_TRUE(r.contacts.empty());
    EXPECT_TRUE(reference.contacts.empty());
    // The reference lists every neighbouring pair (their swept boxes meet); the walk skips them.
    EXPECT_GT(reference.stats.candidate_pairs, 1000u);
    EXPECT_LT(r.stats.candidate_pairs, reference.stats.candidate_pairs / 10);
    // A small sheet's half beyond x = 0.5 swung over and down through the other half.
    const MeshData small = grid_sheet(4, 1.0);
    MeshData folded = small;
    for (Vec3& p : folded.vertices) {
        if (p.x() > 0.5) p = Vec3(1.0 - p.x() + 0.01, p.y(), -0.05);
    }
    const auto [start, end] = interval({small}, {folded});
    const IntervalResult fold = BetweenFrames(self).detect(start, end);
    const IntervalResult fold_reference = between_frames_reference(start, end, self);
    EXPECT_FALSE(fold.contacts.empty());
    EXPECT_EQ(testing::contacts_by_pair(fold).size(), testing::contacts_by_pair(fold_reference).size());
    for (const auto& [pair, found] : testing::contacts_by_pair(fold_reference)) {
        EXPECT_TRUE(testing::contacts_by_pair(fold).count(pair)) << "missed " << pair.tri_a << " " << pair.tri_b;
    }
}

// Two triangles of one object in one plane throughout, one folding over the other through what
// they share (an edge; a vertex): contact starts at the shared vertex, where only an edge-edge
// query between unshared features sees it (a review found the coplanar shortcut, which skips
// edge-edge queries, dropping these).
TEST(BetweenFrames, CoplanarFoldsThroughASharedVertexAreFound) {
    BetweenFramesOptions self;
    self.self_collision = true;
    {
        MeshData from;
        from.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {0.5, -1, 0}};
        from.triangles = {{0, 1, 2}, {0, 1, 3}};
        MeshData to = from;
        to.vertices[2] = {2, -1, 0};
        const auto [a, b] = interval({from}, {to});
        const IntervalResult r = BetweenFrames(self).detect(a, b);
        ASSERT_EQ(r.contacts.size(), 1u);
        EXPECT_FALSE(r.contacts[0].pass_through);  // overlapping at the end
        EXPECT_EQ(r.contacts[0].pair, between_frames_reference(a, b, self).contacts.at(0).pair);
    }
    {
        MeshData from;
        from.vertices = {{0, 0, 0}, {-1, 0, 0}, {1, 1, 0}, {-0.5, -1, 0}, {0.5, -1, 0}};
        from.triangles = {{0, 1, 2}, {0, 3, 4}};
        MeshData to = from;
        to.vertices[2] = {1, -1, 0};
        const auto [a, b] = interval({from}, {to});
        const IntervalResult r = BetweenFrames(self).detect(a, b);
        ASSERT_EQ(r.contacts.size(), 1u);
        EXPECT_EQ(r.contacts[0].pair, between_frames_reference(a, b, self).contacts.at(0).pair);
    }
}

TEST(BetweenFrames, BadIntervalsAreOneLineErrors) {
    const MeshData sheet = grid_sheet(2, 1.0);
    MeshData other = grid_sheet(3, 1.0);
    {
        const auto source_a = make_memory_source({"a"}, {{sheet}});
        const auto source_b = make_memory_source({"a"}, {{other}});
        const Frame from = source_a->frame(0), to = source_b->frame(0);
        try {
            BetweenFrames().detect(from, to);
            FAIL() << "a topology change was accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("object 0 changes its mesh"), std::string::npos) << e.what();
        }
    }
    {
        const auto source = make_memory_source({"a", "b"}, {{sheet, sheet}});
        const auto single = make_memory_source({"a"}, {{sheet}});
        EXPECT_THROW(BetweenFrames().detect(source->frame(0), single->frame(0)), InputError);
    }
}

// The frames' one scan: the first unfit coordinate named by frame, object and vertex (in
// either frame, NaN, infinity or above 1e100), and the default tolerance from both frames' box.
TEST(BetweenFrames, UnfitCoordinatesAreNamedAndTheToleranceSpansBothFrames) {
    const MeshData sheet = grid_sheet(2, 1.0);  // [0, 1] x [0, 1] in z = 0
    // Vertex `vertex`'s coordinate `axis` set to `value` in one frame, after the source (which
    // would refuse it: the engine's own check is tested here). Nine vertices: the scan reads
    // them in pairs, and vertex 8 alone.
    const auto error_of = [&](std::size_t frame, std::size_t vertex, int axis, double value) {
        auto [a, b] = interval({sheet, sheet}, {sheet, sheet});
        std::vector<Vec3> changed = sheet.vertices;
        changed[vertex][axis] = value;
        (frame == 0 ? a : b).objects[1].vertices = std::move(changed);
        try {
            BetweenFrames().detect(a, b);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    ASSERT_EQ(sheet.vertices.size(), 9u);
    const std::string not_finite = " is not finite (between-frames detection needs finite coordinates)";
    const std::string too_large = " has a coordinate above 1e100 (between-frames detection's limit)";
    EXPECT_EQ(error_of(1, 2, 1, std::nan("")), "frame 1, object 1: vertex 2" + not_finite);
    EXPECT_EQ(error_of(0, 4, 0, -std::numeric_limits<double>::infinity()), "frame 0, object 1: vertex 4" + not_finite);
    EXPECT_EQ(error_of(1, 8, 2, std::nan("")), "frame 1, object 1: vertex 8" + not_finite);
    EXPECT_EQ(error_of(0, 8, 0, std::numeric_limits<double>::infinity()), "frame 0, object 1: vertex 8" + not_finite);
    EXPECT_EQ(error_of(1, 5, 2, std::numeric_limits<double>::infinity()), "frame 1, object 1: vertex 5" + not_finite);
    EXPECT_EQ(error_of(1, 0, 1, 2e100), "frame 1, object 1: vertex 0" + too_large);
    EXPECT_EQ(error_of(0, 7, 2, -3e100), "frame 0, object 1: vertex 7" + too_large);
    EXPECT_EQ(error_of(1, 8, 1, -2e100), "frame 1, object 1: vertex 8" + too_large);
    EXPECT_EQ(error_of(0, 3, 1, 1e100), "no error");
    EXPECT_EQ(error_of(1, 8, 0, -1e100), "no error");

    // A frame large enough to be scanned in parallel runs (2^15 vertices a run): the unfit
    // vertex found in any run, an odd one last, and the tolerance from every run's box.
    {
        const MeshData big = grid_sheet(300, 1.0, {0, 0, 10});  // 301 x 301 = 90,601 vertices, above the sheet
        ASSERT_GT(big.vertices.size(), 2u << 15);
        const auto big_error_of = [&](std::size_t vertex, double value) {
            auto [a, b] = interval({sheet, big}, {sheet, big});
            std::vector<Vec3> changed = big.vertices;
            changed[vertex][2] = value;
            b.objects[1].vertices = std::move(changed);
            try {
                return "tolerance " + std::to_string(BetweenFrames().detect(a, b).stats.tolerance);
            } catch (const InputError& e) {
                return std::string(e.what());
            }
        };
        for (const std::size_t vertex : {std::size_t{5}, std::size_t{40000}, std::size_t{70001}, big.vertices.size() - 1}) {
            EXPECT_EQ(big_error_of(vertex, std::nan("")), "frame 1, object 1: vertex " + std::to_string(vertex) + not_finite);
            EXPECT_EQ(big_error_of(vertex, 1e101), "frame 1, object 1: vertex " + std::to_string(vertex) + too_large);
            EXPECT_EQ(big_error_of(vertex, -4.0), "tolerance " + std::to_string(14e-6)) << vertex;  // z from -4 to 10
        }
    }

    // An object without vertices or triangles (no source makes one; a frame built by hand
    // may hold one) is read past.
    {
        auto [a, b] = interval({sheet, sheet}, {sheet, sheet});
        const auto nothing = std::make_shared<const Topology>();
        for (Frame* frame : {&a, &b}) frame->objects[1] = ObjectFrame{nothing, std::vector<Vec3>{}};
        EXPECT_TRUE(BetweenFrames().detect(a, b).contacts.empty());
    }

    // The box of both frames: the sheet at z = 0, then moved up by 4 (extent 4 along z).
    const auto [from, to] = interval({sheet}, {translated(sheet, {0, 0, 4})});
    EXPECT_DOUBLE_EQ(BetweenFrames().detect(from, to).stats.tolerance, 4e-6);
    BetweenFramesOptions set;
    set.tolerance = 0.25;
    EXPECT_EQ(BetweenFrames(set).detect(from, to).stats.tolerance, 0.25);
    EXPECT_DOUBLE_EQ(between_frames_reference(from, to, {}).stats.tolerance, 4e-6);
}

// A triangle of a soup moving linearly: at frame f its corners are centre + f velocity + corner.
struct MovingTriangle {
    Vec3 centre, velocity;
    std::array<Vec3, 3> corners;
};

// The frames of soups of moving triangles (objects "soup0", "soup1", ...), each triangle with
// three vertices of its own; with the source their data come from.
struct SoupFrames {
    std::shared_ptr<FrameSource> source;
    std::vector<Frame> frames;
};

SoupFrames soup_frames(const std::vector<std::vector<MovingTriangle>>& soups, int frame_count) {
    std::vector<std::string> names;
    std::vector<std::vector<MeshData>> by_frame(static_cast<std::size_t>(frame_count));
    for (std::size_t s = 0; s < soups.size(); ++s) {
        names.push_back("soup" + std::to_string(s));
        for (int f = 0; f < frame_count; ++f) {
            MeshData mesh;
            for (const MovingTriangle& t : soups[s]) {
                const auto v = static_cast<std::uint32_t>(mesh.vertices.size());
                for (const Vec3& corner : t.corners) mesh.vertices.push_back(t.centre + f * t.velocity + corner);
                mesh.triangles.push_back({v, v + 1, v + 2});
            }
            by_frame[static_cast<std::size_t>(f)].push_back(std::move(mesh));
        }
    }
    SoupFrames out;
    out.source = make_memory_source(std::move(names), std::move(by_frame));
    for (int f = 0; f < frame_count; ++f) out.frames.push_back(out.source->frame(static_cast<std::uint32_t>(f)));
    return out;
}

// Two soups flying apart and through each other, each triangle along its own direction, so
// that the swept trees degrade within a few intervals and are built again (the swept build,
// at the interval after a refit passes its threshold): interval by interval, the reference's
// pairs and pass-throughs, at one and two threads.
TEST(BetweenFrames, EqualsTheReferenceAsFlyingSoupsAreBuiltAgain) {
    constexpr std::uint64_t seed = 41;
    std::printf("[ seed     ] BetweenFrames flying soups: seed %llu\n", static_cast<unsigned long long>(seed));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto random_vector = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
    constexpr int k_triangles = 90, k_frames = 12;
    // Per soup: each triangle's centre, velocity and corner offsets; the two soups start
    // overlapping and fly out of a shared cube.
    std::vector<std::vector<MovingTriangle>> soups(2);
    for (int soup = 0; soup < 2; ++soup) {
        for (int t = 0; t < k_triangles; ++t) {
            MovingTriangle& moving = soups[soup].emplace_back();
            moving.centre = 0.5 * random_vector() + Vec3(0.2 * soup, 0, 0);
            moving.velocity = 0.3 * random_vector();
            moving.corners = {0.08 * random_vector(), 0.08 * random_vector(), 0.08 * random_vector()};
        }
    }
    const SoupFrames generated = soup_frames(soups, k_frames);
    const std::vector<Frame>& all = generated.frames;
    std::size_t contacts = 0;
    for (const int threads : {1, 2}) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        BetweenFrames detector;
        for (int f = 0; f + 1 < k_frames; ++f) {
            const std::string what = "interval " + std::to_string(f) + " threads " + std::to_string(threads);
            const auto fast = testing::contacts_by_pair(detector.detect(all[f], all[f + 1]));
            const auto slow = testing::contacts_by_pair(between_frames_reference(all[f], all[f + 1], {}));
            ASSERT_EQ(fast.size(), slow.size()) << what;
            for (const auto& [pair, found] : fast) {
                const auto it = slow.find(pair);
                ASSERT_TRUE(it != slow.end()) << what << ": not in the reference " << pair.tri_a << " " << pair.tri_b;
                EXPECT_EQ(found.pass_through, it->second.pass_through) << what;
            }
            contacts += fast.size();
        }
    }
    std::printf("%zu contacts over the flying soups' intervals\n", contacts);
    EXPECT_GT(contacts, 0u);
}

// Random scenes: the fast detector against the reference, interval by interval.
TEST(BetweenFrames, EqualsTheReferenceOnRandomScenesAtOneTwoAndFourThreads) {
    int pass_throughs = 0, contacts = 0;
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({11, 12, 13, 14}, 2)) {
        std::printf("[ seed     ] BetweenFrames random scene: seed %llu\n", static_cast<unsigned long long>(seed));
        testing::RandomSceneConfig config;
        config.objects = 3;
        config.frames = 4;
        config.max_triangles = 30;
        config.sheet_cells = 4;
        const Scene scene = testing::random_scene(seed, config);
        const std::vector<Frame> frames = testing::all_frames(scene);
        for (const bool self : {false, true}) {
            BetweenFramesOptions options;
            options.self_collision = self;
            std::vector<IntervalResult> by_threads;
            for (const int threads : {1, 2, 4}) {
                const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
                BetweenFrames detector(options);
                for (std::size_t f = 0; f + 1 < frames.size(); ++f) {
                    IntervalResult r = detector.detect(frames[f], frames[f + 1]);
                    if (threads == 1) by_threads.push_back(std::move(r));
                    else EXPECT_EQ(r.contacts, by_threads[f].contacts) << "seed " << seed << " interval " << f << " threads " << threads;
                }
            }
            for (std::size_t f = 0; f + 1 < frames.size(); ++f) {
                const std::string what = "seed " + std::to_string(seed) + " interval " + std::to_string(f) + (self ? " self" : "");
                const auto fast = testing::contacts_by_pair(by_threads[f]);
                // The reference at the same tolerance: the same pairs, the same pass-throughs.
                const auto slow = testing::contacts_by_pair(between_frames_reference(frames[f], frames[f + 1], options));
                // No false negative: the reference at a far finer tolerance finds nothing the fast one misses.
                BetweenFramesOptions fine = options;
                fine.tolerance = 1e-12;
                fine.max_boxes = 20000;
                for (const auto& [pair, found] : testing::contacts_by_pair(between_frames_reference(frames[f], frames[f + 1], fine))) {
                    if (!found.resolved) continue;  // not proven within 1e-12: no claim
                    EXPECT_TRUE(fast.count(pair)) << what << ": missed " << pair.obj_a << ":" << pair.tri_a << " " << pair.obj_b << ":" << pair.tri_b;
                }
                for (const auto& [pair, found] : fast) {
                    const auto it = slow.find(pair);
                    EXPECT_TRUE(it != slow.end()) << what << ": not in the reference " << pair.obj_a << ":" << pair.tri_a << " " << pair.obj_b << ":" << pair.tri_b;
                    if (it == slow.end()) continue;
                    EXPECT_EQ(found.pass_through, it->second.pass_through) << what;
                    EXPECT_NEAR(found.toi, it->second.toi, 1e-3) << what;
                    pass_throughs += found.pass_through;
                    ++contacts;
                }
                EXPECT_EQ(fast.size(), slow.size()) << what;
            }
        }
    }
    std::printf("%d contacts, %d pass-throughs over the random intervals\n", contacts, pass_throughs);
    EXPECT_GT(pass_throughs, 0);
}

// Two soups on a grid of 1/8 (corners, centres and velocities), so that contacts at exact times,
// shared planes, touching corners and parallel edges are common; every fifth triangle is a
// segment (two corners equal) and every seventh stands still; the second seed sits 1e6 from the
// origin. Against the reference at the same tolerance: every pair the detector reports, with the
// same pass-through flag; against it at 1e-12: no pair proven touching is missed. The detector
// may leave out a pair the reference accepts within the tolerance without a touch (its overlap
// window proves some of them apart: docs/explanation/between-frames.md); how many is printed.
TEST(BetweenFrames, EqualsTheReferenceOnGridSoupsWithSegmentsAndStillTriangles) {
    std::size_t contacts = 0, pass_throughs = 0, left_out = 0;
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({51, 52}, 2)) {
        const double offset = seed == 52 ? 1e6 : 0.0;
        std::printf("[ seed     ] BetweenFrames grid soups: seed %llu, offset %g\n", static_cast<unsigned long long>(seed), offset);
        std::mt19937_64 rng(seed);
        std::uniform_int_distribution<int> cell(-8, 8);
        const auto grid = [&]() -> Vec3 {
            const double x = cell(rng), y = cell(rng), z = cell(rng);
            return Vec3(x, y, z) / 8.0;
        };
        constexpr int k_triangles = 30, k_frames = 4;
        std::vector<std::vector<MovingTriangle>> soups(2);
        for (int soup = 0; soup < 2; ++soup) {
            for (int t = 0; t < k_triangles; ++t) {
                MovingTriangle& moving = soups[soup].emplace_back();
                moving.centre = 0.5 * grid() + Vec3(offset, 0, 0);  // exact: every coordinate is on a grid of 1/32
                moving.velocity = t % 7 == 0 ? Vec3::Zero() : Vec3(0.5 * grid());
                moving.corners = {0.25 * grid(), 0.25 * grid(), 0.25 * grid()};
                if (t % 5 == 0) moving.corners[2] = moving.corners[1];
            }
        }
        const SoupFrames generated = soup_frames(soups, k_frames);
        const std::vector<Frame>& frames = generated.frames;
        for (const bool self : {false, true}) {
            BetweenFramesOptions options;
            options.self_collision = self;
            BetweenFramesOptions fine = options;
            fine.tolerance = 1e-12;
            fine.max_boxes = 20000;
            std::vector<IntervalResult> by_threads;
            for (const int threads : {1, 2}) {
                const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
                BetweenFrames detector(options);
                for (std::size_t f = 0; f + 1 < frames.size(); ++f) {
                    IntervalResult r = detector.detect(frames[f], frames[f + 1]);
                    if (threads == 1) by_threads.push_back(std::move(r));
                    else EXPECT_EQ(r.contacts, by_threads[f].contacts) << "seed " << seed << " interval " << f;
                }
            }
            for (std::size_t f = 0; f + 1 < frames.size(); ++f) {
                const std::string what = "seed " + std::to_string(seed) + " interval " + std::to_string(f) + (self ? " self" : "");
                const auto fast = testing::contacts_by_pair(by_threads[f]);
                const auto slow = testing::contacts_by_pair(between_frames_reference(frames[f], frames[f + 1], options));
                for (const auto& [pair, found] : testing::contacts_by_pair(between_frames_reference(frames[f], frames[f + 1], fine))) {
                    if (!found.resolved) continue;  // not proven within 1e-12: no claim
                    EXPECT_TRUE(fast.count(pair)) << what << ": missed " << pair.obj_a << ":" << pair.tri_a << " " << pair.obj_b << ":" << pair.tri_b;
                }
                for (const auto& [pair, found] : fast) {
                    const auto it = slow.find(pair);
                    ASSERT_TRUE(it != slow.end()) << what << ": not in the reference " << pair.obj_a << ":" << pair.tri_a << " " << pair.obj_b << ":" << pair.tri_b;
                    EXPECT_EQ(found.pass_through, it->second.pass_through) << what;
                    pass_throughs += found.pass_through;
                }
                contacts += fast.size();
                left_out += slow.size() - fast.size();
            }
        }
    }
    std::printf("%zu contacts, %zu pass-throughs over the grid soups' intervals; %zu reference pairs within the tolerance left out\n",
                contacts, pass_throughs, left_out);
    EXPECT_GT(pass_throughs, 0u);
}

}  // namespace
}  // namespace collidescope

namespace collidescope {
namespace {

TEST(BetweenFramesErrors, ObjectsAreNamedWhereTheIndexIsKnown) {
    const std::vector<std::string> names = {"hand", "hip"};
    EXPECT_EQ(with_object_names("frames 3 and 4: object 1 changes its mesh", names),
              "frames 3 and 4: object 1 ('hip') changes its mesh");
    EXPECT_EQ(with_object_names("object 0, object 1", names), "object 0 ('hand'), object 1 ('hip')");
    EXPECT_EQ(with_object_names("object 7 and object x and object", names), "object 7 and object x and object");
    EXPECT_EQ(with_object_names("object 12345678901234567890", names), "object 12345678901234567890");
    EXPECT_EQ(with_object_names("", names), "");
}

}  // namespace
}  // namespace collidescope

