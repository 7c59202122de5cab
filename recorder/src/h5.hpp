#pragma once
// Thin RAII over the HDF5 C API. Every failure becomes an InputError whose message starts with
// the file's path and names the object ("run.h5: cannot read /collisions/pairs"). HDF5's own
// error stack printing is switched off (silence()), so the library never prints.

#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace collidescope::recorder::h5 {

/// Turns off HDF5's automatic error stack printing for the calling thread (idempotent).
void silence();

/// The innermost description on the calling thread's HDF5 error stack (what the failed call
/// found, e.g. "truncated file: eof = 1000, sblock->base_addr = 0, stored_eof = 2000"); ""
/// when the stack is empty.
std::string error_detail();

/// An H5Ovisit2 callback that appends each dataset's path ("/" + name) to the
/// std::vector<std::string> that `data` points to.
herr_t collect_dataset(hid_t, const char* name, const H5O_info_t* info, void* data);

/// Owns one hid_t and closes it with the matching H5*close.
class Id {
public:
    using Closer = herr_t (*)(hid_t);
    Id() = default;
    Id(hid_t id, Closer closer) : m_id(id), m_closer(closer) {}
    ~Id() { reset(); }
    Id(Id&& other) noexcept : m_id(other.m_id), m_closer(other.m_closer) { other.m_id = -1; }
    Id& operator=(Id&& other) noexcept;
    Id(const Id&) = delete;
    Id& operator=(const Id&) = delete;

    hid_t get() const { return m_id; }
    bool valid() const { return m_id >= 0; }
    /// Closes now; returns false when the close failed (a write that could not be flushed).
    bool reset();

private:
    hid_t m_id = -1;
    Closer m_closer = nullptr;
};

/// Error context: the file's path, prefixed to every message.
class Where {
public:
    explicit Where(std::string file) : m_file(std::move(file)) {}
    const std::string& file() const { return m_file; }
    /// Throws InputError("<file>: <what>").
    [[noreturn]] void fail(const std::string& what) const;
    /// Returns `id` owned, or fails with `what` when it is negative.
    Id own(hid_t id, Id::Closer closer, const std::string& what) const;
    /// Fails with `what` when `status` is negative.
    void check(herr_t status, const std::string& what) const;

private:
    std::string m_file;
};

/// Links or attributes an object keeps in its (checksummed) header before moving them to dense
/// storage (a fractal heap without checksums).
inline constexpr unsigned k_max_compact = 1000;
/// Sets both phase changes of a group or file creation property list to k_max_compact.
void keep_compact(const Where& where, hid_t plist, const std::string& what);

Id open_group(const Where& where, hid_t loc, const std::string& name);
Id create_group(const Where& where, hid_t loc, const std::string& name);
Id open_dataset(const Where& where, hid_t loc, const std::string& name);
bool exists(hid_t loc, const std::string& path);
/// Names of the members of group `group`, in creation order where tracked, else by name.
std::vector<std::string> member_names(const Where& where, hid_t group, const std::string& what);

// Attributes: strings are written fixed-length, null-terminated UTF-8 (read: both kinds);
// numbers scalar.
void write_attr(const Where& where, hid_t obj, const std::string& name, const std::string& value);
void write_attr(const Where& where, hid_t obj, const std::string& name, std::int64_t value);
void write_attr(const Where& where, hid_t obj, const std::string& name, double value);
bool has_attr(hid_t obj, const std::string& name);
/// Reads a string attribute (variable or fixed length); nullopt when absent.
std::optional<std::string> read_string_attr(const Where& where, hid_t obj, const std::string& name);
/// Reads an integer attribute converted to int64; nullopt when absent.
std::optional<std::int64_t> read_int_attr(const Where& where, hid_t obj, const std::string& name);
/// Reads a numeric (float or integer) scalar attribute as double; nullopt when absent.
std::optional<double> read_double_attr(const Where& where, hid_t obj, const std::string& name);

/// Layout of an extensible dataset: `width` columns (1 = a 1-D dataset), rows growing.
struct ExtensibleSpec {
    hid_t file_type = -1;            ///< e.g. H5T_STD_U32LE
    hsize_t width = 1;               ///< columns per row; 1 makes the dataset 1-D
    hsize_t chunk_rows = 256;        ///< rows per chunk
    int deflate = 0;                 ///< gzip level 1-9 (with shuffle); 0 = uncompressed
    const char* unit = nullptr;      ///< the `unit` attribute, required
};

/// Creates an empty extensible dataset `path` (rank 1 or 2) with its unit attribute.
Id create_extensible(const Where& where, hid_t loc, const std::string& path, const ExtensibleSpec& spec);

/// Appends `rows` rows of `mem_type` values (row-major, width per row) to a dataset whose
/// current length is `length`; updates `length`.
void append_rows(const Where& where, hid_t dataset, const std::string& path, hsize_t& length, hid_t mem_type,
                 hsize_t rows, const void* data);

/// Sets the length (rows) of an extensible dataset.
void extend(const Where& where, hid_t dataset, const std::string& path, hsize_t rows);
/// Writes `rows` rows of `mem_type` values at row `first` (inside the current extent).
void write_rows(const Where& where, hid_t dataset, const std::string& path, hsize_t first, hid_t mem_type, hsize_t rows,
                const void* data);
/// Writes the chunk that starts at row `first` (a multiple of the chunk rows, inside the
/// extent), already encoded with the dataset's own filters (all applied), via H5Dwrite_chunk.
void write_encoded_chunk(const Where& where, hid_t dataset, const std::string& path, hsize_t first,
                         std::span<const unsigned char> encoded);

/// Shape of a dataset (dims), failing with the path named.
std::vector<hsize_t> shape(const Where& where, hid_t dataset, const std::string& path);

/// Reads rows [first, first + rows) of a 1-D or 2-D dataset as `mem_type` into `out`, which
/// must hold rows * width values.
void read_rows(const Where& where, hid_t dataset, const std::string& path, hid_t mem_type, hsize_t first,
               hsize_t rows, void* out);

}  // namespace collidescope::recorder::h5
