// The primitive queries of between-frames detection, fast (inclusion.hpp) and reference
// (interval_reference.hpp), on handcrafted motions with known answers (degenerate ones:
// vertex moving in the face's plane, parallel and collinear edges, no motion, contact exactly
// at t = 0 or t = 1, coordinates far from the origin), then the fast one against the reference
// on random queries biased toward contact and near misses (seeds printed).

#include "ccd/inclusion.hpp"
#include "ccd/interval_reference.hpp"
#include "support/sweep_size.hpp"

#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

namespace collidescope::ccd {
namespace {

constexpr double k_delta = 1e-6;

Path still(const Vec3& p) { return {p, p}; }
Path moving(const Vec3& from, const Vec3& to) { return {from, to}; }
Path shifted(const Path& p, const Vec3& offset) { return {p[0] + offset, p[1] + offset}; }

struct Answer {
    bool fast_hit, reference_hit;
    double fast_toi, reference_toi;
};

Answer vf(const Path& p, const Path& a, const Path& b, const Path& c, double delta = k_delta) {
    const QueryResult fast = vertex_face(p, a, b, c, {delta, 1, 200000});
    const QueryResult slow = reference::vertex_face(p, a, b, c, {delta, 1, 2000000});
    return {fast.hit, slow.hit, fast.toi, slow.toi};
}

Answer ee(const Path& p0, const Path& p1, const Path& q0, const Path& q1, double delta = k_delta) {
    const QueryResult fast = edge_edge(p0, p1, q0, q1, {delta, 1, 200000});
    const QueryResult slow = reference::edge_edge(p0, p1, q0, q1, {delta, 1, 2000000});
    return {fast.hit, slow.hit, fast.toi, slow.toi};
}

// The unit face in z = 0 and offsets that move the whole query far from the origin.
const Path k_a = still({0, 0, 0}), k_b = still({1, 0, 0}), k_c = still({0, 1, 0});
const std::array<Vec3, 3> k_offsets{Vec3(0, 0, 0), Vec3(1e6, -2e6, 3e6), Vec3(-1e8, 1e8, 5e7)};

TEST(Inclusion, VertexThroughAFaceAtAKnownTime) {
    for (const Vec3& o : k_offsets) {
        const double delta = k_delta * (1 + o.cwiseAbs().maxCoeff() * 1e-6);  // what rounding allows far out
        // Through the face at t = 3/8, apart at both ends.
        const Answer r = vf(shifted(moving({0.25, 0.25, 3}, {0.25, 0.25, -5}), o), shifted(k_a, o), shifted(k_b, o),
                            shifted(k_c, o), delta);
        EXPECT_TRUE(r.fast_hit && r.reference_hit) << "offset " << o.transpose();
        EXPECT_LE(r.fast_toi, 0.375);
        EXPECT_GE(r.fast_toi, 0.375 - 1e-3);
        EXPECT_LE(r.reference_toi, 0.375);
        // Beside the face (x + y > 1): a miss.
        const Answer miss = vf(shifted(moving({0.7, 0.7, 3}, {0.7, 0.7, -5}), o), shifted(k_a, o), shifted(k_b, o),
                               shifted(k_c, o), delta);
        EXPECT_FALSE(miss.fast_hit || miss.reference_hit) << "offset " << o.transpose();
    }
}

TEST(Inclusion, DegenerateVertexFaceMotions) {
    // In the face's plane, across the face: a contact from when it enters (x = 0 at t = 1/4).
    Answer r = vf(moving({-1, 0.2, 0}, {3, 0.2, 0}), k_a, k_b, k_c);
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
    EXPECT_LE(r.fast_toi, 0.25);
    EXPECT_GE(r.fast_toi, 0.25 - 1e-3);
    // In the plane, passing beside the face: a miss.
    r = vf(moving({-1, 1.5, 0}, {3, 1.5, 0}), k_a, k_b, k_c);
    EXPECT_FALSE(r.fast_hit || r.reference_hit);
    // No motion at all: on the face (toi 0), and off it.
    r = vf(still({0.3, 0.3, 0}), k_a, k_b, k_c);
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
    EXPECT_EQ(r.fast_toi, 0);
    r = vf(still({0.3, 0.3, 0.5}), k_a, k_b, k_c);
    EXPECT_FALSE(r.fast_hit || r.reference_hit);
    // Reaching the face exactly at t = 1, and leaving it exactly at t = 0.
    r = vf(moving({0.2, 0.2, 1}, {0.2, 0.2, 0}), k_a, k_b, k_c);
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
    EXPECT_GE(r.fast_toi, 1 - 1e-3);
    r = vf(moving({0.2, 0.2, 0}, {0.2, 0.2, 1}), k_a, k_b, k_c);
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
    EXPECT_EQ(r.fast_toi, 0);
    // Exactly onto a corner and onto an edge of the face.
    EXPECT_TRUE(vf(moving({1, 0, 1}, {1, 0, -1}), k_a, k_b, k_c).fast_hit);
    EXPECT_TRUE(vf(moving({0.5, 0.5, 1}, {0.5, 0.5, -1}), k_a, k_b, k_c).fast_hit);
    // The face moves onto a still vertex, turning about its edge (the plane rotates).
    const Path b = moving({1, 0, 0}, {1, 0, 0}), c = moving({0, 1, -1}, {0, 1, 1});
    EXPECT_TRUE(vf(still({0.2, 0.2, 0}), still({0, 0, 0}), b, c).fast_hit);
    // A degenerate face (a segment) that a vertex passes through.
    r = vf(moving({0.5, 1, 0}, {0.5, -1, 0}), k_a, k_b, still({0.5, 0, 0}));
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
}

TEST(Inclusion, DegenerateEdgeEdgeMotions) {
    // Crossing edges meeting at t = 1/2.
    Answer r = ee(moving({-1, 0, 1}, {-1, 0, -1}), moving({1, 0, 1}, {1, 0, -1}), still({0, -1, 0}), still({0, 1, 0}));
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
    EXPECT_LE(r.fast_toi, 0.5);
    EXPECT_GE(r.fast_toi, 0.5 - 1e-3);
    // Parallel edges passing each other at a gap: a miss; collinear, sliding into overlap: a hit.
    r = ee(moving({0, 0, 0}, {5, 0, 0}), moving({1, 0, 0}, {6, 0, 0}), still({2, 0.1, 0}), still({3, 0.1, 0}));
    EXPECT_FALSE(r.fast_hit || r.reference_hit);
    r = ee(moving({-3, 0, 0}, {1, 0, 0}), moving({-2, 0, 0}, {2, 0, 0}), still({0, 0, 0}), still({1, 0, 0}));
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
    EXPECT_LE(r.fast_toi, 0.5);
    // Parallel, one above the other, dropping onto it exactly at t = 1.
    r = ee(moving({0, 0, 1}, {0, 0, 0}), moving({1, 0, 1}, {1, 0, 0}), still({0.5, 0, 0}), still({2, 0, 0}));
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
    // Edges that would cross on their lines but not within the segments.
    r = ee(moving({2, 0, 1}, {2, 0, -1}), moving({3, 0, 1}, {3, 0, -1}), still({0, -1, 0}), still({0, 1, 0}));
    EXPECT_FALSE(r.fast_hit || r.reference_hit);
    // A zero-length edge (a point) moving through a still edge.
    r = ee(moving({0, 0, 1}, {0, 0, -1}), moving({0, 0, 1}, {0, 0, -1}), still({-1, 0, 0}), still({1, 0, 0}));
    EXPECT_TRUE(r.fast_hit && r.reference_hit);
    for (const Vec3& o : k_offsets) {
        const double delta = k_delta * (1 + o.cwiseAbs().maxCoeff() * 1e-6);
        r = ee(shifted(moving({-1, 0, 1}, {-1, 0, -1}), o), shifted(moving({1, 0, 1}, {1, 0, -1}), o),
               shifted(still({0, -1, 0}), o), shifted(still({0, 1, 0}), o), delta);
        EXPECT_TRUE(r.fast_hit && r.reference_hit) << "offset " << o.transpose();
    }
}

// The fast answer's promise at its toi, checked by the reference at that instant: some point
// of the features' domain has every coordinate of F within the tolerance (the reference looks
// for one within 1.01 delta, and accepts an interval within 1.05 delta). Unresolved: the
// reference ran out of boxes (a sliver face makes its even halving slow), no answer.
QueryResult within_at(bool vertex_face_query, const std::array<Path, 4>& x, double toi, double delta) {
    const QueryConfig at{delta * 1.05, toi, 200000};
    const reference::Times instant{toi, delta * 1.01};
    const QueryResult r = vertex_face_query ? reference::vertex_face(x[0], x[1], x[2], x[3], at, instant)
                                            : reference::edge_edge(x[0], x[1], x[2], x[3], at, instant);
    return r;
}

// No false negative: where the reference (certain exclusions, a far finer tolerance) finds the
// features within 1e-9, the fast query reports contact no later; and a hit is within the
// tolerance at its toi. Returns false when the reference could not confirm a hit (its budget).
bool agrees_with_reference(bool vertex_face_query, const std::array<Path, 4>& x, const QueryResult& fast,
                           const QueryResult& slow, double delta, const std::string& what) {
    if (slow.hit && slow.resolved) {
        EXPECT_TRUE(fast.hit) << what;
        if (fast.hit) {
            EXPECT_LE(fast.toi, slow.toi + 1e-6) << what;
        }
    }
    if (!fast.hit) return true;
    EXPECT_TRUE(fast.resolved) << what;
    const QueryResult check = within_at(vertex_face_query, x, fast.toi, delta);
    EXPECT_TRUE(check.hit) << what << " toi " << fast.toi;
    return check.resolved;
}

Vec3 random_point(std::mt19937_64& rng, double scale) {
    std::uniform_real_distribution<double> u(-scale, scale);
    return {u(rng), u(rng), u(rng)};
}

// Random queries built around a contact: at a random time, the vertex (or the first edge's
// point) is put on the face (or the second edge's point) plus an offset of 0 (touching, up to
// rounding), a small one (a near miss or a graze) or a large one. Features of size `scale`
// around `center` (small features far from the origin: the cubic's rounding bound is one of
// the features' differences, not of the coordinates), the tolerance and offsets in proportion.
void random_queries_agree(std::uint64_t seed, double scale, const Vec3& center) {
    std::printf("[ seed     ] Inclusion random queries: seed %llu, scale %g\n", static_cast<unsigned long long>(seed), scale);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const double delta = k_delta * scale;
    int hits = 0, misses = 0, unchecked = 0;
    for (int q = 0; q < 120; ++q) {
        const bool vertex_face_query = q % 2 == 0;
        std::array<Path, 4> x;
        for (Path& p : x) p = {center + random_point(rng, scale), center + random_point(rng, scale)};
        if (q % 7 == 3) x[2][1] = x[2][0];  // still features now and then
        if (q % 11 == 5) x[1] = {x[3][0] + Vec3(1e-3 * scale, 0, 0), x[3][1] + Vec3(1e-3 * scale, 0, 0)};  // near-degenerate
        const double t = unit(rng), u = unit(rng), v = unit(rng) * (vertex_face_query ? 1 - u : 1);
        const auto at = [&](const Path& p) -> Vec3 { return p[0] + t * (p[1] - p[0]); };
        Vec3 target = at(x[2]) + v * (at(x[3]) - at(x[2])) - u * (at(x[1]) - at(x[0]));
        if (vertex_face_query) target = at(x[1]) + u * (at(x[2]) - at(x[1])) + v * (at(x[3]) - at(x[1]));
        const double offsets[] = {0, 1e-4, 1e-2, 0.3};
        const Vec3 offset = random_point(rng, 1).normalized() * offsets[q % 4] * scale;
        // Move x[0]'s end so that it passes through target + offset at time t.
        x[0][1] = x[0][0] + (target + offset - x[0][0]) / std::max(t, 1e-3);
        const QueryConfig config{delta, 1, 200000};
        const QueryResult fast = vertex_face_query ? vertex_face(x[0], x[1], x[2], x[3], config)
                                                   : edge_edge(x[0], x[1], x[2], x[3], config);
        // No false negative: where the reference (certain exclusions, a far finer tolerance)
        // finds the features within 1e-9 of the scale, the fast query reports contact no later.
        const QueryConfig fine{1e-9 * scale, 1, 100000};
        const QueryResult slow = vertex_face_query ? reference::vertex_face(x[0], x[1], x[2], x[3], fine)
                                                   : reference::edge_edge(x[0], x[1], x[2], x[3], fine);
        const std::string what = "seed " + std::to_string(seed) + " scale " + std::to_string(scale) + " query " + std::to_string(q);
        unchecked += !agrees_with_reference(vertex_face_query, x, fast, slow, delta, what);
        (fast.hit ? hits : misses) += 1;
    }
    // Both answers occur often (the generator is what it says).
    EXPECT_GT(hits, 25) << "seed " << seed;
    EXPECT_GT(misses, 25) << "seed " << seed;
    EXPECT_LE(unchecked, 6) << "seed " << seed;
}

TEST(Inclusion, FastAgreesWithTheReferenceOnRandomQueries) {
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({1, 2, 3}, 3)) random_queries_agree(seed, 1, Vec3::Zero());
    // Features of 0.01 near coordinates of 1.
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({4, 5}, 2)) random_queries_agree(seed, 0.01, Vec3(0.7, -0.4, 0.9));
}

