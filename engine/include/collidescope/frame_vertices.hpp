#pragma once
/// One object's vertex positions in one frame (ObjectFrame::vertices): either owned, as the
/// readers, point caches, generators and animated models produce them, or a view of memory
/// the caller owns, so the embedding facade hands packed doubles to the engine with no copy
/// (Session::step, docs/reference/embedding.md).
///
/// A view is valid only while the caller's memory is. The engine reads a frame's vertices only
/// inside Pipeline::process (and the sinks' on_frame, called from it); whatever keeps positions
/// across frames copies them (the background rebuild's snapshot, the recorder's float copy).

#include "collidescope/types.hpp"

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <utility>
#include <vector>

namespace collidescope {

// A view reinterprets caller memory of packed x y z doubles as Vec3: that needs Vec3 to be
// exactly three doubles, with no padding and no stricter alignment than a double's.
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three packed doubles");
static_assert(alignof(Vec3) == alignof(double), "Vec3 is aligned like a double");

/// Read-only positions, indexed like the object's vertices. Copying an owning FrameVertices
/// copies the positions; copying a view copies the view (both still view the caller's memory).
/// Not thread-safe to assign while read; reading from several threads is fine.
class FrameVertices {
public:
    using value_type = Vec3;
    using iterator = const Vec3*;
    using const_iterator = const Vec3*;

    FrameVertices() = default;
    /// Owns `vertices` (implicit, so a producer writes `{topology, std::move(vertices)}`).
    FrameVertices(std::vector<Vec3> vertices) : m_owned(std::move(vertices)) { point_at_owned(); }
    FrameVertices(std::initializer_list<Vec3> vertices) : FrameVertices(std::vector<Vec3>(vertices)) {}

    /// Views `vertices` in place, without a copy. The caller keeps them valid and unchanged
    /// while the frame is in use (for the engine: until Pipeline::process returns).
    static FrameVertices view(std::span<const Vec3> vertices) {
        FrameVertices result;
        result.m_data = vertices.data();
        result.m_size = vertices.size();
        result.m_owns = false;
        return result;
    }

    FrameVertices(const FrameVertices& other)
        : m_owned(other.m_owned), m_data(other.m_data), m_size(other.m_size), m_owns(other.m_owns) {
        if (m_owns) point_at_owned();
    }
    FrameVertices(FrameVertices&& other) noexcept
        : m_owned(std::move(other.m_owned)), m_data(other.m_data), m_size(other.m_size), m_owns(other.m_owns) {
        if (m_owns) point_at_owned();
        other.clear();
    }
    FrameVertices& operator=(FrameVertices other) noexcept {
        swap(other);
        return *this;
    }
    ~FrameVertices() = default;

    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    const Vec3* data() const { return m_data; }
    const Vec3* begin() const { return m_data; }
    const Vec3* end() const { return m_data + m_size; }
    const Vec3& operator[](std::size_t i) const { return m_data[i]; }
    const Vec3& front() const { return m_data[0]; }
    const Vec3& back() const { return m_data[m_size - 1]; }
    std::span<const Vec3> span() const { return {m_data, m_size}; }

    /// True when the positions are this object's own; false for a view of caller memory.
    bool owns() const { return m_owns; }
    /// An owning copy of the positions: what to keep when they must outlive the frame.
    std::vector<Vec3> to_vector() const { return {begin(), end()}; }

    /// Equal positions, element by element (owning or not).
    friend bool operator==(const FrameVertices& a, const FrameVertices& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end());
    }

private:
    void point_at_owned() {
        m_data = m_owned.data();
        m_size = m_owned.size();
        m_owns = true;
    }
    void clear() {
        m_owned.clear();
        m_data = nullptr;
        m_size = 0;
        m_owns = true;
    }
    void swap(FrameVertices& other) noexcept {
        std::swap(m_owned, other.m_owned);  // a vector's swap keeps each buffer where it is
        std::swap(m_data, other.m_data);
        std::swap(m_size, other.m_size);
        std::swap(m_owns, other.m_owns);
    }

    std::vector<Vec3> m_owned;       ///< the positions when owning; empty for a view
    const Vec3* m_data = nullptr;    ///< m_owned.data(), or the caller's memory
    std::size_t m_size = 0;
    bool m_owns = true;              ///< an empty FrameVertices owns its (no) positions
};

}  // namespace collidescope
