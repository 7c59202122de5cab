#pragma once
// The copying side of `join` (join_recordings.cpp plans it): attributes copied generically,
// dataset rows copied as raw chunks where they line up, through HDF5 elsewhere.

#include "h5.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace collidescope::recorder::join {

/// One attribute read whatever its type: raw bytes in the file's type, or the text of a
/// variable-length string (schema 1.0 and 1.1 files).
struct Attribute {
    std::string name;
    h5::Id type;
    h5::Id space;
    std::vector<unsigned char> bytes;
    bool variable_string = false;
    std::string text;  ///< the variable-length string's value
};

/// Every attribute of `object`, in the file's order.
std::vector<Attribute> read_attributes(const h5::Where& where, hid_t object, const std::string& what);
/// Same type, shape and value.
bool same_value(const Attribute& a, const Attribute& b);
/// Writes `attribute` on `object` (a variable-length string becomes a fixed-length one).
void write_attribute(const h5::Where& where, hid_t object, const Attribute& attribute);

/// What the rows of one dataset copy did.
struct CopyCount {
    std::uint64_t raw_chunks = 0;
    std::uint64_t raw_bytes = 0;
    std::uint64_t rewritten_rows = 0;
};

/// Rows [first, first + rows) of `source` (an extensible dataset) to rows [at, at + rows) of
/// `target` (extended to at + rows). Where both start on a chunk boundary and the two datasets
/// have the same creation properties (chunk shape, filters), whole chunks are copied raw;
/// `last` lets the final, partly filled chunk go raw too (nothing is appended after it).
CopyCount copy_rows(const h5::Where& source_where, hid_t source, const h5::Where& target_where, hid_t target,
                    const std::string& path, hsize_t first, hsize_t rows, hsize_t at, bool last);

}  // namespace collidescope::recorder::join