// The signed volume det(p - a, b - a, c - a) at time t, exactly: the positions interpolated
// in rationals from the doubles at both ends.
int exact_volume_sign(const Path& p, const Path& a, const Path& b, const Path& c, const mpq_class& t) {
    const auto at = [&](const Path& x, int k) -> mpq_class { return mpq_class(x[0][k]) + t * (mpq_class(x[1][k]) - mpq_class(x[0][k])); };
    mpq_class m[3][3];
    for (int k = 0; k < 3; ++k) {
        const mpq_class origin = at(a, k);
        m[0][k] = at(p, k) - origin;
        m[1][k] = at(b, k) - origin;
        m[2][k] = at(c, k) - origin;
    }
    const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sgn(det);
}

// MovingPlane::side, the pair filter of between-frames detection, never claims a side the
// point leaves: wherever it answers 1 or -1, the exact signed volume has that sign at every
// sampled time (65 rational times, both ends included), on random motions, motions that cross
// the plane or end on it, points that move in it, still and degenerate faces, and coordinates
// far from the origin (where the rounding bound, which grows with the coordinates' magnitude,
// leaves it mostly undecided). Near the origin it also answers often (the filter does its work).
TEST(Inclusion, MovingPlaneSideHoldsAtEverySampledTime) {
    for (const std::uint64_t seed : {21u, 22u, 23u}) {
        std::printf("[ seed     ] MovingPlane random motions: seed %llu\n", static_cast<unsigned long long>(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0, 1);
        int sided = 0, undecided = 0;
        for (int q = 0; q < 200; ++q) {
            std::array<Path, 4> x;  // p, a, b, c: moving by up to a tenth of their spread
            for (Path& path : x) {
                const Vec3 start = random_point(rng, 1);
                path = {start, start + random_point(rng, 0.1)};
            }
            if (q % 5 == 1) x[0][1] = x[1][1] + unit(rng) * (x[2][1] - x[1][1]);                    // ends on the face's plane
            if (q % 5 == 2) x[0] = {x[1][0] + 0.3 * (x[2][0] - x[1][0]), x[1][1] + 0.6 * (x[3][1] - x[1][1])};  // in it at both ends
            if (q % 7 == 3) x[3] = {x[1][0] + 2.0 * (x[2][0] - x[1][0]), x[1][1] + 2.0 * (x[2][1] - x[1][1])};  // a face on a line
            if (q % 11 == 4) x[0][1] = x[0][0];  // a still point
            const Vec3 offset = k_offsets[q % k_offsets.size()];
            for (Path& path : x) path = shifted(path, offset);
            double largest = 0;
            for (const Path& path : x) largest = std::max({largest, path[0].cwiseAbs().maxCoeff(), path[1].cwiseAbs().maxCoeff()});
            const int side = MovingPlane(x[1], x[2], x[3], largest).side(x[0]);
            if (q % k_offsets.size() == 0) (side != 0 ? sided : undecided) += 1;  // near the origin
            if (side == 0) continue;
            for (int k = 0; k <= 64; ++k) {
                const mpq_class time(k, 64);
                EXPECT_EQ(exact_volume_sign(x[0], x[1], x[2], x[3], time), side)
                    << "seed " << seed << " motion " << q << " time " << k << "/64";
            }
        }
        EXPECT_GT(sided, 20) << "seed " << seed;
        EXPECT_GT(undecided, 10) << "seed " << seed;
    }
}

// ---- The planar query (vertex_face_in_plane) --------------------------------------------

// Whether p lies in the closed triangle (a, b, c) at time t, all four in the plane that drops
// axis `drop`, decided exactly: positions interpolated in rationals, the three orientations
// of the projection; a flat triangle holds p when p is on its line within its extent.
bool exactly_inside(const Path& p, const Path& a, const Path& b, const Path& c, int drop, const mpq_class& t) {
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const auto at = [&](const Path& x, int k) -> mpq_class { return mpq_class(x[0][k]) + t * (mpq_class(x[1][k]) - mpq_class(x[0][k])); };
    const auto orient = [&](const Path& from, const Path& to) {
        return sgn((at(to, i) - at(from, i)) * (at(p, j) - at(from, j)) - (at(to, j) - at(from, j)) * (at(p, i) - at(from, i)));
    };
    const int o[3] = {orient(a, b), orient(b, c), orient(c, a)};
    const int area = sgn((at(b, i) - at(a, i)) * (at(c, j) - at(a, j)) - (at(b, j) - at(a, j)) * (at(c, i) - at(a, i)));
    if (area != 0) return o[0] * area >= 0 && o[1] * area >= 0 && o[2] * area >= 0;
    if (o[0] != 0 || o[1] != 0 || o[2] != 0) return false;
    for (const int k : {i, j}) {
        const mpq_class lo = std::min({at(a, k), at(b, k), at(c, k)}), hi = std::max({at(a, k), at(b, k), at(c, k)});
        if (at(p, k) < lo || at(p, k) > hi) return false;
    }
    return true;
}

// Where `meets(k)` (an exact test at time k/64) first holds, the query reports contact no later.
template <class Meets>
void expect_no_later_than_first_sample(const QueryResult& fast, Meets meets, const std::string& what) {
    for (int k = 0; k <= 64; ++k) {
        if (!meets(k)) continue;
        EXPECT_TRUE(fast.hit) << what << " meeting at " << k << "/64";
        EXPECT_LE(fast.toi, k / 64.0) << what;
        return;
    }
}

void expect_counts(std::uint64_t seed, int hits, int misses, int unchecked) {
    std::printf("[ counts   ] %d hits, %d misses, %d hits the reference could not confirm\n", hits, misses, unchecked);
    EXPECT_GT(hits, 25) << "seed " << seed;
    EXPECT_GT(misses, 15) << "seed " << seed;
    EXPECT_LE(unchecked, 10) << "seed " << seed;
}

// Planes in which dyadic coordinates stay exact: z = 0.375, x = -1.25, and the tilted plane
// x + 2y + 4z = 1.5 (its normal has no zero component: any axis can be dropped). (s, r) on a
// grid of 2^-20 within [-4, 4] lands exactly on each.
Vec3 on_plane(int plane, double s, double r) {
    s = std::round(s * 0x1p20) * 0x1p-20;
    r = std::round(r * 0x1p20) * 0x1p-20;
    if (plane == 0) return {s, r, 0.375};
    if (plane == 1) return {-1.25, s, r};
    return {s, r, (1.5 - s - 2 * r) / 4};
}

TEST(Inclusion, PlanarVertexFaceHandcrafted) {
    const QueryConfig config{k_delta, 1, 200000};
    // In the plane z = 0, across the unit face: contact from x = 0 at t = 1/4.
    QueryResult r = vertex_face_in_plane(moving({-1, 0.2, 0}, {3, 0.2, 0}), k_a, k_b, k_c, 2, config);
    EXPECT_TRUE(r.hit);
    EXPECT_LE(r.toi, 0.25);
    EXPECT_GE(r.toi, 0.25 - 1e-3);
    // Beside it: a miss. Still and on it: toi 0.
    EXPECT_FALSE(vertex_face_in_plane(moving({-1, 1.5, 0}, {3, 1.5, 0}), k_a, k_b, k_c, 2, config).hit);
    r = vertex_face_in_plane(still({0.3, 0.3, 0}), k_a, k_b, k_c, 2, config);
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.toi, 0);
    // A face that flattens onto the x axis at t = 1/2 and turns over (c from (0, 1) to
    // (0, -1)): a point on the axis beyond the face's extent is never inside; one on edge ab is
    // inside throughout (toi 0); (0.25, -0.25) is inside once c.y <= -1/3, from t = 2/3.
    const Path folding = moving({0, 1, 0}, {0, -1, 0});
    EXPECT_FALSE(vertex_face_in_plane(still({2, 0, 0}), k_a, k_b, folding, 2, config).hit);
    r = vertex_face_in_plane(still({0.5, 0, 0}), k_a, k_b, folding, 2, config);
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.toi, 0);
    r = vertex_face_in_plane(still({0.25, -0.25, 0}), k_a, k_b, folding, 2, config);
    EXPECT_TRUE(r.hit);
    EXPECT_LE(r.toi, 2.0 / 3);
    EXPECT_GE(r.toi, 2.0 / 3 - 1e-3);
    // Reaching the face exactly at t = 1 in the tilted plane (each axis dropped in turn).
    const Path a = still(on_plane(2, 0, 0)), b = still(on_plane(2, 1, 0)), c = still(on_plane(2, 0, 1));
    const Path p = moving(on_plane(2, -1, 0.5), on_plane(2, 0, 0.5));
    for (int drop = 0; drop < 3; ++drop) {
        r = vertex_face_in_plane(p, a, b, c, drop, config);
        EXPECT_TRUE(r.hit) << "drop " << drop;
        EXPECT_GE(r.toi, 1 - 1e-3) << "drop " << drop;
    }
}

