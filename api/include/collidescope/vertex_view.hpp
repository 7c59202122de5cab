#pragma once
/// Views of caller memory that a Session reads one frame's positions from (api/).
///
/// A view names V vertices of x, y, z as float or double at any byte strides, so an array in
/// any layout (a std::vector of structs, a numpy array, a column of an SoA buffer) is read
/// where it lies: packed doubles by the engine itself (no copy), other layouts once, into
/// doubles. The caller owns the memory; it must stay valid and unchanged during step() only.

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

namespace collidescope {

/// The scalar type of a VertexView's coordinates.
enum class Scalar : std::uint8_t {
    Float32,  ///< float: widened to double exactly
    Float64,  ///< double: taken as is
};

/// V vertices of one object: vertex i, coordinate c (0 x, 1 y, 2 z) is the scalar at
/// `data + i * row_stride + c * column_stride` (bytes).
struct VertexView {
    const void* data = nullptr;        ///< the first vertex's x; may be null when count is 0
    std::size_t count = 0;             ///< V, vertices
    Scalar scalar = Scalar::Float64;   ///< float or double
    std::ptrdiff_t row_stride = 0;     ///< bytes from one vertex to the next
    std::ptrdiff_t column_stride = 0;  ///< bytes from x to y, y to z

    /// True when the view is packed x y z x y z ... of its scalar (the copy is one block).
    bool contiguous() const {
        const std::ptrdiff_t size = scalar == Scalar::Float32 ? 4 : 8;
        return column_stride == size && (row_stride == 3 * size || count <= 1);
    }
};

/// A view of packed x y z doubles: `xyz.size() / 3` vertices (size must be a multiple of 3).
inline VertexView vertex_view(std::span<const double> xyz) {
    return {xyz.data(), xyz.size() / 3, Scalar::Float64, 3 * sizeof(double), sizeof(double)};
}

/// A view of packed x y z floats: `xyz.size() / 3` vertices (size must be a multiple of 3).
inline VertexView vertex_view(std::span<const float> xyz) {
    return {xyz.data(), xyz.size() / 3, Scalar::Float32, 3 * sizeof(float), sizeof(float)};
}

/// A view of an array of structs or vectors with three consecutive coordinates, `stride`
/// bytes apart (std::vector<std::array<double, 3>>, Eigen::Vector3d, a {x, y, z, w} struct).
template <class T>
VertexView vertex_view(const T* first, std::size_t count, std::ptrdiff_t stride = 3 * sizeof(T)) {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>, "float or double coordinates");
    return {first, count, std::is_same_v<T, float> ? Scalar::Float32 : Scalar::Float64, stride, sizeof(T)};
}

}  // namespace collidescope
