// One triangle pair over an interval: its filters (the planes' cubics, fixed directions) never
// part a pair that touches, at any scale the engine accepts and beyond: random pairs that the
// exact per-frame test finds intersecting, held still, are each reported (seeds printed). A
// review found the fixed directions' dot products overflowing at coordinates of 1e77 and their
// bound underflowing at 1e-161, each parting pairs that intersect. Pairs ahead on one axis at
// both ends are parted first, and one that changes sides is not; so are pairs whose boxes
// never meet during the interval (the overlap window), and a contact at the one instant they
// meet is not.

#include "ccd/pair_motion.hpp"
#include "support/sweep_size.hpp"

#include "collidescope/geometry.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <tuple>
#include <utility>

namespace collidescope::ccd {
namespace {

// A triangle's lowest and highest coordinate along axis k at one end.
std::pair<double, double> axis_range(const std::array<Path, 3>& t, int end, int k) {
    const auto [lo, hi] = std::minmax({t[0][end][k], t[1][end][k], t[2][end][k]});
    return {lo, hi};
}

// The slow obvious case of an empty overlap window: along some axis, the same triangle lies
// strictly below the other at both ends (comparisons of the coordinates, exact).
bool apart_on_an_axis(const PairMotion& m) {
    for (int k = 0; k < 3; ++k) {
        bool a_below = true, b_below = true;
        for (int end = 0; end < 2; ++end) {
            const auto [a_lo, a_hi] = axis_range(m.a, end, k);
            const auto [b_lo, b_hi] = axis_range(m.b, end, k);
            a_below = a_below && a_hi < b_lo;
            b_below = b_below && b_hi < a_lo;
        }
        if (a_below || b_below) return true;
    }
    return false;
}

// Triangles (p[0], p[1], p[2]) and (p[3], p[4], p[5]) of two objects, held still.
PairMotion still_pair(const std::array<Vec3, 6>& p) {
    PairMotion m;
    for (int i = 0; i < 3; ++i) {
        m.a[i] = {p[i], p[i]};
        m.b[i] = {p[3 + i], p[3 + i]};
    }
    m.ia = {0, 1, 2};
    m.ib = {3, 4, 5};
    return m;
}

TEST(PairMotion, AStillIntersectingPairIsReportedAtEveryScale) {
    int intersecting = 0;
    // Tiny scales take the exact predicates' slow path (2 s for 20,000 pairs): the two pairs of
    // the next test stand for them.
    for (const double scale : {1.0, 1e50, 1e77, 1e99}) {
        for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({41, 42})) {
            std::printf("[ seed     ] PairMotion still pairs: seed %llu, scale %g\n", static_cast<unsigned long long>(seed), scale);
            std::mt19937_64 rng(seed);
            std::uniform_real_distribution<double> coordinate(-1, 1);
            for (int n = 0; n < 20000; ++n) {
                std::array<Vec3, 6> p;
                for (Vec3& q : p) q = scale * Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
                if (!triangles_intersect(p[0], p[1], p[2], p[3], p[4], p[5])) continue;
                ++intersecting;
                const PairOutcome outcome = test_pair(still_pair(p), 1e-6 * scale, 10000);
                ASSERT_TRUE(outcome.contact) << "seed " << seed << " scale " << scale << " pair " << n;
                EXPECT_TRUE(outcome.start_contact) << "seed " << seed << " scale " << scale << " pair " << n;
            }
        }
    }
    std::printf("%d intersecting pairs, each reported\n", intersecting);
    EXPECT_GT(intersecting, 1000);
}

// Two intersecting pairs near 1e-162, where the fixed directions' bound, without its term for
// products that underflow, was below their rounding: each was parted.
TEST(PairMotion, TwoStillPairsWhereProductsUnderflowAreReported) {
    const std::array<std::array<Vec3, 6>, 2> pairs{{
        {Vec3(-3.5725602073723994e-164, -7.2297075642524838e-162, -8.0039992240454986e-162),
         Vec3(8.1320909323640938e-162, -2.3035169761213227e-162, -2.5177420982958113e-162),
         Vec3(7.1105093203210387e-162, -2.0739716248710306e-162, 9.2328819370030257e-162),
         Vec3(6.9272087892343251e-162, 3.3023603374585433e-163, 5.0753659174667118e-162),
         Vec3(6.1575785106737853e-162, -3.5444592616562201e-162, -3.8703519851751192e-162),
         Vec3(1.0356541396743601e-162, -5.1583806535622977e-162, -3.2373814141904233e-162)},
        {Vec3(-5.1521965631847987e-163, -9.1457538973655784e-163, 7.5695406409447363e-163),
         Vec3(8.9226185535288224e-163, -9.248450682976333e-163, 8.1668205086867642e-163),
         Vec3(-2.0874981090402576e-163, 6.8809572589402271e-163, -7.0172758150338358e-163),
         Vec3(2.7817032605689863e-163, 9.8077324197670788e-163, -6.1476972890306297e-163),
         Vec3(-8.7967165914072165e-163, -2.8026083177375424e-163, -9.1932408271993483e-163),
         Vec3(-6.8725374412601017e-163, 9.2861125112546331e-163, -6.5006265796490502e-163)},
    }};
    for (const std::array<Vec3, 6>& p : pairs) {
        ASSERT_TRUE(triangles_intersect(p[0], p[1], p[2], p[3], p[4], p[5]));
        EXPECT_TRUE(test_pair(still_pair(p), 1e-168, 10000).contact);
    }
}

// Pairs moving in one plane, where the planar query and its shortcuts decide (cases a review
// found left unresolved or reported as contacts): a triangle sliding past a face 0.125 beyond
// its hypotenuse, near the origin and 2^20 and 2^22 from it (the orientations' bound grew with
// the coordinates and swamped them there), and two flat triangles on one line drawing apart
// (every orientation zero throughout: each narrow span went to the boxes, until the budget).
TEST(PairMotion, PairsInOnePlaneResolveNearMissesFarOutAndOnALine) {
    for (const double offset : {0.0, 0x1p20, 0x1p22}) {
        const Vec3 o(offset, offset, 0), d(-2, 2, 0), s(1.0625, 0.0625, 0);  // s: x + y = 1.125
        PairMotion m;
        m.ia = {0, 1, 2};
        m.ib = {3, 4, 5};
        m.b = {Path{o, o}, Path{o + Vec3(1, 0, 0), o + Vec3(1, 0, 0)}, Path{o + Vec3(0, 1, 0), o + Vec3(0, 1, 0)}};
        m.a = {Path{o + s - d, o + s + d}, Path{o + s - d + Vec3(1, 0, 0), o + s + d + Vec3(1, 0, 0)},
               Path{o + s - d + Vec3(0, 1, 0), o + s + d + Vec3(0, 1, 0)}};
        const PairOutcome miss = test_pair(m, 1e-5, 50000);
        EXPECT_FALSE(miss.contact) << "offset " << offset << ": toi " << miss.toi << ", boxes " << miss.boxes;
        // The same triangle 0.25 lower: its tip crosses the hypotenuse (x + y = 0.875 < 1).
        for (Path& path : m.a) path = {path[0] - Vec3(0, 0.25, 0), path[1] - Vec3(0, 0.25, 0)};
        const PairOutcome hit = test_pair(m, 1e-5, 50000);
        EXPECT_TRUE(hit.contact && hit.resolved) << "offset " << offset << ": boxes " << hit.boxes;
    }
    const auto on_axis = [](double from, double to) { return Path{Vec3(from, 0, 0), Vec3(to, 0, 0)}; };
    PairMotion line;
    line.ia = {0, 1, 2};
    line.ib = {3, 4, 5};
    line.a = {on_axis(0, 1.5), on_axis(1, 2.5), on_axis(0.5, 2)};
    line.b = {on_axis(2, 3.75), on_axis(3, 4.75), on_axis(2.5, 4.25)};
    const PairOutcome apart = test_pair(line, 1e-6, 50000);
    EXPECT_FALSE(apart.contact) << "toi " << apart.toi << ", boxes " << apart.boxes;
    // Drawing together instead: they meet when the gap of 1 closes, at t = 1/2.
    line.b = {on_axis(2, 1), on_axis(3, 2), on_axis(2.5, 1.5)};
    line.a = {on_axis(0, 1), on_axis(1, 2), on_axis(0.5, 1.5)};
    const PairOutcome meet = test_pair(line, 1e-6, 50000);
    EXPECT_TRUE(meet.contact && meet.resolved) << "boxes " << meet.boxes;
    EXPECT_LE(meet.toi, 0.5);
    EXPECT_GE(meet.toi, 0.5 - 1e-3);
}

// A pair that comes within δ = 0.05 without touching (a random search's find, seed 7): the
// boxes accept it near t = 0.9, and the pair's fixed directions at t = 1, asked of a pair
// reported without touching at either end, part it (the centroids' line or an edge normal at
// t = 0 does not). Checked here never to touch at 4,097 sampled times.
TEST(PairMotion, AGrazingPairThatTheDirectionsAtTheEndPartIsNotReported) {
    PairMotion m;
    m.ia = {0, 1, 2};
    m.ib = {3, 4, 5};
    m.a = {Path{Vec3(0.63860273031406423, 0.9486938053009315, 0.092971198119813803), Vec3(0.51827453552387648, 0.73686483994477536, 0.37152769728951668)},
           Path{Vec3(-0.52901843549572081, -0.6224750712947198, -0.46184699995397782), Vec3(-0.52898387138043634, -0.72420613957998925, -0.59948343598290588)},
           Path{Vec3(0.13076229280132479, 0.33327826614093969, 0.33409689736014658), Vec3(0.15624228791540984, 0.16072683053303916, 0.14285605328632733)}};
    m.b = {Path{Vec3(0.62099422964056616, -0.71988316365916283, 0.9269324799820442), Vec3(0.63406066541710437, -0.574598039716398, 1.177184753189652)},
           Path{Vec3(0.51002920666620066, 0.43349478276956055, 0.4280756609191414), Vec3(0.38876390723866622, 0.4527889928957568, 0.31192160323931645)},
           Path{Vec3(-0.66438889224079878, -0.83896382308524153, -0.32924442280809774), Vec3(-0.71738518526075423, -0.86189616541054037, -0.38406713220707278)}};
    constexpr int k_samples = 4096;
    for (int k = 0; k <= k_samples; ++k) {
        const double t = static_cast<double>(k) / k_samples;
        const auto at = [t](const Path& p) -> Vec3 { return p[0] + t * (p[1] - p[0]); };
        ASSERT_FALSE(triangles_intersect(at(m.a[0]), at(m.a[1]), at(m.a[2]), at(m.b[0]), at(m.b[1]), at(m.b[2]))) << "t " << t;
    }
    const PairOutcome outcome = test_pair(m, 0.05, 10000);
    EXPECT_FALSE(outcome.contact) << "toi " << outcome.toi;
    EXPECT_GT(outcome.queries, 0u);  // the queries ran (and accepted it within δ)
}

// Two triangles flying side by side in one direction, the same one ahead along x at both ends:
// their swept boxes overlap (each sweeps through the other's), yet they never meet, and the
// first filter parts them before any query runs. Then random motions, some passing each other:
// wherever the filter says apart, the obvious check agrees (at 257 times across the interval,
// one axis with the triangles' ranges apart at every one of them). Seeds printed.
TEST(PairMotion, APairAheadOnOneAxisAtBothEndsIsPartedBeforeItsQueries) {
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({71, 72})) {
        std::printf("[ seed     ] PairMotion side by side: seed %llu\n", static_cast<unsigned long long>(seed));
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> coordinate(-1, 1);
        for (int n = 0; n < 2000; ++n) {
            const Vec3 flight = Vec3(10 + 5 * coordinate(rng), coordinate(rng), coordinate(rng));  // past the gap of 2.5
            PairMotion m;
            m.ia = {0, 1, 2};
            m.ib = {3, 4, 5};
            for (int i = 0; i < 3; ++i) {
                const Vec3 a(coordinate(rng), coordinate(rng), coordinate(rng));
                const Vec3 b = Vec3(2.5, 0, 0) + Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
                m.a[i] = {a, a + flight + 0.2 * Vec3(coordinate(rng), coordinate(rng), coordinate(rng))};
                m.b[i] = {b, b + flight + 0.2 * Vec3(coordinate(rng), coordinate(rng), coordinate(rng))};
            }
            ASSERT_TRUE(apart_on_an_axis(m)) << "seed " << seed << " pair " << n;
            ASSERT_TRUE(overlap_window(m).empty()) << "seed " << seed << " pair " << n;
            const PairOutcome outcome = test_pair(m, 1e-6, 10000);
            ASSERT_FALSE(outcome.contact) << "seed " << seed << " pair " << n;
            ASSERT_EQ(outcome.queries, 0u) << "seed " << seed << " pair " << n;
        }
        int apart = 0, not_apart = 0;
        for (int n = 0; n < 4000; ++n) {
            PairMotion m;
            m.ia = {0, 1, 2};
            m.ib = {3, 4, 5};
            const Vec3 flight_a = 3 * Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
            const Vec3 flight_b = 3 * Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
            for (int i = 0; i < 3; ++i) {
                const Vec3 a = 0.5 * Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
                const Vec3 b = Vec3(coordinate(rng), coordinate(rng), coordinate(rng)) + 0.5 * Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
                m.a[i] = {a, a + flight_a};
                m.b[i] = {b, b + flight_b};
            }
            if (!apart_on_an_axis(m)) {
                ++not_apart;
                continue;
            }
            ++apart;
            ASSERT_TRUE(overlap_window(m).empty()) << "seed " << seed << " pair " << n;
            bool some_axis = false;
            for (int k = 0; k < 3 && !some_axis; ++k) {
                bool a_below = true, b_below = true;
                for (int step = 0; step <= 256; ++step) {
                    const double t = step / 256.0;
                    double a_lo = 1e300, a_hi = -1e300, b_lo = 1e300, b_hi = -1e300;
                    for (int i = 0; i < 3; ++i) {
                        // The ends exactly (the interpolation's rounding at t = 1 could move them).
                        const double x = step == 256 ? m.a[i][1][k] : m.a[i][0][k] + t * (m.a[i][1][k] - m.a[i][0][k]);
                        const double y = step == 256 ? m.b[i][1][k] : m.b[i][0][k] + t * (m.b[i][1][k] - m.b[i][0][k]);
                        a_lo = std::min(a_lo, x), a_hi = std::max(a_hi, x), b_lo = std::min(b_lo, y), b_hi = std::max(b_hi, y);
                    }
                    a_below = a_below && a_hi < b_lo;
                    b_below = b_below && b_hi < a_lo;
                }
                some_axis = a_below || b_below;
            }
            ASSERT_TRUE(some_axis) << "seed " << seed << " pair " << n;
        }
        std::printf("%d random pairs apart on an axis, %d not\n", apart, not_apart);
        EXPECT_GT(apart, 200);
        EXPECT_GT(not_apart, 200);
    }
}

