// GeneratedSource: frames computed on demand from per-object vertex functions.

#include "datasets/generated_source.hpp"

#include "scene/file_source.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

namespace collidescope::datasets {
namespace {

class GeneratedSource final : public FrameSource {
public:
    GeneratedSource(std::vector<GeneratedObject> objects, std::uint32_t frame_count)
        : m_objects(std::move(objects)), m_frame_count(frame_count) {
        for ([[maybe_unused]] const GeneratedObject& object : m_objects) {
            assert(!object.phases.empty() && object.phases.front().first_frame == 0);
            assert(std::is_sorted(object.phases.begin(), object.phases.end(),
                                  [](const TopologyPhase& a, const TopologyPhase& b) {
                                      return a.first_frame < b.first_frame;
                                  }));
            assert(object.vertices);
        }
    }

    std::uint32_t frame_count() const override { return m_frame_count; }
    std::uint32_t object_count() const override {
        return static_cast<std::uint32_t>(m_objects.size());
    }
    std::string object_name(std::uint32_t object) const override {
        return m_objects.at(object).name;
    }

    Frame frame(std::uint32_t index) override {
        if (index >= m_frame_count) {
            throw std::out_of_range("frame " + std::to_string(index) + " of " +
                                    std::to_string(m_frame_count));
        }
        Frame frame;
        frame.index = index;
        frame.objects.reserve(m_objects.size());
        for (const GeneratedObject& object : m_objects) {
            frame.objects.push_back(object_frame(object, index));
        }
        return frame;
    }

private:
    static ObjectFrame object_frame(const GeneratedObject& object, std::uint32_t index) {
        ObjectFrame result;
        result.topology = topology_at(object, index);
        std::vector<Vec3> vertices(result.topology->vertex_count);
        object.vertices(index, vertices);
        for (Vec3& vertex : vertices) vertex = round_to_float32(vertex);
        result.vertices = std::move(vertices);
        return result;
    }

    // The last phase that starts at or before `index`.
    static const std::shared_ptr<const Topology>& topology_at(const GeneratedObject& object,
                                                              std::uint32_t index) {
        auto phase = std::upper_bound(
            object.phases.begin(), object.phases.end(), index,
            [](std::uint32_t frame, const TopologyPhase& p) { return frame < p.first_frame; });
        return std::prev(phase)->topology;
    }

    std::vector<GeneratedObject> m_objects;
    std::uint32_t m_frame_count;
};

}  // namespace

std::shared_ptr<FrameSource> make_generated_source(std::vector<GeneratedObject> objects,
                                                   std::uint32_t frame_count) {
    return std::make_shared<GeneratedSource>(std::move(objects), frame_count);
}

std::shared_ptr<const Topology> make_topology(std::vector<TriIndices> triangles,
                                              std::uint32_t vertex_count) {
    auto topology = std::make_shared<Topology>();
    topology->triangles = std::move(triangles);
    topology->vertex_count = vertex_count;
    topology->revision = next_topology_revision();
    return topology;
}

std::vector<TriIndices> grid_triangles(std::uint32_t columns, std::uint32_t rows) {
    assert(columns >= 2 && rows >= 2);
    std::vector<TriIndices> triangles;
    triangles.reserve(2 * std::size_t{columns - 1} * (rows - 1));
    for (std::uint32_t j = 0; j + 1 < rows; ++j) {
        for (std::uint32_t i = 0; i + 1 < columns; ++i) {
            const std::uint32_t v00 = j * columns + i;
            const std::uint32_t v10 = v00 + 1;
            const std::uint32_t v01 = v00 + columns;
            const std::uint32_t v11 = v01 + 1;
            triangles.push_back({v00, v10, v11});
            triangles.push_back({v00, v11, v01});
        }
    }
    return triangles;
}

std::vector<TriIndices> torus_triangles(std::uint32_t columns, std::uint32_t rows) {
    assert(columns >= 3 && rows >= 3);
    std::vector<TriIndices> triangles;
    triangles.reserve(2 * std::size_t{columns} * rows);
    for (std::uint32_t j = 0; j < rows; ++j) {
        for (std::uint32_t i = 0; i < columns; ++i) {
            const std::uint32_t next_i = (i + 1) % columns;
            const std::uint32_t next_j = (j + 1) % rows;
            const std::uint32_t v00 = j * columns + i;
            const std::uint32_t v10 = j * columns + next_i;
            const std::uint32_t v01 = next_j * columns + i;
            const std::uint32_t v11 = next_j * columns + next_i;
            triangles.push_back({v00, v10, v11});
            triangles.push_back({v00, v11, v01});
        }
    }
    return triangles;
}

std::vector<TriIndices> soup_triangles(std::uint32_t count) {
    std::vector<TriIndices> triangles(count);
    for (std::uint32_t i = 0; i < count; ++i) triangles[i] = {3 * i, 3 * i + 1, 3 * i + 2};
    return triangles;
}

Random::Random(std::uint64_t seed, std::uint64_t stream)
    : m_state(seed ^ (stream * 0xD1B54A32D192ED03ULL)) {}

std::uint64_t Random::next_u64() {
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

double Random::uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

double Random::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

// Coordinates are drawn in separate statements: the order in which a constructor's arguments
// are evaluated is unspecified, and would make the stream compiler-dependent.
Vec3 Random::in_cube() {
    const double x = uniform(-1, 1);
    const double y = uniform(-1, 1);
    const double z = uniform(-1, 1);
    return {x, y, z};
}

Vec3 Random::unit_vector() {
    for (;;) {
        const Vec3 p = in_cube();
        const double norm = p.norm();
        if (norm > 1e-3 && norm <= 1) return p / norm;
    }
}

Vec3 Random::in_ball(double radius) {
    for (;;) {
        const Vec3 p = in_cube();
        if (p.squaredNorm() <= 1) return radius * p;
    }
}

}  // namespace collidescope::datasets
