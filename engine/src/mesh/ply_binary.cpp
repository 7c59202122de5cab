// Binary PLY bodies, little- and big-endian.
//
// Speed matters here (caches of millions of triangles per frame), so the common layouts get
// loops specialised at compile time: vertices whose x, y, z share one float type in a
// fixed-size record, and faces made of a single "uchar/char count + int/uint indices" list.
// Everything else walks each item property by property (a switch per value), still without
// strings or virtual calls.

#include "mesh/fan.hpp"
#include "mesh/ply_body.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <type_traits>

namespace collidescope::ply {
namespace {

inline std::uint8_t byteswap(std::uint8_t v) { return v; }
inline std::uint16_t byteswap(std::uint16_t v) { return __builtin_bswap16(v); }
inline std::uint32_t byteswap(std::uint32_t v) { return __builtin_bswap32(v); }
inline std::uint64_t byteswap(std::uint64_t v) { return __builtin_bswap64(v); }

template <std::size_t N>
using UnsignedOfSize = std::conditional_t<
    N == 1, std::uint8_t,
    std::conditional_t<N == 2, std::uint16_t,
                       std::conditional_t<N == 4, std::uint32_t, std::uint64_t>>>;

// One scalar of type T at `p`, byte-swapped when the file's byte order is not the host's.
template <class T, bool Swap>
inline T load(const std::byte* p) {
    using U = UnsignedOfSize<sizeof(T)>;
    U bits;
    std::memcpy(&bits, p, sizeof(U));
    if constexpr (Swap) bits = byteswap(bits);
    return std::bit_cast<T>(bits);
}

template <bool Swap>
double load_double(ScalarType type, const std::byte* p) {
    switch (type) {
        case ScalarType::Int8: return load<std::int8_t, Swap>(p);
        case ScalarType::UInt8: return load<std::uint8_t, Swap>(p);
        case ScalarType::Int16: return load<std::int16_t, Swap>(p);
        case ScalarType::UInt16: return load<std::uint16_t, Swap>(p);
        case ScalarType::Int32: return load<std::int32_t, Swap>(p);
        case ScalarType::UInt32: return load<std::uint32_t, Swap>(p);
        case ScalarType::Float32: return load<float, Swap>(p);
        case ScalarType::Float64: return load<double, Swap>(p);
    }
    return 0;
}

// Integer types only (list counts and corner indices; the header and layout check that).
template <bool Swap>
std::int64_t load_integer(ScalarType type, const std::byte* p) {
    switch (type) {
        case ScalarType::Int8: return load<std::int8_t, Swap>(p);
        case ScalarType::UInt8: return load<std::uint8_t, Swap>(p);
        case ScalarType::Int16: return load<std::int16_t, Swap>(p);
        case ScalarType::UInt16: return load<std::uint16_t, Swap>(p);
        case ScalarType::Int32: return load<std::int32_t, Swap>(p);
        case ScalarType::UInt32: return load<std::uint32_t, Swap>(p);
        case ScalarType::Float32:
        case ScalarType::Float64: break;
    }
    return -1;
}

template <bool Swap>
class BinaryBody {
public:
    BinaryBody(std::span<const std::byte> body, const Layout& layout, MeshData& mesh,
               std::string_view source)
        : m_pos(body.data()), m_end(body.data() + body.size()), m_body_size(body.size()),
          m_layout(layout), m_mesh(mesh), m_source(source) {}

    void read(const Header& header) {
        m_body_offset = header.body_offset;
        for (std::size_t e = 0; e < header.elements.size(); ++e) {
            const Element& element = header.elements[e];
            if (static_cast<int>(e) == m_layout.vertex_element) {
                read_vertices(element);
            } else if (static_cast<int>(e) == m_layout.face_element) {
                read_faces(element);
            } else {
                skip_element(element);
            }
        }
    }

private:
    std::size_t remaining() const { return static_cast<std::size_t>(m_end - m_pos); }
    // Byte offsets in the file (header included), for the truncation message.
    std::uint64_t file_offset(const std::byte* at) const {
        return m_body_offset + static_cast<std::uint64_t>(at - (m_end - m_body_size));
    }
    [[noreturn]] void truncated(const Element& element, std::uint64_t item, std::uint64_t needed,
                                const std::byte* at) const {
        throw_item_error(m_source, element.name, item,
                         "file truncated: expected " + std::to_string(needed) + " bytes at byte " +
                             std::to_string(file_offset(at)) + ", the file ends at byte " +
                             std::to_string(file_offset(m_end)));
    }

