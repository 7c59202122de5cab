// PLY header parsing: a few dozen short text lines, so clarity wins over speed here.

#include "mesh/ply_header.hpp"

#include "collidescope/error.hpp"

#include <array>
#include <charconv>
#include <optional>

namespace collidescope::ply {
namespace {

struct TypeName {
    std::string_view name;
    ScalarType type;
};

// Both spellings of the PLY scalar types (Greg Turk's original and the sized ones).
constexpr std::array<TypeName, 16> k_type_names = {{
    {"char", ScalarType::Int8},     {"int8", ScalarType::Int8},
    {"uchar", ScalarType::UInt8},   {"uint8", ScalarType::UInt8},
    {"short", ScalarType::Int16},   {"int16", ScalarType::Int16},
    {"ushort", ScalarType::UInt16}, {"uint16", ScalarType::UInt16},
    {"int", ScalarType::Int32},     {"int32", ScalarType::Int32},
    {"uint", ScalarType::UInt32},   {"uint32", ScalarType::UInt32},
    {"float", ScalarType::Float32}, {"float32", ScalarType::Float32},
    {"double", ScalarType::Float64}, {"float64", ScalarType::Float64},
}};

std::optional<ScalarType> type_from_name(std::string_view name) {
    for (const TypeName& entry : k_type_names) {
        if (entry.name == name) return entry.type;
    }
    return std::nullopt;
}

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t pos = 0;
    while (pos < line.size()) {
        const std::size_t start = line.find_first_not_of(" \t\r", pos);
        if (start == std::string_view::npos) break;
        std::size_t end = line.find_first_of(" \t\r", start);
        if (end == std::string_view::npos) end = line.size();
        words.push_back(line.substr(start, end - start));
        pos = end;
    }
    return words;
}

// Reads the header line by line, keeping the line number for messages.
class HeaderParser {
public:
    HeaderParser(std::string_view text, std::string_view source) : m_text(text), m_source(source) {}

    Header parse() {
        Header header;
        expect_magic();
        bool has_format = false;
        while (true) {
            const std::vector<std::string_view> words = split_words(next_line());
            if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
            if (words[0] == "end_header") break;
            if (words[0] == "format") {
                header.format = parse_format(words);
                has_format = true;
            } else if (words[0] == "element") {
                header.elements.push_back(parse_element(words));
            } else if (words[0] == "property") {
                if (header.elements.empty()) fail("property before any element");
                header.elements.back().properties.push_back(parse_property(words));
            } else {
                fail("unknown header keyword '" + std::string(words[0]) +
                     "' (expected format, element, property, comment, obj_info or end_header)");
            }
        }
        if (!has_format) fail("no format line");
        header.body_offset = m_pos;
        header.body_line = m_line + 1;
        return header;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(std::string(m_source) + ": header line " + std::to_string(m_line) + ": " +
                         what);
    }

    std::string_view next_line() {
        if (m_pos >= m_text.size()) fail("file ends before end_header");
        std::size_t end = m_text.find('\n', m_pos);
        if (end == std::string_view::npos) end = m_text.size();
        const std::string_view line = m_text.substr(m_pos, end - m_pos);
        m_pos = end < m_text.size() ? end + 1 : end;
        ++m_line;
        return line;
    }

    void expect_magic() {
        const std::vector<std::string_view> words = split_words(next_line());
        if (words.size() != 1 || words[0] != "ply") fail("not a PLY file (no 'ply' magic)");
    }

    Format parse_format(const std::vector<std::string_view>& words) const {
        if (words.size() != 3) fail("malformed format line");
        if (words[1] == "ascii") return Format::Ascii;
        if (words[1] == "binary_little_endian") return Format::BinaryLittleEndian;
        if (words[1] == "binary_big_endian") return Format::BinaryBigEndian;
        fail("unknown format '" + std::string(words[1]) + "'");
    }

    Element parse_element(const std::vector<std::string_view>& words) const {
        if (words.size() != 3) fail("malformed element line");
        Element element;
        element.name = std::string(words[1]);
        const std::string_view count = words[2];
        const auto result = std::from_chars(count.data(), count.data() + count.size(), element.count);
        if (result.ec != std::errc() || result.ptr != count.data() + count.size()) {
            fail("bad element count '" + std::string(count) + "'");
        }
        return element;
    }

    ScalarType parse_type(std::string_view name) const {
        const std::optional<ScalarType> type = type_from_name(name);
        if (!type) fail("unknown property type '" + std::string(name) + "'");
        return *type;
    }

    Property parse_property(const std::vector<std::string_view>& words) const {
        Property property;
        if (words.size() == 5 && words[1] == "list") {
            property.is_list = true;
            property.count_type = parse_type(words[2]);
            if (is_floating(property.count_type)) fail("list count type must be an integer");
            property.type = parse_type(words[3]);
            property.name = std::string(words[4]);
        } else if (words.size() == 3) {
            property.type = parse_type(words[1]);
            property.name = std::string(words[2]);
        } else {
            fail("malformed property line");
        }
        return property;
    }

    std::string_view m_text;
    std::string_view m_source;
    std::size_t m_pos = 0;
    int m_line = 0;
};

}  // namespace

std::size_t scalar_size(ScalarType type) {
    switch (type) {
        case ScalarType::Int8:
        case ScalarType::UInt8: return 1;
        case ScalarType::Int16:
        case ScalarType::UInt16: return 2;
        case ScalarType::Int32:
        case ScalarType::UInt32:
        case ScalarType::Float32: return 4;
        case ScalarType::Float64: return 8;
    }
    return 0;
}

bool is_floating(ScalarType type) {
    return type == ScalarType::Float32 || type == ScalarType::Float64;
}

int Element::find(std::string_view property_name) const {
    for (std::size_t i = 0; i < properties.size(); ++i) {
        if (properties[i].name == property_name) return static_cast<int>(i);
    }
    return -1;
}

bool Element::fixed_size() const {
    for (const Property& property : properties) {
        if (property.is_list) return false;
    }
    return true;
}

std::size_t Element::item_size() const {
    std::size_t size = 0;
    for (const Property& property : properties) size += scalar_size(property.type);
    return size;
}

Header parse_header(std::span<const std::byte> bytes, std::string_view source) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    return HeaderParser(text, source).parse();
}

}  // namespace collidescope::ply
