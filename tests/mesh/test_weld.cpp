// weld: equal keys (value for value, -0 == +0) become one vertex, first occurrence first;
// checked against an all-pairs grouping on seeded random keys drawn from a small value set.

#include "mesh/weld.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace collidescope {
namespace {

WeldKeys keys_of(const std::vector<std::vector<double>>& rows) {
    WeldKeys keys;
    for (const auto& row : rows) keys.add(row);
    return keys;
}

TEST(Weld, EqualKeysShareTheFirstOccurrencesIndex) {
    const Welding welding = weld(keys_of({{1, 2, 3}, {0, 0, 0}, {1, 2, 3}, {-0.0, 0, 0}, {1, 2}}));
    EXPECT_EQ(welding.remap, (std::vector<std::uint32_t>{0, 1, 0, 1, 2}));
    EXPECT_EQ(welding.kept, (std::vector<std::uint32_t>{0, 1, 4}));
}

TEST(Weld, NanKeysNeverBreakTheOrderAndOnlyEqualBitsMeet) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Welding welding = weld(keys_of({{nan}, {1}, {nan}, {1}}));
    EXPECT_EQ(welding.remap, (std::vector<std::uint32_t>{0, 1, 0, 1}));
}

TEST(Weld, MatchesAllPairsGroupingOnRandomKeys) {
    const unsigned seed = 20261125;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> value(-2, 2), length(1, 4);
    for (int round = 0; round < 50; ++round) {
        std::vector<std::vector<double>> rows(200);
        for (auto& row : rows) {
            row.resize(length(rng) == 1 ? 2 : 3);
            for (double& x : row) x = value(rng) * 0.5;
        }
        const Welding welding = weld(keys_of(rows));
        // Slow: vertex v's new index is the number of distinct earlier first occurrences.
        std::vector<std::uint32_t> first_of(rows.size());
        std::vector<std::uint32_t> expected_kept;
        for (std::size_t v = 0; v < rows.size(); ++v) {
            std::size_t u = 0;
            while (rows[u] != rows[v]) ++u;
            if (u == v) {
                first_of[v] = static_cast<std::uint32_t>(expected_kept.size());
                expected_kept.push_back(static_cast<std::uint32_t>(v));
            } else {
                first_of[v] = first_of[u];
            }
        }
        ASSERT_EQ(welding.remap, first_of) << "seed " << seed << " round " << round;
        ASSERT_EQ(welding.kept, expected_kept) << "seed " << seed << " round " << round;
    }
}

}  // namespace
}  // namespace collidescope