// Far from the origin the planar query's bound stays that of the features' size: the unit face
// 2^18 to 2^24 from the origin, a vertex entering it at t = 1/4, is resolved in a few boxes (a
// review found the bound, then made of the coordinates, swamping the orientations there).
TEST(Inclusion, PlanarVertexFaceFarFromTheOrigin) {
    for (const double offset : {0x1p18, 0x1p20, 0x1p24}) {
        const Vec3 o(offset, offset, 0);
        const QueryResult r = vertex_face_in_plane(shifted(moving({-1, 0.25, 0}, {3, 0.25, 0}), o), shifted(k_a, o),
                                                   shifted(k_b, o), shifted(k_c, o), 2, {1e-5, 1, 50000});
        EXPECT_TRUE(r.hit && r.resolved) << "offset " << offset;
        EXPECT_LE(r.toi, 0.25) << "offset " << offset;
        EXPECT_GE(r.toi, 0.25 - 1e-3) << "offset " << offset;
        EXPECT_LT(r.boxes, 1000u) << "offset " << offset;
    }
}

// Random motions in the three planes, biased toward contact, near misses, flat faces, still
// features and coordinates far out (seeds printed): wherever the exact test finds the vertex
// in the face at one of 65 sampled times, the planar query reports contact no later; where the
// reference finds contact, no later than it; and a hit is within the tolerance at its toi.
TEST(Inclusion, PlanarVertexFaceAgreesWithExactAndReferenceAnswers) {
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({31, 32, 33}, 3)) {
        std::printf("[ seed     ] Inclusion planar queries: seed %llu\n", static_cast<unsigned long long>(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0, 1), coordinate(-1, 1);
        int hits = 0, misses = 0, unchecked = 0;
        for (int q = 0; q < 120; ++q) {
            const int plane = q % 3;
            const int drop = plane == 0 ? 2 : plane == 1 ? 0 : static_cast<int>(q / 3 % 3);
            const double far = q % 5 == 4 ? 1024 : 0;  // a dyadic offset: still exact
            std::array<std::array<double, 2>, 4> s0, s1;  // p, a, b, c in plane coordinates
            for (int k = 0; k < 4; ++k) {  // a face of about 0.4 and a vertex within 1 of it
                const double spread = k == 0 ? 1.0 : 0.4, step = k == 0 ? 1.0 : 0.2;
                s0[k] = {far + spread * coordinate(rng), spread * coordinate(rng)};
                s1[k] = {s0[k][0] + step * coordinate(rng), s0[k][1] + step * coordinate(rng)};
            }
            if (q % 7 == 3) s1[2] = s0[2];  // a still corner
            if (q % 4 == 1) s1[3] = {2 * s1[2][0] - s1[1][0], 2 * s1[2][1] - s1[1][1]};  // a face flat at t = 1
            // The vertex passes through a point of the face (plus an offset) at time t.
            const double t = std::max(unit(rng), 1e-3), u = unit(rng), v = unit(rng) * (1 - u);
            const auto at = [&](int k, int axis) { return s0[k][axis] + t * (s1[k][axis] - s0[k][axis]); };
            const double offsets[] = {0, 1e-5, 1e-2, 0.8};
            const double angle = 6.283185307179586 * unit(rng), size = offsets[q % 4];
            for (int axis = 0; axis < 2; ++axis) {
                const double target = at(1, axis) + u * (at(2, axis) - at(1, axis)) + v * (at(3, axis) - at(1, axis)) +
                                      size * (axis == 0 ? std::cos(angle) : std::sin(angle));
                s1[0][axis] = s0[0][axis] + (target - s0[0][axis]) / t;
            }
            std::array<Path, 4> x;
            for (int k = 0; k < 4; ++k) x[k] = {on_plane(plane, s0[k][0], s0[k][1]), on_plane(plane, s1[k][0], s1[k][1])};
            const std::string what = "seed " + std::to_string(seed) + " query " + std::to_string(q);
            const double delta = k_delta * (1 + far * 1e-3);
            const QueryResult fast = vertex_face_in_plane(x[0], x[1], x[2], x[3], drop, {delta, 1, 200000});
            expect_no_later_than_first_sample(
                fast, [&](int k) { return exactly_inside(x[0], x[1], x[2], x[3], drop, mpq_class(k, 64)); }, what);
            const QueryResult slow = reference::vertex_face(x[0], x[1], x[2], x[3], {1e-9, 1, 100000});
            unchecked += !agrees_with_reference(true, x, fast, slow, delta, what);
            (fast.hit ? hits : misses) += 1;
        }
        expect_counts(seed, hits, misses, unchecked);
    }
}

