// The facade's input boundary: positions viewed in place (packed doubles) or converted into
// the engine's Frame, and checked.

#include "frame_input.hpp"

#include "collidescope/error.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace collidescope::api {
namespace {

const char* const k_axes[] = {"x", "y", "z"};

[[noreturn]] void throw_non_finite(const std::string& label, std::size_t vertex, int axis, double value) {
    throw InputError(label + ": vertex " + std::to_string(vertex) + " has a non-finite " + k_axes[axis] +
                     " coordinate (" + std::to_string(value) + ")");
}

// The first vertex with a non-finite coordinate, named in an InputError (only called once a
// quick scan found one).
[[noreturn]] void report_non_finite(std::span<const Vec3> vertices, const std::string& label) {
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            if (!std::isfinite(vertices[i][axis])) throw_non_finite(label, i, axis, vertices[i][axis]);
        }
    }
    throw InputError(label + ": a non-finite coordinate");  // unreachable: the scan found one
}

// Whether every coordinate is finite: an exponent of all ones is infinity or NaN. Integer
// operations without early exit, so the loop vectorises.
bool all_finite(std::span<const Vec3> vertices) {
    const double* values = vertices.empty() ? nullptr : vertices.front().data();
    const std::size_t count = vertices.size() * 3;
    constexpr std::uint64_t k_exponent = 0x7ff0000000000000ull;
    std::uint64_t bad = 0;
    for (std::size_t i = 0; i < count; ++i) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, values + i, sizeof bits);
        bad |= static_cast<std::uint64_t>((bits & k_exponent) == k_exponent);
    }
    return bad == 0;
}

template <class T>
void copy_strided(const VertexView& view, std::vector<Vec3>& vertices) {
    const auto* base = static_cast<const std::byte*>(view.data);
    for (std::size_t i = 0; i < view.count; ++i) {
        const std::byte* row = base + static_cast<std::ptrdiff_t>(i) * view.row_stride;
        for (int axis = 0; axis < 3; ++axis) {
            T value;
            std::memcpy(&value, row + axis * view.column_stride, sizeof value);
            vertices[i][axis] = static_cast<double>(value);
        }
    }
}

}  // namespace

std::string object_label(std::uint32_t object, const std::string& name) {
    std::string label = "object " + std::to_string(object);
    if (!name.empty()) label += " ('" + name + "')";
    return label;
}

bool viewable_in_place(const VertexView& view) {
    // frame_vertices.hpp asserts Vec3 is three packed doubles aligned like a double, which
    // makes packed doubles at that alignment an array of Vec3.
    return view.scalar == Scalar::Float64 && view.contiguous() &&
           reinterpret_cast<std::uintptr_t>(view.data) % alignof(Vec3) == 0;
}

std::uint64_t take_vertices(const VertexView& view, std::vector<Vec3>& converted, FrameVertices& vertices,
                            const std::string& label) {
    if (viewable_in_place(view)) {
        const std::span<const Vec3> in_place(static_cast<const Vec3*>(view.data), view.count);
        if (!all_finite(in_place)) report_non_finite(in_place, label);
        vertices = FrameVertices::view(in_place);
        return 0;
    }
    copy_vertices(view, converted, label);
    vertices = FrameVertices::view(converted);
    return std::uint64_t{view.count} * sizeof(Vec3);
}

void copy_vertices(const VertexView& view, std::vector<Vec3>& vertices, const std::string& label) {
    vertices.resize(view.count);
    if (view.count == 0) return;
    if (view.scalar == Scalar::Float64 && view.contiguous()) {
        std::memcpy(vertices.front().data(), view.data, view.count * sizeof(Vec3));
    } else if (view.scalar == Scalar::Float64) {
        copy_strided<double>(view, vertices);
    } else {
        copy_strided<float>(view, vertices);
    }
    if (!all_finite(vertices)) report_non_finite(vertices, label);
}

void copy_vertices_reference(const VertexView& view, std::vector<Vec3>& vertices, const std::string& label) {
    vertices.assign(view.count, Vec3::Zero());
    const auto* base = static_cast<const std::byte*>(view.data);
    for (std::size_t i = 0; i < view.count; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const std::byte* at = base + static_cast<std::ptrdiff_t>(i) * view.row_stride + axis * view.column_stride;
            double value = 0;
            if (view.scalar == Scalar::Float32) {
                float single = 0;
                std::memcpy(&single, at, sizeof single);
                value = single;
            } else {
                std::memcpy(&value, at, sizeof value);
            }
            if (!std::isfinite(value)) throw_non_finite(label, i, axis, value);
            vertices[i][axis] = value;
        }
    }
}

void check_triangle_indices(std::span<const TriIndices> triangles, std::uint32_t vertex_count,
                            const std::string& label) {
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t index = triangles[t][corner];
            if (index >= vertex_count) {
                throw InputError(label + ": triangle " + std::to_string(t) + " corner " + std::to_string(corner) +
                                 " is vertex " + std::to_string(index) + ", past its " +
                                 std::to_string(vertex_count) + " vertices");
            }
        }
    }
}

}  // namespace collidescope::api
