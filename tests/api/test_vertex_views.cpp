// The facade's position copy: the block copy and the strided and widening loops against the
// slow one-coordinate-at-a-time reference, and a session fed the same coordinates through
// every layout reports the same pairs.

#include "session_helpers.hpp"

#include "frame_input.hpp"

#include "collidescope/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace collidescope {
namespace {

// `count` vertices of random floats stored in a buffer of `width` scalars per row, x y z at
// columns `columns` (so the rows can be padded and the axes permuted or reversed).
template <class T>
struct StridedBuffer {
    std::vector<T> buffer;
    VertexView view;
};

template <class T>
StridedBuffer<T> random_layout(std::mt19937_64& rng, std::size_t count, std::size_t width, std::size_t first_column,
                        int column_step, bool reversed_rows) {
    std::uniform_real_distribution<double> value(-10, 10);
    StridedBuffer<T> layout;
    layout.buffer.resize(count * width);
    for (T& v : layout.buffer) v = static_cast<T>(value(rng));
    const auto row = static_cast<std::ptrdiff_t>(width * sizeof(T));
    const T* first = layout.buffer.data() + first_column + (reversed_rows && count > 0 ? (count - 1) * width : 0);
    layout.view = {first, count, std::is_same_v<T, float> ? Scalar::Float32 : Scalar::Float64,
                   reversed_rows ? -row : row, column_step * static_cast<std::ptrdiff_t>(sizeof(T))};
    return layout;
}

template <class T>
void expect_copy_equals_reference(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    for (int trial = 0; trial < 50; ++trial) {
        const std::size_t count = rng() % 40;
        const bool packed = trial % 2 == 0;
        const std::size_t width = packed ? 3 : 3 + rng() % 3;
        const int step = packed || trial % 3 != 0 ? 1 : -1;  // -1: z y x at columns 2 1 0
        const std::size_t first_column = step == 1 ? (packed ? 0 : rng() % (width - 2)) : 2;
        const StridedBuffer<T> layout = random_layout<T>(rng, count, width, first_column, step, !packed && trial % 5 == 1);
        std::vector<Vec3> fast;
        std::vector<Vec3> slow;
        api::copy_vertices(layout.view, fast, "object 0");
        api::copy_vertices_reference(layout.view, slow, "object 0");
        ASSERT_EQ(fast.size(), count);
        ASSERT_TRUE(fast == slow) << "seed " << seed << " trial " << trial;
    }
}

TEST(VertexViews, CopyEqualsTheReference) {
    expect_copy_equals_reference<double>(240);
    expect_copy_equals_reference<float>(241);
}

TEST(VertexViews, ContiguousOnlyForPackedRows) {
    const double xyz[6] = {};
    EXPECT_TRUE(vertex_view(std::span<const double>(xyz)).contiguous());
    EXPECT_TRUE(vertex_view(xyz, 1, 4 * sizeof(double)).contiguous());  // one vertex: any row stride
    EXPECT_FALSE((VertexView{xyz, 2, Scalar::Float64, 4 * sizeof(double), sizeof(double)}.contiguous()));
    EXPECT_FALSE((VertexView{xyz, 2, Scalar::Float32, 3 * sizeof(double), sizeof(double)}.contiguous()));
}

// A NaN or infinity anywhere is named with its vertex and axis, by both copies alike.
TEST(VertexViews, NonFiniteCoordinatesAreNamed) {
    for (const double bad : {std::nan(""), double(INFINITY), -double(INFINITY)}) {
        std::vector<double> xyz(30, 1.0);
        xyz[3 * 7 + 2] = bad;
        std::vector<Vec3> out;
        for (const auto copy : {&api::copy_vertices, &api::copy_vertices_reference}) {
            try {
                copy(vertex_view(std::span<const double>(xyz)), out, "object 3 ('cloth')");
                FAIL() << "no error for " << bad;
            } catch (const InputError& error) {
                EXPECT_EQ(std::string(error.what()).rfind("object 3 ('cloth'): vertex 7 has a non-finite z coordinate", 0), 0u)
                    << error.what();
            }
        }
    }
}

// Float32 coordinates, packed or strided, give the pairs of the same values as doubles.
TEST(VertexViews, EveryLayoutGivesTheSamePairs) {
    SceneFrames scene = SceneFrames::builtin("C:small");
    Session doubles({.method = "aabb"});
    Session floats({.method = "aabb"});
    Session padded({.method = "aabb"});
    for (Session* session : {&doubles, &floats, &padded}) testing::declare_objects(*session, scene);
    std::size_t total = 0;
    for (std::uint32_t f = 0; f < scene.frame_count(); ++f) {
        scene.load(f);
        std::vector<std::vector<float>> single(2);
        std::vector<std::vector<double>> rounded(2);
        std::vector<std::vector<double>> xyzw(2);
        for (std::uint32_t k = 0; k < 2; ++k) {
            for (const double v : scene.positions(k)) single[k].push_back(static_cast<float>(v));
            rounded[k].assign(single[k].begin(), single[k].end());
            for (std::size_t i = 0; i < rounded[k].size(); i += 3) {
                xyzw[k].insert(xyzw[k].end(), {rounded[k][i], rounded[k][i + 1], rounded[k][i + 2], -1.0});
            }
        }
        const VertexView d[] = {vertex_view(std::span<const double>(rounded[0])), vertex_view(std::span<const double>(rounded[1]))};
        const VertexView s[] = {vertex_view(std::span<const float>(single[0])), vertex_view(std::span<const float>(single[1]))};
        const VertexView p[] = {vertex_view(xyzw[0].data(), xyzw[0].size() / 4, 4 * sizeof(double)),
                                vertex_view(xyzw[1].data(), xyzw[1].size() / 4, 4 * sizeof(double))};
        const std::span<const CollidingPair> from_doubles = doubles.step(d);
        const std::vector<CollidingPair> expected(from_doubles.begin(), from_doubles.end());
        const std::span<const CollidingPair> from_floats = floats.step(s);
        ASSERT_TRUE(std::equal(expected.begin(), expected.end(), from_floats.begin(), from_floats.end())) << "frame " << f;
        const std::span<const CollidingPair> from_padded = padded.step(p);
        ASSERT_TRUE(std::equal(expected.begin(), expected.end(), from_padded.begin(), from_padded.end())) << "frame " << f;
        total += expected.size();
    }
    EXPECT_GT(total, 0u);
}

}  // namespace
}  // namespace collidescope