// ---- Edges on a flat cubic (edge_edge's line sides) --------------------------------------

// Whether the segments (p0, p1) and (q0, q1) meet at time t, all four points in the plane that
// drops axis `drop`, decided exactly: positions interpolated in rationals; two segments meet
// when each straddles (or touches) the other's line, or, all four on one line, when their
// extents overlap.
bool exactly_crossing(const Path& p0, const Path& p1, const Path& q0, const Path& q1, int drop, const mpq_class& t) {
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const auto at = [&](const Path& x, int k) -> mpq_class { return mpq_class(x[0][k]) + t * (mpq_class(x[1][k]) - mpq_class(x[0][k])); };
    const auto orient = [&](const Path& from, const Path& to, const Path& p) {
        return sgn((at(to, i) - at(from, i)) * (at(p, j) - at(from, j)) - (at(to, j) - at(from, j)) * (at(p, i) - at(from, i)));
    };
    const int a = orient(p0, p1, q0), b = orient(p0, p1, q1), c = orient(q0, q1, p0), d = orient(q0, q1, p1);
    if (a * b > 0 || c * d > 0) return false;
    if (a != 0 || b != 0 || c != 0 || d != 0) {
        // Not all on one line. A zero-length segment straddles any line through it; it meets
        // the other segment only where it lies within it.
        return true;
    }
    for (const int k : {i, j}) {
        const mpq_class lo_p = std::min(at(p0, k), at(p1, k)), hi_p = std::max(at(p0, k), at(p1, k));
        const mpq_class lo_q = std::min(at(q0, k), at(q1, k)), hi_q = std::max(at(q0, k), at(q1, k));
        if (hi_p < lo_q || hi_q < lo_p) return false;
    }
    return true;
}