// The same gap along x at both ends, but on opposite sides: the small upright triangle passes
// through the flat one between the frames, and is reported (a filter that ignored which side
// is ahead would part it).
TEST(PairMotion, APairThatChangesSidesOnAnAxisIsStillTested) {
    PairMotion m;
    m.ia = {0, 1, 2};
    m.ib = {3, 4, 5};
    const std::array<Vec3, 3> flat{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 1, 0)};
    const std::array<Vec3, 3> upright{Vec3(0, 0, -0.5), Vec3(0.5, 0, 0.5), Vec3(0, 0.2, 0.5)};
    for (int i = 0; i < 3; ++i) {
        m.a[i] = {flat[i], flat[i]};
        m.b[i] = {upright[i] + Vec3(2, 0, 0), upright[i] - Vec3(2.5, 0, 0)};
    }
    ASSERT_FALSE(triangles_intersect(flat[0], flat[1], flat[2], m.b[0][0], m.b[1][0], m.b[2][0]));
    ASSERT_FALSE(triangles_intersect(flat[0], flat[1], flat[2], m.b[0][1], m.b[1][1], m.b[2][1]));
    const PairOutcome outcome = test_pair(m, 1e-6, 10000);
    EXPECT_TRUE(outcome.contact);
    EXPECT_FALSE(outcome.start_contact);
    EXPECT_FALSE(outcome.end_contact);
    // The upright triangle's edge from (0, 0, -0.5) to (0, 0.2, 0.5) crosses the flat one's
    // plane at (0, 0.1, 0) plus its offset 2 - 4.5 t along x, which reaches the flat one's edge
    // x = 1 - (y + 1) / 2 (x = 0.45 at y = 0.1) first: at 2 - 4.5 t = 0.45.
    EXPECT_NEAR(outcome.toi, 1.55 / 4.5, 1e-5);
}

