#pragma once
// The facade's input boundary: one object's positions from a caller's VertexView into the
// engine's Frame (viewed in place when they are packed doubles, converted otherwise), and its
// triangles at declaration, each checked once here (STYLE.md: bad input at a public entry is
// an InputError naming the object and element).

#include "collidescope/scene.hpp"
#include "collidescope/vertex_view.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace collidescope::api {

/// "object 2 ('cloth')" or "object 2": how messages name an object.
std::string object_label(std::uint32_t object, const std::string& name);

/// True when the engine can read `view` in place as Vec3: packed x y z doubles (contiguous,
/// float64) at a double's alignment. A numpy (V, 3) float64 C-contiguous array is.
bool viewable_in_place(const VertexView& view);

/// One object's positions for the engine's frame. When viewable_in_place, `vertices` views the
/// caller's memory (no copy) after a read pass that checks every coordinate is finite;
/// otherwise the positions are converted into `converted` (resized; the caller keeps it
/// across steps, so its capacity is reused) and `vertices` views that. Returns the bytes
/// converted: 0, or view.count * sizeof(Vec3). Throws InputError naming `label` and the first
/// vertex with a non-finite coordinate (before the engine sees the frame).
std::uint64_t take_vertices(const VertexView& view, std::vector<Vec3>& converted, FrameVertices& vertices,
                            const std::string& label);

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
