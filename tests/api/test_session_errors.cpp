// Bad input at the facade's boundary: one-line InputErrors naming the object and element,
// thrown before the engine sees the frame, after which the session is still usable.

#include "collidescope/error.hpp"
#include "collidescope/session.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

namespace collidescope {
namespace {

// Two triangles over four vertices: a unit square at height z.
const std::array<std::uint32_t, 3> k_square[] = {{0, 1, 2}, {0, 2, 3}};

std::vector<double> square(double z) { return {0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z}; }

std::string error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no InputError)";
}

class SessionErrors : public ::testing::Test {
protected:
    void SetUp() override {
        m_session.add_object(k_square, "floor");
        m_session.add_object(k_square);
    }
    std::span<const CollidingPair> step(const std::vector<double>& a, const std::vector<double>& b) {
        const VertexView views[] = {vertex_view(std::span<const double>(a)), vertex_view(std::span<const double>(b))};
        return m_session.step(views);
    }
    Session m_session{{.method = "brute"}};
};

TEST_F(SessionErrors, WrongObjectCount) {
    const std::vector<double> a = square(0);
    const VertexView one[] = {vertex_view(std::span<const double>(a))};
    EXPECT_EQ(error_of([&] { m_session.step(one); }), "step: positions for 1 objects, 2 declared");
}

TEST_F(SessionErrors, NonFiniteCoordinateNamesObjectAndVertex) {
    std::vector<double> b = square(0);
    b[3 * 2 + 1] = std::nan("");
    EXPECT_EQ(error_of([&] { step(square(0), b); }), "object 1: vertex 2 has a non-finite y coordinate (nan)");
    EXPECT_EQ(step(square(0), square(0)).size(), 4u);  // still usable: coplanar overlaps
    EXPECT_EQ(m_session.frame_count(), 1u);
}

TEST_F(SessionErrors, IndexPastTheVerticesNamesTheTriangle) {
    const std::vector<double> three(9, 0.0);
    EXPECT_EQ(error_of([&] { step(three, square(1)); }), "object 0 ('floor'): triangle 1 corner 2 is vertex 3, past its 3 vertices");
    EXPECT_EQ(step(square(0), square(1)).size(), 0u);  // the failed first frame fixed nothing
}

TEST_F(SessionErrors, VertexCountMayNotChange) {
    step(square(0), square(1));
    std::vector<double> five = square(1);
    five.insert(five.end(), {2, 2, 2});
    EXPECT_EQ(error_of([&] { step(square(0), five); }), "object 1: 5 vertices in frame 1, 4 since frame 0 (set_triangles changes an object's topology)");
}

// A topology change takes effect with the next step's positions, checked against them.
TEST_F(SessionErrors, SetTrianglesChangesTheVertexCount) {
    step(square(0), square(1));
    const std::array<std::uint32_t, 3> three[] = {{0, 1, 4}, {2, 3, 4}, {4, 1, 2}};
    m_session.set_triangles(1, three);
    EXPECT_EQ(error_of([&] { step(square(0), square(0)); }),
              "object 1: triangle 0 corner 2 is vertex 4, past its 4 vertices");
    std::vector<double> five = square(0);
    five.insert(five.end(), {0.5, 0.5, 0});
    EXPECT_EQ(step(square(0), five).size(), 6u);  // 2 x 3 coplanar overlaps
    EXPECT_EQ(error_of([&] { step(square(0), square(0)); }),
              "object 1: 4 vertices in frame 2, 5 since frame 1 (set_triangles changes an object's topology)");
    EXPECT_EQ(error_of([&] { m_session.set_triangles(2, three); }), "set_triangles: no object 2 (2 declared)");
}

TEST(SessionErrorsOther, NoObjectsNoTrianglesUnknownMethod) {
    Session session;
    EXPECT_EQ(error_of([&] { session.step({}); }), "step: no objects declared (add_object before the first step)");
    EXPECT_EQ(error_of([&] { session.add_object(std::span<const std::array<std::uint32_t, 3>>(), "empty"); }),
              "object 0 ('empty'): no triangles");
    const std::uint32_t flat[] = {0, 1, 2, 3};
    EXPECT_EQ(error_of([&] { session.add_object(flat); }), "add_object: 4 indices, not 3 per triangle");
    EXPECT_THROW(Session({.method = "nope"}), std::invalid_argument);
    EXPECT_THROW(Session({.policy = "nope"}), std::invalid_argument);
    EXPECT_THROW(Session({.threads = -1}), std::invalid_argument);
}

TEST(SessionErrorsOther, NoObjectsAfterTheFirstStepNoStepAfterClose) {
    Session session({.method = "aabb"});
    session.add_object(k_square);
    const std::vector<double> a = square(0);
    const VertexView views[] = {vertex_view(std::span<const double>(a))};
    session.step(views);
    EXPECT_THROW(session.add_object(k_square), std::logic_error);
    session.close();
    session.close();  // idempotent
    EXPECT_THROW(session.step(views), std::logic_error);
}

}  // namespace
}  // namespace collidescope