// Apart must be strict: a vertex of one triangle on the other's face, still, with the two
// ranges along x meeting at that vertex's coordinate at both ends, is a contact.
TEST(PairMotion, APairWhoseRangesMeetOnAnAxisAtBothEndsIsNotParted) {
    PairMotion m;
    m.ia = {0, 1, 2};
    m.ib = {3, 4, 5};
    const std::array<Vec3, 3> face{Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};  // in x = 0
    const std::array<Vec3, 3> touching{Vec3(0, 0.2, 0.2), Vec3(1, 0.2, 0.2), Vec3(1, 0.5, 0.2)};
    for (int i = 0; i < 3; ++i) {
        m.a[i] = {face[i], face[i]};
        m.b[i] = {touching[i], touching[i]};
    }
    EXPECT_FALSE(apart_on_an_axis(m));
    EXPECT_FALSE(overlap_window(m).empty());
    const PairOutcome outcome = test_pair(m, 1e-6, 10000);
    EXPECT_TRUE(outcome.contact);
    EXPECT_TRUE(outcome.start_contact);
}

// The overlap window against the slow obvious answers (seeds printed):
// - the exact window of the interpolated bounds, in rationals: the computed one holds it, and
//   is within 1e-12 of it (no wider than it needs to be);
// - on coordinates on a grid of 1/8 below 2^25, where every position at a time k / 1024 is
//   exact, each triangle's box computed there: wherever the two boxes meet (touching counts),
//   the window holds the time. The third seed's coordinates are arbitrary doubles far from
//   the origin, whose differences round: only the rational check applies there.
// A pair apart on an axis at both ends has an empty window.
TEST(PairMotion, TheOverlapWindowHoldsEveryTimeTheBoxesMeet) {
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({81, 82, 83})) {
        std::printf("[ seed     ] PairMotion overlap window: seed %llu\n", static_cast<unsigned long long>(seed));
        std::mt19937_64 rng(seed);
        const bool grid = seed != 83;
        std::uniform_int_distribution<int> step_of_grid(-64, 64);
        std::uniform_real_distribution<double> real(-64, 64);
        const auto point = [&] {
            return grid ? Vec3(step_of_grid(rng), step_of_grid(rng), step_of_grid(rng)) : Vec3(real(rng), real(rng), real(rng));
        };
        int empty = 0, narrowed = 0, met = 0;
        const int pairs = testing::sweep_size(3000);
        for (int n = 0; n < pairs; ++n) {
            PairMotion m;
            m.ia = {0, 1, 2};
            m.ib = {3, 4, 5};
            // A far offset on some pairs: the gaps are differences of large coordinates.
            const Vec3 offset = n % 3 != 0 ? Vec3::Zero() : grid ? Vec3(1 << 24, -(1 << 24), 1 << 20) : Vec3(3e7 + 0.1, -1e9 / 3, 7e5);
            const Vec3 flight_a = 2 * point(), flight_b = 2 * point();
            for (int i = 0; i < 3; ++i) {
                const Vec3 a = offset + 0.25 * point(), b = offset + point();
                m.a[i] = {a, a + flight_a + 0.125 * point()};
                m.b[i] = {b, b + flight_b + 0.125 * point()};
            }
            const OverlapWindow window = overlap_window(m);
            if (apart_on_an_axis(m)) {
                ASSERT_TRUE(window.empty()) << "seed " << seed << " pair " << n;
            }
            ASSERT_LE(0.0, window.lo);
            ASSERT_LE(window.hi, 1.0);
            bool any = false;
            for (int step = 0; step <= 1024 && grid; ++step) {
                const double t = step / 1024.0;
                std::array<Vec3, 2> lo{Vec3::Constant(1e300), Vec3::Constant(1e300)}, hi{-lo[0], -lo[1]};
                for (int i = 0; i < 3; ++i) {
                    const Vec3 x = m.a[i][0] + t * (m.a[i][1] - m.a[i][0]), y = m.b[i][0] + t * (m.b[i][1] - m.b[i][0]);
                    lo[0] = lo[0].cwiseMin(x), hi[0] = hi[0].cwiseMax(x), lo[1] = lo[1].cwiseMin(y), hi[1] = hi[1].cwiseMax(y);
                }
                if ((lo[0].array() <= hi[1].array()).all() && (lo[1].array() <= hi[0].array()).all()) {
                    any = true;
                    ASSERT_TRUE(window.lo <= t && t <= window.hi)
                        << "seed " << seed << " pair " << n << ": the boxes meet at t = " << t << ", the window is ["
                        << window.lo << ", " << window.hi << "]";
                }
            }
            met += any;
            // The exact window of the interpolated bounds: each gap's ends exactly, its root as
            // a rational.
            mpq_class lo = 0, hi = 1;
            bool exact_empty = false;
            for (int k = 0; k < 3; ++k) {
                std::array<double, 2> a_lo, a_hi, b_lo, b_hi;
                for (int end = 0; end < 2; ++end) {
                    std::tie(a_lo[end], a_hi[end]) = axis_range(m.a, end, k);
                    std::tie(b_lo[end], b_hi[end]) = axis_range(m.b, end, k);
                }
                const auto gap = [](double top, double bottom) -> mpq_class { return mpq_class(top) - mpq_class(bottom); };
                for (const auto& [g0, g1] : {std::pair{gap(a_hi[0], b_lo[0]), gap(a_hi[1], b_lo[1])},
                                             std::pair{gap(b_hi[0], a_lo[0]), gap(b_hi[1], a_lo[1])}}) {
                    if (g0 < 0 && g1 < 0) exact_empty = true;
                    if ((g0 < 0) == (g1 < 0)) continue;
                    const mpq_class root = g0 / (g0 - g1);
                    if (g0 < 0 && root > lo) lo = root;
                    if (g0 >= 0 && root < hi) hi = root;
                }
            }
            exact_empty = exact_empty || lo > hi;
            if (window.empty()) {
                ASSERT_TRUE(exact_empty) << "seed " << seed << " pair " << n;
                ++empty;
                continue;
            }
            if (exact_empty) continue;  // only where the ends nearly meet: the window is rounded outward
            ASSERT_LE(mpq_class(window.lo), lo) << "seed " << seed << " pair " << n;
            ASSERT_GE(mpq_class(window.hi), hi) << "seed " << seed << " pair " << n;
            ASSERT_LE(mpq_class(lo - window.lo).get_d(), 1e-12) << "seed " << seed << " pair " << n;
            ASSERT_LE(mpq_class(window.hi - hi).get_d(), 1e-12) << "seed " << seed << " pair " << n;
            narrowed += window.hi - window.lo < 0.5;
        }
        std::printf("%d pairs: %d with an empty window, %d narrowed to under half, %d meeting at a sampled time\n", pairs, empty,
                    narrowed, met);
        EXPECT_GT(empty, pairs / 20);
        EXPECT_GT(narrowed, pairs / 20);
        if (grid) {
            EXPECT_GT(met, pairs / 20);
        }
    }
}

