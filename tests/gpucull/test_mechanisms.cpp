// The thesis's tuning mechanisms with scripted inputs: the view configuration matrix
// (Algorithm 2, Equations 4.1-4.2, our reading in view_configuration.hpp) and the adaptive
// triangles per query (Algorithm 3, Equations 4.3-4.10, triangles_per_query.hpp).

#include "gpucull/triangles_per_query.hpp"
#include "gpucull/view_configuration.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace collidescope::gpucull {
namespace {

TEST(ViewConfiguration, UpdateFollowsEquations41And42AndStep2) {
    ViewConfiguration matrix({0.5, false, 1});
    const ViewConfiguration::Matrix before = matrix.matrix();
    matrix.update({1, 2, 0}, {0.8, 0.4, 0.2});
    const ViewConfiguration::Matrix& m = matrix.matrix();
    // (4.1) on the chosen entries, then row 0 raised to passes 1 and 2's entries for their
    // views, then everything * 0.5.
    const double r1z = before[1][2] / 4 + 0.75 * 0.4;  // pass 1 used view z
    const double r2x = before[2][0] / 4 + 0.75 * 0.2;  // pass 2 used view x
    const double r0y = before[0][1] / 4 + 0.75 * 0.8;  // pass 0 used view y
    EXPECT_DOUBLE_EQ(m[1][2], 0.5 * r1z);
    EXPECT_DOUBLE_EQ(m[2][0], 0.5 * r2x);
    EXPECT_DOUBLE_EQ(m[0][1], 0.5 * r0y);
    EXPECT_DOUBLE_EQ(m[0][2], 0.5 * std::max(before[0][2], r1z));
    EXPECT_DOUBLE_EQ(m[0][0], 0.5 * std::max(before[0][0], r2x));
    EXPECT_DOUBLE_EQ(m[1][0], 0.5 * before[1][0]);  // untouched entries only decay
}

TEST(ViewConfiguration, ChoosesTheBestViewPerPassAndExploresOncePerFrame) {
    ViewConfiguration greedy({0.9, false, 1});
    EXPECT_EQ(greedy.choose(3), (std::vector<int>{2, 0, 1}));  // the initial order z, x, y
    for (int frame = 0; frame < 5; ++frame) greedy.update({1, 0, 2}, {0.9, 0.5, 0.1});  // y culls best first
    EXPECT_EQ(greedy.choose(1).front(), 1);

    ViewConfiguration exploring({0.9, true, 7});
    int differs = 0;
    for (int frame = 0; frame < 200; ++frame) {
        const std::vector<int> views = exploring.choose(3);
        std::vector<int> sorted = views;
        std::sort(sorted.begin(), sorted.end());
        ASSERT_EQ(sorted, (std::vector<int>{0, 1, 2}));  // distinct views every frame
        differs += views != std::vector<int>{2, 0, 1};
    }
    EXPECT_GT(differs, 20);  // exploration does change the configuration
    EXPECT_LT(differs, 200);
}

// Expensive queries and a cheap final step: fewer queries pay, so P grows while the cull holds.
// Cheap queries and an expensive final step, with a larger P culling much less: P shrinks.
TEST(TrianglesPerQuery, MovesWithTheCostModel) {
    TrianglesPerQuery expensive_queries({4, 64});
    for (int frame = 0; frame < 10; ++frame) {
        // O = 1 ms per query, R = 0.0001 ms per triangle: a query costs 10,000 triangles' rebuild.
        expensive_queries.update({900, 1000, 1.0, 0.0001});
    }
    EXPECT_GT(expensive_queries.current(), 4u);
    EXPECT_DOUBLE_EQ(expensive_queries.predicted(4), 900);

    TrianglesPerQuery cheap_queries({1, 64});
    cheap_queries.update({900, 1000, 0.0001, 1.0});  // P = 1 culls 900 of 1000
    EXPECT_EQ(cheap_queries.current(), 2u);          // untried P = 2 is predicted as good
    cheap_queries.update({100, 1000, 0.0001, 1.0});  // but culls only 100
    EXPECT_EQ(cheap_queries.current(), 1u);          // P = 1's 900 pays for its queries

    TrianglesPerQuery fixed({1, 1});
    fixed.update({500, 1000, 1.0, 0.0001});
    EXPECT_EQ(fixed.current(), 1u);  // the maximum holds P
    EXPECT_EQ(fixed.predicted(2), -1);
}

TEST(TrianglesPerQuery, PredictionIsAThreeQuarterMovingAverage) {
    TrianglesPerQuery mechanism({1, 1});  // P cannot move
    mechanism.update({100, 1000, 0.04, 0.001});
    EXPECT_DOUBLE_EQ(mechanism.predicted(1), 100);
    mechanism.update({300, 1000, 0.04, 0.001});
    EXPECT_DOUBLE_EQ(mechanism.predicted(1), 100.0 / 4 + 0.75 * 300);
}

}  // namespace
}  // namespace collidescope::gpucull