    // The next `size` bytes of item `item`, or the truncation error.
    const std::byte* take(std::uint64_t size, const Element& element, std::uint64_t item) {
        if (size > remaining()) truncated(element, item, size, m_pos);
        const std::byte* start = m_pos;
        m_pos += size;
        return start;
    }

    // Fixed-size records: checks that all `count` fit, else names the first that does not.
    void require_records(const Element& element, std::size_t stride) const {
        const std::uint64_t available = remaining() / stride;
        if (available < element.count) truncated(element, available, stride, m_pos + available * stride);
    }

    // Walks one item property by property, handing scalars and lists to the callbacks.
    template <class OnScalar, class OnList>
    void walk_item(const Element& element, std::uint64_t item, OnScalar&& on_scalar,
                   OnList&& on_list) {
        for (std::size_t p = 0; p < element.properties.size(); ++p) {
            const Property& property = element.properties[p];
            if (!property.is_list) {
                on_scalar(p, take(scalar_size(property.type), element, item));
                continue;
            }
            const std::byte* count_at = take(scalar_size(property.count_type), element, item);
            const std::int64_t count = load_integer<Swap>(property.count_type, count_at);
            if (count < 0) {
                throw_item_error(m_source, element.name, item, "negative list length " + std::to_string(count) +
                                                                   " at byte " + std::to_string(file_offset(count_at)));
            }
            const std::uint64_t size = static_cast<std::uint64_t>(count) * scalar_size(property.type);
            on_list(p, count, take(size, element, item));
        }
    }

    void skip_element(const Element& element) {
        if (element.fixed_size()) {
            const std::size_t stride = element.item_size();
            if (stride == 0) return;  // an element without properties takes no bytes
            require_records(element, stride);
            m_pos += element.count * stride;
            return;
        }
        for (std::uint64_t item = 0; item < element.count; ++item) {
            walk_item(element, item, [](std::size_t, const std::byte*) {},
                      [](std::size_t, std::int64_t, const std::byte*) {});
        }
    }

    void read_vertices(const Element& element) {
        if (element.fixed_size()) {
            read_fixed_vertices(element);
        } else {
            read_listed_vertices(element);
        }
        m_limit = {m_mesh.vertices.size(), true};
    }

    void read_fixed_vertices(const Element& element) {
        const std::size_t stride = element.item_size();
        require_records(element, stride);
        std::size_t offsets[3] = {0, 0, 0};
        const int axes[3] = {m_layout.x, m_layout.y, m_layout.z};
        for (int a = 0; a < 3; ++a) {
            for (int p = 0; p < axes[a]; ++p) offsets[a] += scalar_size(element.properties[p].type);
        }
        const ScalarType type = element.properties[m_layout.x].type;
        const bool same_type = element.properties[m_layout.y].type == type &&
                               element.properties[m_layout.z].type == type;
        m_mesh.vertices.resize(element.count);
        if (same_type && type == ScalarType::Float32) {
            copy_vertices<float>(stride, offsets);
        } else if (same_type && type == ScalarType::Float64) {
            copy_vertices<double>(stride, offsets);
        } else {
            copy_mixed_vertices(element, stride, offsets);
        }
        m_pos += element.count * stride;
    }

    template <class T>
    void copy_vertices(std::size_t stride, const std::size_t (&offsets)[3]) {
        const std::byte* record = m_pos;
        for (Vec3& vertex : m_mesh.vertices) {
            vertex = Vec3(load<T, Swap>(record + offsets[0]), load<T, Swap>(record + offsets[1]),
                          load<T, Swap>(record + offsets[2]));
            record += stride;
        }
    }

    void copy_mixed_vertices(const Element& element, std::size_t stride,
                             const std::size_t (&offsets)[3]) {
        const ScalarType tx = element.properties[m_layout.x].type;
        const ScalarType ty = element.properties[m_layout.y].type;
        const ScalarType tz = element.properties[m_layout.z].type;
        const std::byte* record = m_pos;
        for (Vec3& vertex : m_mesh.vertices) {
            vertex = Vec3(load_double<Swap>(tx, record + offsets[0]),
                          load_double<Swap>(ty, record + offsets[1]),
                          load_double<Swap>(tz, record + offsets[2]));
            record += stride;
        }
    }

