// Nanoseconds per exact triangle-triangle test on random near-contact pairs, and the share of
// predicate calls that needed the exact fallback.
//
//   build/bench/bench_triangle_test [--benchmark_min_time=1]
//
// Workloads: "separated" (random float32 triangles in the unit cube: mostly plane-side
// rejections), "near_contact" (B has a corner within 1e-1..1e-12 of a point of A, float32
// coordinates), "coplanar" (both in z = const: every call reaches the exact path), and
// "self_adjacent" (pairs of one cloth grid sharing a vertex or an edge).

#include "collidescope/geometry.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using collidescope::Vec3;
using Tri = std::array<Vec3, 3>;

double f32(double x) { return collidescope::round_to_float32(x); }

std::vector<std::pair<Tri, Tri>> make_pairs(const std::string& kind, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto point = [&] { return Vec3(f32(unit(rng)), f32(unit(rng)), f32(unit(rng))); };
    std::vector<std::pair<Tri, Tri>> pairs(1 << 14);
    for (auto& [a, b] : pairs) {
        a = {point(), point(), point()};
        if (kind == "separated") {
            b = {point(), point(), point()};
        } else if (kind == "near_contact") {
            const double u = unit(rng), v = unit(rng) * (1 - u);
            const Vec3 x = a[0] + u * (a[1] - a[0]) + v * (a[2] - a[0]);
            const double offset = std::pow(10.0, -1 - int(unit(rng) * 12));
            const Vec3 b0 = x + offset * Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
            b = {Vec3(f32(b0.x()), f32(b0.y()), f32(b0.z())), point(), point()};
        } else {  // coplanar
            for (auto* t : {&a, &b})
                for (auto& p : *t) p.z() = 0.5;
            b = {point(), point(), point()};
            for (auto& p : b) p.z() = 0.5;
        }
    }
    return pairs;
}

void run(benchmark::State& state, const std::string& kind) {
    const auto pairs = make_pairs(kind, 42);
    const auto before = collidescope::predicate_counters();
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const auto& [a, b] = pairs[i++ & (pairs.size() - 1)];
        hits += collidescope::triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]);
    }
    const auto after = collidescope::predicate_counters();
    const double calls = double(after.filtered - before.filtered + after.exact - before.exact);
    state.counters["hit_rate"] = double(hits) / double(state.iterations());
    state.counters["exact_share"] = calls > 0 ? double(after.exact - before.exact) / calls : 0;
    state.counters["exact_per_test"] =
        double(after.exact - before.exact) / double(state.iterations());
}

/// Pairs of a 64x64 cloth grid that share a vertex or an edge, through the self rule.
void self_adjacent(benchmark::State& state) {
    const int n = 64;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> wobble(-0.2, 0.2);
    std::vector<Vec3> v;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) v.emplace_back(f32(x), f32(y), f32(wobble(rng)));
    std::vector<collidescope::TriIndices> t;
    const auto id = [&](int x, int y) { return std::uint32_t(y * (n + 1) + x); };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            t.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
            t.push_back({id(x, y), id(x + 1, y + 1), id(x, y + 1)});
        }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> adjacent;
    for (std::uint32_t i = 0; i < t.size(); ++i)
        for (std::uint32_t j = i + 1; j < std::min<std::uint32_t>(static_cast<std::uint32_t>(t.size()), i + 4 * n); ++j)
            for (auto vi : t[i])
                if (vi == t[j][0] || vi == t[j][1] || vi == t[j][2]) {
                    adjacent.emplace_back(i, j);
                    break;
                }
    const auto corners = [&](std::uint32_t k) { return Tri{v[t[k][0]], v[t[k][1]], v[t[k][2]]}; };
    const auto before = collidescope::predicate_counters();
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const auto& [p, q] = adjacent[i++ % adjacent.size()];
        hits += collidescope::self_triangles_collide(t[p], corners(p), t[q], corners(q));
    }
    const auto after = collidescope::predicate_counters();
    const double calls = double(after.filtered - before.filtered + after.exact - before.exact);
    state.counters["hit_rate"] = double(hits) / double(state.iterations());
    state.counters["exact_share"] = calls > 0 ? double(after.exact - before.exact) / calls : 0;
}

}  // namespace

BENCHMARK_CAPTURE(run, separated, std::string("separated"));
BENCHMARK_CAPTURE(run, near_contact, std::string("near_contact"));
BENCHMARK_CAPTURE(run, coplanar, std::string("coplanar"));
BENCHMARK(self_adjacent);
BENCHMARK_MAIN();