// Parallel and collinear edges in a plane and in space, the cases where the coplanarity cubic
// is flat throughout: answered, and in few boxes (the boxes alone ran out of them).
TEST(Inclusion, FlatEdgeEdgeHandcrafted) {
    const QueryConfig config{k_delta, 1, 200000};
    // Parallel, a gap of 1e-3 apart, sliding past each other: a miss.
    QueryResult r = edge_edge(moving({-3, 0, 0}, {3, 0, 0}), moving({-2, 0, 0}, {4, 0, 0}), still({0, 1e-3, 0}),
                              still({1, 1e-3, 0}), config);
    EXPECT_FALSE(r.hit);
    EXPECT_LT(r.boxes, 100u);
    // Parallel in one plane, the first passing through the second's line at t = 1/2 where they
    // overlap: contact then, not before.
    r = edge_edge(moving({0, -1, 0}, {0.5, 1, 0}), moving({1, -1, 0}, {1.5, 1, 0}), still({0.5, 0, 0}), still({2, 0, 0}),
                  config);
    EXPECT_TRUE(r.hit && r.resolved);
    EXPECT_LE(r.toi, 0.5);
    EXPECT_GE(r.toi, 0.5 - 1e-5);
    EXPECT_LT(r.boxes, 1000u);
    // The same line crossing where they do not overlap (the first edge has slid past): a miss.
    r = edge_edge(moving({3, -1, 0}, {3.5, 1, 0}), moving({4, -1, 0}, {4.5, 1, 0}), still({0.5, 0, 0}), still({2, 0, 0}),
                  config);
    EXPECT_FALSE(r.hit);
    // Parallel in space, not in one plane: passing over the other at a gap of 1e-3, then
    // through it.
    r = edge_edge(moving({0, 1e-3, -1}, {0, 1e-3, 1}), moving({1, 1e-3, -1}, {1, 1e-3, 1}), still({0.5, 0, 0}),
                  still({2, 0, 0}), config);
    EXPECT_FALSE(r.hit);
    EXPECT_LT(r.boxes, 1000u);
    r = edge_edge(moving({0, 0, -1}, {0, 0, 1}), moving({1, 0, -1}, {1, 0, 1}), still({0.5, 0, 0}), still({2, 0, 0}), config);
    EXPECT_TRUE(r.hit && r.resolved);
    EXPECT_LE(r.toi, 0.5);
    EXPECT_GE(r.toi, 0.5 - 1e-5);
    // Two rings' edges of contact-rods (one horizontal plane, parallel to within 2e-7 radians,
    // passing through each other's line while overlapping): before, 4,096 boxes and
    // unresolved.
    const auto hex = [](const char* x, const char* y, const char* z) { return Vec3(std::strtod(x, nullptr), std::strtod(y, nullptr), std::strtod(z, nullptr)); };
    const Path p0 = moving(hex("0x1.673e9ap-5", "-0x1.27a41cp-5", "0x1.1e6508p+1"), hex("0x1.22dcfep-4", "-0x1.6d3912p-6", "0x1.1e6508p+1"));
    const Path p1 = moving(hex("0x1.ae0f1ap-5", "-0x1.4d7dfep-5", "0x1.1e6508p+1"), hex("0x1.46453ep-4", "-0x1.b8ecd6p-6", "0x1.1e6508p+1"));
    const Path q0 = moving(hex("0x1.117318p-4", "-0x1.8a2198p-5", "0x1.1e6508p+1"), hex("0x1.fc27p-5", "-0x1.273872p-6", "0x1.1e6508p+1"));
    const Path q1 = moving(hex("0x1.dc15b2p-5", "-0x1.6447b6p-5", "0x1.1e6508p+1"), hex("0x1.b55682p-5", "-0x1.b7095cp-7", "0x1.1e6508p+1"));
    r = edge_edge(p0, p1, q0, q1, {3e-6, 1, 50000});
    EXPECT_TRUE(r.hit && r.resolved);
    EXPECT_LT(r.boxes, 1000u);
    // The reference's even halving runs out of boxes here. Exactly: the edges meet within 2^-12
    // after the toi (the lines cross inside both segments for only a few millionths of the interval,
    // found on a grid of 2^-26), and at none of the times k/64 before it.
    const mpq_class toi(r.toi);
    bool met = false;
    for (int k = 0; k <= 1 << 14 && !met; ++k) met = exactly_crossing(p0, p1, q0, q1, 2, toi + mpq_class(k, 1 << 26));
    EXPECT_TRUE(met);
    for (int k = 0; k < 64 && k / 64.0 < r.toi; ++k) EXPECT_FALSE(exactly_crossing(p0, p1, q0, q1, 2, mpq_class(k, 64))) << k;
}