    void read_listed_vertices(const Element& element) {
        m_mesh.vertices.reserve(std::min<std::uint64_t>(element.count, remaining()));
        for (std::uint64_t item = 0; item < element.count; ++item) {
            Vec3 vertex = Vec3::Zero();
            const auto on_scalar = [&](std::size_t p, const std::byte* at) {
                const ScalarType type = element.properties[p].type;
                const int index = static_cast<int>(p);
                if (index == m_layout.x) vertex.x() = load_double<Swap>(type, at);
                if (index == m_layout.y) vertex.y() = load_double<Swap>(type, at);
                if (index == m_layout.z) vertex.z() = load_double<Swap>(type, at);
            };
            walk_item(element, item, on_scalar, [](std::size_t, std::int64_t, const std::byte*) {});
            m_mesh.vertices.push_back(vertex);
        }
    }

    void read_faces(const Element& element) {
        const Property& list = element.properties[m_layout.corners];
        m_mesh.triangles.reserve(std::min<std::uint64_t>(element.count, remaining() / 4));
        const bool single = element.properties.size() == 1;
        const bool byte_count =
            list.count_type == ScalarType::UInt8 || list.count_type == ScalarType::Int8;
        if (single && byte_count && list.type == ScalarType::Int32) {
            read_simple_faces<std::int32_t>(element);
        } else if (single && byte_count && list.type == ScalarType::UInt32) {
            read_simple_faces<std::uint32_t>(element);
        } else {
            read_general_faces(element);
        }
    }

    // Faces that hold nothing but "count (1 byte) + 32-bit indices": the common layout.
    template <class Index>
    void read_simple_faces(const Element& element) {
        const bool signed_count = element.properties[0].count_type == ScalarType::Int8;
        std::vector<std::uint32_t> corners;
        for (std::uint64_t face = 0; face < element.count; ++face) {
            const std::byte* count_at = take(1, element, face);
            const std::int64_t count = signed_count ? load<std::int8_t, Swap>(count_at)
                                                    : load<std::uint8_t, Swap>(count_at);
            if (count < 3) too_few_corners(face, count);
            const std::byte* at = take(static_cast<std::uint64_t>(count) * 4, element, face);
            if (count == 3) {
                m_mesh.triangles.push_back({corner(load<Index, Swap>(at), face),
                                            corner(load<Index, Swap>(at + 4), face),
                                            corner(load<Index, Swap>(at + 8), face)});
                continue;
            }
            corners.resize(static_cast<std::size_t>(count));
            for (std::size_t c = 0; c < corners.size(); ++c) {
                corners[c] = corner(load<Index, Swap>(at + 4 * c), face);
            }
            append_fan(corners, m_mesh.triangles);
        }
    }

    void read_general_faces(const Element& element) {
        const std::size_t list_index = static_cast<std::size_t>(m_layout.corners);
        const ScalarType index_type = element.properties[list_index].type;
        const std::size_t index_size = scalar_size(index_type);
        std::vector<std::uint32_t> corners;
        for (std::uint64_t face = 0; face < element.count; ++face) {
            const auto on_list = [&](std::size_t p, std::int64_t count, const std::byte* at) {
                if (p != list_index) return;
                if (count < 3) too_few_corners(face, count);
                corners.resize(static_cast<std::size_t>(count));
                for (std::size_t c = 0; c < corners.size(); ++c) {
                    corners[c] = corner(load_integer<Swap>(index_type, at + index_size * c), face);
                }
                append_fan(corners, m_mesh.triangles);
            };
            walk_item(element, face, [](std::size_t, const std::byte*) {}, on_list);
        }
    }

    std::uint32_t corner(std::int64_t index, std::uint64_t face) const {
        return checked_corner(index, m_limit, m_source, face);
    }

    [[noreturn]] void too_few_corners(std::uint64_t face, std::int64_t count) const {
        throw_item_error(m_source, "face", face,
                         std::to_string(count) + " corners (a face needs at least 3)");
    }

    const std::byte* m_pos;
    const std::byte* m_end;
    std::size_t m_body_size;
    std::uint64_t m_body_offset = 0;  ///< where the body starts in the file (after end_header)
    const Layout& m_layout;
    MeshData& m_mesh;
    std::string_view m_source;
    CornerLimit m_limit;
};

}  // namespace

void read_binary_body(std::span<const std::byte> body, const Header& header, const Layout& layout,
                      MeshData& mesh, std::string_view source) {
    const bool file_little = header.format == Format::BinaryLittleEndian;
    const bool host_little = std::endian::native == std::endian::little;
    if (file_little == host_little) {
        BinaryBody<false>(body, layout, mesh, source).read(header);
    } else {
        BinaryBody<true>(body, layout, mesh, source).read(header);
    }
}

}  // namespace collidescope::ply