// Two triangles whose boxes meet at one instant only, where their corners meet: along x the
// gap closes until t = 3/4, along y it opens from then on. The window is that instant, and
// the contact there is reported, in a plane and out of it, near the origin and far from it.
TEST(PairMotion, AContactAtTheOnlyInstantTheBoxesMeetIsReported) {
    for (const double z_tilt : {0.0, 1.0}) {
        for (const double offset : {0.0, 1e6, -3.0 * (1 << 30)}) {
            SCOPED_TRACE("tilt " + std::to_string(z_tilt) + ", offset " + std::to_string(offset));
            PairMotion m;
            m.ia = {0, 1, 2};
            m.ib = {3, 4, 5};
            const Vec3 shift = Vec3::Constant(offset);
            const std::array<Vec3, 3> still{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
            // At t = 3/4 the moving one's corner is at the origin, the rest at x <= 0, y <= 0.
            const std::array<Vec3, 3> at_contact{Vec3(0, 0, 0), Vec3(-1, 0, z_tilt), Vec3(0, -1, z_tilt)};
            const Vec3 velocity(-4, 4, 0);
            for (int i = 0; i < 3; ++i) {
                m.a[i] = {shift + still[i], shift + still[i]};
                m.b[i] = {shift + at_contact[i] - 0.75 * velocity, shift + at_contact[i] + 0.25 * velocity};
            }
            const OverlapWindow window = overlap_window(m);
            EXPECT_FALSE(window.empty());
            EXPECT_LE(window.lo, 0.75);
            EXPECT_GE(window.hi, 0.75);
            EXPECT_NEAR(window.lo, 0.75, 1e-12);
            EXPECT_NEAR(window.hi, 0.75, 1e-12);
            const PairOutcome outcome = test_pair(m, 1e-6, 10000);
            EXPECT_TRUE(outcome.contact);
            EXPECT_FALSE(outcome.start_contact);
            EXPECT_LE(outcome.toi, 0.75);
            EXPECT_GT(outcome.toi, 0.75 - 1e-3);
            // The moving one started 1e-3 lower along y: its corner passes below the other's
            // as the x gap closes, the boxes never meet, and the pair is apart.
            for (int i = 0; i < 3; ++i) m.b[i][0].y() -= 1e-3;
            EXPECT_TRUE(overlap_window(m).empty());
            EXPECT_FALSE(test_pair(m, 1e-6, 10000).contact);
        }
    }
}

}  // namespace
}  // namespace collidescope::ccd
