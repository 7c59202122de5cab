// parse_obj: the project's own OBJ reader.
//
// Why not assimp: its OBJ importer makes one vertex per face corner (the Stanford bunny
// comes out with 208,998 vertices instead of 34,835), and aiProcess_JoinIdenticalVertices
// merges by position, which is not the file's indexing. Pair indices and the self-collision
// rule need the file's own vertex order and sharing, so OBJ is read here: `v` and `f`
// records only, numbers through std::from_chars.

#include "mesh/fan.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <charconv>
#include <limits>

namespace collidescope {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Splits one line into whitespace-separated tokens, one at a time.
class Tokens {
public:
    explicit Tokens(std::string_view line) : m_line(line) {}

    /// The next token, or an empty view at the end of the line.
    std::string_view next() {
        while (m_pos < m_line.size() && is_blank(m_line[m_pos])) ++m_pos;
        const std::size_t start = m_pos;
        while (m_pos < m_line.size() && !is_blank(m_line[m_pos])) ++m_pos;
        return m_line.substr(start, m_pos - start);
    }

private:
    std::string_view m_line;
    std::size_t m_pos = 0;
};

class ObjParser {
public:
    explicit ObjParser(std::string_view source) : m_source(source) {}

    MeshData parse(std::string_view text) {
        m_mesh.vertices.reserve(text.size() / 64);
        m_mesh.triangles.reserve(text.size() / 32);
        std::size_t pos = 0;
        while (pos < text.size()) {
            std::size_t end = text.find('\n', pos);
            if (end == std::string_view::npos) end = text.size();
            ++m_line;
            parse_line(text.substr(pos, end - pos));
            pos = end + 1;
        }
        return std::move(m_mesh);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(std::string(m_source) + ": line " + std::to_string(m_line) + ": " + what);
    }

    void parse_line(std::string_view line) {
        Tokens tokens(line);
        const std::string_view keyword = tokens.next();
        if (keyword == "v") {
            parse_vertex(tokens);
        } else if (keyword == "f") {
            parse_face(tokens);
        }
        // Everything else (vt, vn, vp, o, g, s, usemtl, mtllib, l, p, comments) is ignored.
    }

    double parse_coordinate(std::string_view token) const {
        if (token.empty()) fail("vertex needs 3 coordinates");
        std::string_view digits = token;
        if (digits.size() > 1 && digits[0] == '+') digits.remove_prefix(1);
        double value = 0;
        const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
            fail("bad number '" + std::string(token) + "'");
        }
        return value;
    }

    // `v x y z [w]`: w (and the colours some exporters append) is ignored.
    void parse_vertex(Tokens& tokens) {
        const double x = parse_coordinate(tokens.next());
        const double y = parse_coordinate(tokens.next());
        const double z = parse_coordinate(tokens.next());
        m_mesh.vertices.emplace_back(x, y, z);
    }

    // One corner: `v`, `v/vt`, `v//vn` or `v/vt/vn`; negative v counts back from the last vertex.
    std::uint32_t parse_corner(std::string_view token) const {
        std::int64_t index = 0;
        const auto result = std::from_chars(token.data(), token.data() + token.size(), index);
        const bool rest_ok = result.ptr == token.data() + token.size() || *result.ptr == '/';
        if (result.ec != std::errc() || !rest_ok) fail("bad face corner '" + std::string(token) + "'");
        const std::int64_t count = static_cast<std::int64_t>(m_mesh.vertices.size());
        if (index == 0) fail("vertex index 0 (OBJ indices start at 1)");
        const std::int64_t resolved = index > 0 ? index - 1 : count + index;
        if (resolved < 0 || resolved >= count) {
            fail("vertex index " + std::to_string(index) + " out of range (" + std::to_string(count) +
                 " vertices defined before this line)");
        }
        return static_cast<std::uint32_t>(resolved);
    }

    void parse_face(Tokens& tokens) {
        m_corners.clear();
        for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
            m_corners.push_back(parse_corner(token));
        }
        if (m_corners.size() < 3) {
            fail("face with " + std::to_string(m_corners.size()) + " corners (a face needs at least 3)");
        }
        append_fan(m_corners, m_mesh.triangles);
    }

    std::string_view m_source;
    MeshData m_mesh;
    std::vector<std::uint32_t> m_corners;
    std::uint64_t m_line = 0;
};

}  // namespace

MeshData parse_obj(std::string_view text, std::string_view source) {
    MeshData mesh = ObjParser(source).parse(text);
    if (mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw InputError(std::string(source) + ": too many vertices");
    }
    return mesh;
}

}  // namespace collidescope
