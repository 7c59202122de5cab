#pragma once
// The copying side of `join` (join_recordings.cpp plans it): attributes copied generically,
// dataset rows copied as raw chunks where they line up, through HDF5 elsewhere.

#include "h5.hpp"

#include <cstdint>
#include <string>
#include <utility>
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

/// Appends rows of part datasets, in order, to one extensible chunked dataset of the output,
/// writing whole chunks itself: chunks of a part that line up with the output's are copied raw
/// (H5Dread_chunk / H5Dwrite_chunk, still compressed); other rows are read through HDF5 and
/// gathered into the output's chunks, each encoded once when full (or at the end) with the
/// recorder's own shuffle + deflate encoder (chunk_codec.hpp) or stored as is when the dataset
/// is not filtered. A dataset with another filter pipeline or chunk shape goes through HDF5's
/// own writes.
class RowAppender {
public:
    RowAppender(const h5::Where& where, hid_t target, std::string path);
    /// Rows [first, first + rows) of `source`; `last`: nothing is appended after them (so a
    /// partly filled final chunk may be copied raw).
    void append(const h5::Where& source_where, hid_t source, hsize_t first, hsize_t rows, bool last);
    /// Writes the final, partly filled chunk (zero-padded, as the recorder writes one).
    void finish();
    const CopyCount& count() const { return m_count; }

private:
    enum class Encoding { shuffle_deflate, none, hdf5 };
    void write_pending();
    /// Encodes the full chunks waiting in m_full, one thread each, and writes them.
    void write_full();
    /// Raw copies of the source's whole chunks from `first`; returns the rows copied.
    hsize_t copy_raw_chunks(const h5::Where& source_where, hid_t source, hsize_t first, hsize_t rows, bool last);

    const h5::Where& m_where;
    hid_t m_target;
    std::string m_path;
    Encoding m_encoding = Encoding::hdf5;
    int m_level = 0;
    hsize_t m_chunk = 0;             ///< rows per chunk of the target
    std::size_t m_row_bytes = 0;
    std::size_t m_element_bytes = 0;
    h5::Id m_type;                   ///< the target's file type (read and written unconverted)
    h5::Id m_dcpl;
    hsize_t m_rows = 0;              ///< rows appended so far
    std::vector<unsigned char> m_pending;  ///< rows of the chunk being filled, from its first row
    std::vector<unsigned char> m_encoded;
    /// Full chunks waiting to be encoded (first row, raw bytes): as many as there are
    /// hardware threads, then encoded together.
    std::vector<std::pair<hsize_t, std::vector<unsigned char>>> m_full;
    std::size_t m_threads = 1;
    CopyCount m_count;
};

}  // namespace collidescope::recorder::join
