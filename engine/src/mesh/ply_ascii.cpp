// Ascii PLY bodies: a stream of whitespace-separated numbers, item after item.
//
// Properties declared float are parsed straight to float32 (as a binary file would hold
// them), double and integer ones to double; numbers use std::from_chars.

#include "mesh/fan.hpp"
#include "mesh/ply_body.hpp"

#include "collidescope/error.hpp"

#include <charconv>

namespace collidescope::ply {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

class AsciiBody {
public:
    AsciiBody(std::string_view text, int first_line, const Layout& layout, MeshData& mesh,
              std::string_view source)
        : m_text(text), m_line(first_line), m_layout(layout), m_mesh(mesh), m_source(source) {}

    void read(const Header& header) {
        for (std::size_t e = 0; e < header.elements.size(); ++e) {
            const Element& element = header.elements[e];
            if (static_cast<int>(e) == m_layout.vertex_element) {
                read_vertices(element);
            } else if (static_cast<int>(e) == m_layout.face_element) {
                read_faces(element);
            } else if (!element.properties.empty()) {
                // An element without properties takes no text: skipping its items one by one
                // would loop `count` times (up to 2^64) over nothing.
                for (std::uint64_t item = 0; item < element.count; ++item) skip_item(element, item);
            }
        }
    }

private:
    [[noreturn]] void fail(const Element& element, std::uint64_t item, const std::string& what) const {
        throw_item_error(m_source, element.name, item, what + " (line " + std::to_string(m_line) + ")");
    }

    std::string_view next_token(const Element& element, std::uint64_t item) {
        while (m_pos < m_text.size() && is_space(m_text[m_pos])) {
            if (m_text[m_pos] == '\n') ++m_line;
            ++m_pos;
        }
        if (m_pos >= m_text.size()) {
            fail(element, item, "file truncated: expected " + std::to_string(element.count) + " " + element.name +
                                    " items, the file ends inside this one");
        }
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !is_space(m_text[m_pos])) ++m_pos;
        return m_text.substr(start, m_pos - start);
    }

    template <class T>
    T parse_number(const Element& element, std::uint64_t item) {
        std::string_view token = next_token(element, item);
        const std::string_view original = token;
        if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
        T value{};
        const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
        if (result.ec != std::errc() || result.ptr != token.data() + token.size()) {
            fail(element, item, "bad number '" + std::string(original) + "'");
        }
        return value;
    }

    double parse_coordinate(ScalarType type, const Element& element, std::uint64_t item) {
        if (type == ScalarType::Float32) return parse_number<float>(element, item);
        return parse_number<double>(element, item);
    }

    std::int64_t parse_count(const Element& element, std::uint64_t item) {
        const std::int64_t count = parse_number<std::int64_t>(element, item);
        if (count < 0) fail(element, item, "negative list length " + std::to_string(count));
        // Each value takes at least one character: a longer list cannot fit in the rest.
        if (static_cast<std::uint64_t>(count) > m_text.size() - m_pos) {
            fail(element, item, "file truncated: a list of " + std::to_string(count) + " values does not fit in the " +
                                    std::to_string(m_text.size() - m_pos) + " bytes left");
        }
        return count;
    }

    void skip_item(const Element& element, std::uint64_t item) {
        for (const Property& property : element.properties) {
            const std::int64_t count = property.is_list ? parse_count(element, item) : 1;
            for (std::int64_t i = 0; i < count; ++i) next_token(element, item);
        }
    }

    void read_vertices(const Element& element) {
        m_mesh.vertices.reserve(std::min<std::uint64_t>(element.count, m_text.size() / 2));
        for (std::uint64_t item = 0; item < element.count; ++item) {
            Vec3 vertex = Vec3::Zero();
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const Property& property = element.properties[p];
                const int index = static_cast<int>(p);
                const int axis = index == m_layout.x ? 0 : index == m_layout.y ? 1
                                                         : index == m_layout.z ? 2 : -1;
                if (axis >= 0) {
                    vertex[axis] = parse_coordinate(property.type, element, item);
                    continue;
                }
                const std::int64_t count = property.is_list ? parse_count(element, item) : 1;
                for (std::int64_t i = 0; i < count; ++i) next_token(element, item);
            }
            m_mesh.vertices.push_back(vertex);
        }
        m_limit = {m_mesh.vertices.size(), true};
    }

    void read_faces(const Element& element) {
        m_mesh.triangles.reserve(std::min<std::uint64_t>(element.count, m_text.size() / 8));
        for (std::uint64_t face = 0; face < element.count; ++face) {
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const Property& property = element.properties[p];
                const std::int64_t count = property.is_list ? parse_count(element, face) : 1;
                if (static_cast<int>(p) == m_layout.corners) {
                    read_corners(element, face, count);
                    continue;
                }
                for (std::int64_t i = 0; i < count; ++i) next_token(element, face);
            }
        }
    }

    void read_corners(const Element& element, std::uint64_t face, std::int64_t count) {
        if (count < 3) {
            fail(element, face, std::to_string(count) + " corners (a face needs at least 3)");
        }
        m_corners.resize(static_cast<std::size_t>(count));
        for (std::uint32_t& corner : m_corners) {
            corner = checked_corner(parse_number<std::int64_t>(element, face), m_limit, m_source,
                                    face);
        }
        append_fan(m_corners, m_mesh.triangles);
    }

    std::string_view m_text;
    std::size_t m_pos = 0;
    int m_line;
    const Layout& m_layout;
    MeshData& m_mesh;
    std::string_view m_source;
    CornerLimit m_limit;
    std::vector<std::uint32_t> m_corners;
};

}  // namespace

void read_ascii_body(std::string_view body, const Header& header, const Layout& layout,
                     MeshData& mesh, std::string_view source) {
    AsciiBody(body, header.body_line, layout, mesh, source).read(header);
}

}  // namespace collidescope::ply
