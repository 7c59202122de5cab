#pragma once
// The facade's input boundary: one object's positions from a caller's VertexView into the
// engine's Frame, and its triangles at declaration, each checked once here (STYLE.md: bad
// input at a public entry is an InputError naming the object and element).

#include "collidescope/scene.hpp"
#include "collidescope/vertex_view.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace collidescope::api {

/// "object 2 ('cloth')" or "object 2": how messages name an object.
std::string object_label(std::uint32_t object, const std::string& name);

/// Copies `view` into `vertices` (resized to view.count): one block copy when the view is
/// packed doubles, a widening or strided loop otherwise. Throws InputError naming `label`
/// and the first vertex with a non-finite coordinate (before the engine sees the frame).
void copy_vertices(const VertexView& view, std::vector<Vec3>& vertices, const std::string& label);

/// The same copy, one coordinate at a time through the view's strides: the slow, obvious
/// version that tests hold copy_vertices to.
void copy_vertices_reference(const VertexView& view, std::vector<Vec3>& vertices, const std::string& label);

/// Checks every index of `triangles` against `vertex_count`; throws InputError naming
/// `label`, the triangle and the index otherwise.
void check_triangle_indices(std::span<const TriIndices> triangles, std::uint32_t vertex_count,
                            const std::string& label);

}  // namespace collidescope::api