// Random edge pairs in the three planes (seeds printed): parallel ones sliding past each other
// a gap apart or passing through each other's line, nearly parallel ones, crossing and
// near-missing ones, still and zero-length edges, coordinates far out. Wherever the exact test
// finds the segments meeting at one of 65 sampled times, the query reports contact no later;
// where the reference finds contact, no later than it; a hit is within the tolerance at its
// toi.
TEST(Inclusion, FlatEdgeEdgeAgreesWithExactAndReferenceAnswers) {
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({41, 42, 43}, 3)) {
        std::printf("[ seed     ] Inclusion flat edge pairs: seed %llu\n", static_cast<unsigned long long>(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> unit(0, 1), coordinate(-1, 1);
        int hits = 0, misses = 0, unchecked = 0;
        for (int q = 0; q < 120; ++q) {
            const int plane = q % 3;
            const int drop = plane == 0 ? 2 : plane == 1 ? 0 : static_cast<int>(q / 3 % 3);
            const double far = q % 5 == 4 ? 1024 : 0;  // a dyadic offset: still exact
            const int kind = q / 3 % 4;                // parallel, nearly parallel, crossing, a point
            // The first edge along `along`, of length 0.4; the second of length 0.3, parallel
            // (or turned by 1e-7, or by a random angle), on the side `side` of the first's line
            // at t = 0 and crossing to `-side` (or not) by t = 1, sliding along by up to 1.
            const double angle = 6.283185307179586 * unit(rng);
            const std::array<double, 2> along{std::cos(angle), std::sin(angle)}, across{-along[1], along[0]};
            const double turn = kind == 0 ? 0 : kind == 1 ? 1e-7 : 3 * coordinate(rng);
            const std::array<double, 2> other{std::cos(angle + turn), std::sin(angle + turn)};
            const double gaps[] = {0, 1e-5, 1e-2, 0.3};
            const double gap = gaps[q % 4];
            const double start = coordinate(rng), slide = coordinate(rng);
            const bool crosses = unit(rng) < 0.5;
            std::array<std::array<double, 2>, 4> s0, s1;
            for (int axis = 0; axis < 2; ++axis) {
                s0[0][axis] = far + 0.1 * along[axis] * coordinate(rng);
                s1[0][axis] = s0[0][axis] + 0.2 * coordinate(rng);
                s0[1][axis] = s0[0][axis] + (kind == 3 ? 0 : 0.4) * along[axis];
                s1[1][axis] = s1[0][axis] + (kind == 3 ? 0 : 0.4) * along[axis];
                const double offset0 = (gap + 0.05) * across[axis], offset1 = (crosses ? -1 : 1) * gap * across[axis];
                s0[2][axis] = s0[0][axis] + start * 0.5 * along[axis] + offset0;
                s1[2][axis] = s1[0][axis] + (start + slide) * 0.5 * along[axis] + offset1;
                s0[3][axis] = s0[2][axis] + 0.3 * other[axis];
                s1[3][axis] = s1[2][axis] + 0.3 * other[axis];
            }
            if (q % 7 == 3) s1[2] = s0[2], s1[3] = s0[3];  // a still edge
            std::array<Path, 4> x;
            for (int k = 0; k < 4; ++k) x[k] = {on_plane(plane, s0[k][0], s0[k][1]), on_plane(plane, s1[k][0], s1[k][1])};
            const std::string what = "seed " + std::to_string(seed) + " query " + std::to_string(q);
            const double delta = k_delta * (1 + far * 1e-3);
            const QueryResult fast = edge_edge(x[0], x[1], x[2], x[3], {delta, 1, 200000});
            expect_no_later_than_first_sample(
                fast, [&](int k) { return exactly_crossing(x[0], x[1], x[2], x[3], drop, mpq_class(k, 64)); }, what);
            const QueryResult slow = reference::edge_edge(x[0], x[1], x[2], x[3], {1e-9, 1, 100000});
            unchecked += !agrees_with_reference(false, x, fast, slow, delta, what);
            (fast.hit ? hits : misses) += 1;
        }
        expect_counts(seed, hits, misses, unchecked);
    }
}

}  // namespace
}  // namespace collidescope::ccd
