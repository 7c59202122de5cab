#pragma once
// The PLY header: format, elements and their properties (engine/src/mesh, private).
//
// The header is plain text up to "end_header"; the body that follows is ascii or binary.
// This header describes the body so the readers can walk it without strings in their loops.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace collidescope::ply {

/// Scalar types of PLY properties (both the old "int" and the sized "int32" spellings map here).
enum class ScalarType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// Size in bytes of one scalar of `type` in a binary body.
std::size_t scalar_size(ScalarType type);

/// True for Float32 and Float64.
bool is_floating(ScalarType type);

/// One property of an element: a scalar, or a list (a count followed by that many values).
struct Property {
    std::string name;
    ScalarType type = ScalarType::Float32;  ///< the scalar, or the list's item type
    bool is_list = false;
    ScalarType count_type = ScalarType::UInt8;  ///< the list's count type (lists only)
};

/// One element ("vertex", "face", or anything else) with its item count.
struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;

    /// Index of the property named `name`, or -1.
    int find(std::string_view property_name) const;
    /// True when no property is a list, so every item has the same binary size.
    bool fixed_size() const;
    /// Binary size of one item; only meaningful when fixed_size().
    std::size_t item_size() const;
};

/// How the body is encoded.
enum class Format : std::uint8_t { Ascii, BinaryLittleEndian, BinaryBigEndian };

/// A parsed header plus where the body starts.
struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    std::size_t body_offset = 0;  ///< byte offset of the first body byte
    int body_line = 1;            ///< line number of the first body line (ascii messages)
};

/// Parses the header at the start of `bytes`. Throws InputError naming `source` and the
/// header line on malformed input.
Header parse_header(std::span<const std::byte> bytes, std::string_view source);

}  // namespace collidescope::ply
