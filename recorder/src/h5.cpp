// Thin RAII over the HDF5 C API.

#include "h5.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/schema.hpp"


namespace collidescope::recorder::h5 {

void silence() {
    // Per thread: a thread-safe HDF5 (Debian's is) keeps the error stack, and whether it
    // prints, per thread; the recorder's writer thread printed HDF5-DIAG pages on a full disk.
    thread_local bool silenced = false;
    if (silenced) return;
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    silenced = true;
}

namespace {

// HDF5 1.10.8 crashes in its atexit handler (H5F__close_cb, from H5_term_library) once closing
// a file has failed, as on a full disk: measured, `record` printed its error line and then
// died of SIGSEGV at exit. Every file here is closed by its owner (RAII) before exit, so the
// handler has nothing left to do; it must be switched off before the library initialises.
const bool g_no_atexit_handler = [] {
    H5dont_atexit();
    return true;
}();

herr_t keep_description(unsigned, const H5E_error2_t* error, void* data) {
    if (error->desc != nullptr && error->desc[0] != '\0') *static_cast<std::string*>(data) = error->desc;
    return 0;
}

}  // namespace

herr_t collect_dataset(hid_t, const char* name, const H5O_info_t* info, void* data) {
    if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(data)->push_back(std::string("/") + name);
    return 0;
}

std::string error_detail() {
    // Walked from the API call down: the last description kept is the innermost one.
    std::string detail;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, keep_description, &detail);
    return detail;
}

Id& Id::operator=(Id&& other) noexcept {
    if (this != &other) {
        reset();
        m_id = other.m_id;
        m_closer = other.m_closer;
        other.m_id = -1;
    }
    return *this;
}

bool Id::reset() {
    bool ok = true;
    if (m_id >= 0 && m_closer != nullptr) ok = m_closer(m_id) >= 0;
    m_id = -1;
    return ok;
}

void Where::fail(const std::string& what) const { throw InputError(m_file + ": " + what); }

Id Where::own(hid_t id, Id::Closer closer, const std::string& what) const {
    if (id < 0) fail(what);
    return Id(id, closer);
}

void Where::check(herr_t status, const std::string& what) const {
    if (status < 0) fail(what);
}

void keep_compact(const Where& where, hid_t plist, const std::string& what) {
    // Links and attributes stay in the object header (checksummed in the latest format) instead
    // of "dense" storage in a fractal heap, whose blocks carry no checksum by default: HDF5
    // 1.10.8 frees a garbage pointer iterating a group whose dense link storage is corrupt
    // (tests/recorder/test_corruption.cpp found it).
    where.check(H5Pset_link_phase_change(plist, k_max_compact, k_max_compact), "cannot keep the links of " + what + " compact");
    where.check(H5Pset_attr_phase_change(plist, k_max_compact, k_max_compact), "cannot keep the attributes of " + what + " compact");
}

Id open_group(const Where& where, hid_t loc, const std::string& name) {
    return where.own(H5Gopen2(loc, name.c_str(), H5P_DEFAULT), H5Gclose, "cannot open group " + name);
}

Id create_group(const Where& where, hid_t loc, const std::string& name) {
    const Id plist = where.own(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "cannot create a property list");
    // Track creation order, so readers list stages and counts in the engine's order.
    where.check(H5Pset_link_creation_order(plist.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
                "cannot set creation order on " + name);
    keep_compact(where, plist.get(), name);
    return where.own(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, plist.get(), H5P_DEFAULT), H5Gclose,
                     "cannot create group " + name);
}

Id open_dataset(const Where& where, hid_t loc, const std::string& name) {
    if (!exists(loc, name)) where.fail("missing dataset " + name + " (not a complete collidescope recording)");
    return where.own(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, "cannot open dataset " + name);
}

bool exists(hid_t loc, const std::string& path) {
    // H5Lexists needs every intermediate link to exist: walk the path.
    std::string prefix;
    std::size_t start = path.front() == '/' ? 1 : 0;
    if (start == 1) prefix = "/";
    while (start <= path.size()) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        prefix += path.substr(start, end - start);
        if (H5Lexists(loc, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
        prefix += '/';
        start = end + 1;
    }
    return true;
}

namespace {

herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* data) {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
}

}  // namespace

std::vector<std::string> member_names(const Where& where, hid_t group, const std::string& what) {
    std::vector<std::string> names;
    hsize_t index = 0;
    // Creation order when the group tracks it (ours do), else names.
    if (H5Literate(group, H5_INDEX_CRT_ORDER, H5_ITER_INC, &index, collect_name, &names) < 0) {
        names.clear();
        index = 0;
        where.check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &index, collect_name, &names),
                    "cannot list " + what);
    }
    return names;
}

void write_attr(const Where& where, hid_t obj, const std::string& name, const std::string& value) {
    // Fixed length, null-terminated (schema 1.2): a variable-length string lives in the global
    // heap, which has no checksum, and HDF5 1.10.8 can crash reading a corrupt one.
    const Id type = where.own(H5Tcopy(H5T_C_S1), H5Tclose, "cannot make a string type");
    where.check(H5Tset_size(type.get(), value.size() + 1), "cannot make a string type");
    where.check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), "cannot make a string type");
    where.check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot make a string type");
    const Id space = where.own(H5Screate(H5S_SCALAR), H5Sclose, "cannot make a dataspace");
    const Id attr = where.own(H5Acreate2(obj, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                              H5Aclose, "cannot create attribute " + name);
    where.check(H5Awrite(attr.get(), type.get(), value.c_str()), "cannot write attribute " + name);
}

void write_attr(const Where& where, hid_t obj, const std::string& name, std::int64_t value) {
    const Id space = where.own(H5Screate(H5S_SCALAR), H5Sclose, "cannot make a dataspace");
    const Id attr = where.own(H5Acreate2(obj, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                              H5Aclose, "cannot create attribute " + name);
    where.check(H5Awrite(attr.get(), H5T_NATIVE_INT64, &value), "cannot write attribute " + name);
}

void write_attr(const Where& where, hid_t obj, const std::string& name, double value) {
    const Id space = where.own(H5Screate(H5S_SCALAR), H5Sclose, "cannot make a dataspace");
    const Id attr = where.own(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                              H5Aclose, "cannot create attribute " + name);
    where.check(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value), "cannot write attribute " + name);
}

bool has_attr(hid_t obj, const std::string& name) { return H5Aexists(obj, name.c_str()) > 0; }

std::optional<std::string> read_string_attr(const Where& where, hid_t obj, const std::string& name) {
    if (!has_attr(obj, name)) return std::nullopt;
    const Id attr = where.own(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open attribute " + name);
    const Id type = where.own(H5Aget_type(attr.get()), H5Tclose, "cannot read attribute " + name);
    if (H5Tget_class(type.get()) != H5T_STRING) where.fail("attribute " + name + " is not a string");
    const Id space = where.own(H5Aget_space(attr.get()), H5Sclose, "cannot read attribute " + name);
    if (H5Sget_simple_extent_npoints(space.get()) != 1) where.fail("attribute " + name + " is not a scalar");
    // Same character set as the file's type: HDF5 does not convert between ASCII and UTF-8.
    const Id mem = where.own(H5Tcopy(type.get()), H5Tclose, "cannot make a string type");
    if (H5Tis_variable_str(type.get()) > 0) {
        char* text = nullptr;
        where.check(H5Aread(attr.get(), mem.get(), &text), "cannot read attribute " + name);
        std::string value = text != nullptr ? text : "";
        H5free_memory(text);
        return value;
    }
    const std::size_t size = H5Tget_size(type.get());
    if (size == 0 || size > (1u << 20)) where.fail("attribute " + name + " has a bad size");
    where.check(H5Tset_size(mem.get(), size + 1), "cannot make a string type");
    where.check(H5Tset_strpad(mem.get(), H5T_STR_NULLTERM), "cannot make a string type");
    std::string value(size + 1, '\0');
    where.check(H5Aread(attr.get(), mem.get(), value.data()), "cannot read attribute " + name);
    value.resize(value.find('\0'));
    return value;
}

std::optional<std::int64_t> read_int_attr(const Where& where, hid_t obj, const std::string& name) {
    if (!has_attr(obj, name)) return std::nullopt;
    const Id attr = where.own(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open attribute " + name);
    const Id type = where.own(H5Aget_type(attr.get()), H5Tclose, "cannot read attribute " + name);
    const Id space = where.own(H5Aget_space(attr.get()), H5Sclose, "cannot read attribute " + name);
    if (H5Tget_class(type.get()) != H5T_INTEGER || H5Sget_simple_extent_npoints(space.get()) != 1) {
        where.fail("attribute " + name + " is not an integer scalar");
    }
    std::int64_t value = 0;
    where.check(H5Aread(attr.get(), H5T_NATIVE_INT64, &value), "cannot read attribute " + name);
    return value;
}

Id create_extensible(const Where& where, hid_t loc, const std::string& path, const ExtensibleSpec& spec) {
    const int rank = spec.width == 1 ? 1 : 2;
    const hsize_t dims[2] = {0, spec.width};
    const hsize_t max_dims[2] = {H5S_UNLIMITED, spec.width};
    const hsize_t chunk[2] = {spec.chunk_rows, spec.width};
    const Id space = where.own(H5Screate_simple(rank, dims, max_dims), H5Sclose, "cannot make a dataspace");
    const Id plist = where.own(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "cannot create a property list");
    where.check(H5Pset_chunk(plist.get(), rank, chunk), "cannot set chunks of " + path);
    if (spec.deflate > 0) {
        where.check(H5Pset_shuffle(plist.get()), "cannot set shuffle on " + path);
        where.check(H5Pset_deflate(plist.get(), static_cast<unsigned>(spec.deflate)), "cannot set deflate on " + path);
    }
    Id dataset = where.own(H5Dcreate2(loc, path.c_str(), spec.file_type, space.get(), H5P_DEFAULT, plist.get(),
                                      H5P_DEFAULT),
                           H5Dclose, "cannot create dataset " + path);
    write_attr(where, dataset.get(), schema::k_attr_unit, std::string(spec.unit));
    return dataset;
}

namespace {

/// Rank (1 or 2) and dims (dims[1] = 1 for rank 1) of a dataset's current extent, in `space`.
struct Extent {
    Id space;
    int rank = 0;
    hsize_t dims[2] = {0, 1};
};

Extent extent_of(const Where& where, hid_t dataset, const std::string& path) {
    Extent extent;
    extent.space = where.own(H5Dget_space(dataset), H5Sclose, "cannot read the shape of " + path);
    extent.rank = H5Sget_simple_extent_ndims(extent.space.get());
    if (extent.rank < 1 || extent.rank > 2 || H5Sget_simple_extent_dims(extent.space.get(), extent.dims, nullptr) < 0) {
        where.fail("cannot read the shape of " + path);
    }
    return extent;
}

}  // namespace

void extend(const Where& where, hid_t dataset, const std::string& path, hsize_t rows) {
    const hsize_t new_dims[2] = {rows, extent_of(where, dataset, path).dims[1]};
    where.check(H5Dset_extent(dataset, new_dims), "cannot extend " + path);
}

void write_rows(const Where& where, hid_t dataset, const std::string& path, hsize_t first, hid_t mem_type, hsize_t rows,
                const void* data) {
    if (rows == 0) return;
    const Extent file = extent_of(where, dataset, path);
    const hsize_t start[2] = {first, 0};
    const hsize_t count[2] = {rows, file.dims[1]};
    where.check(H5Sselect_hyperslab(file.space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
                "cannot select rows of " + path);
    const Id mem_space = where.own(H5Screate_simple(file.rank, count, nullptr), H5Sclose, "cannot make a dataspace");
    where.check(H5Dwrite(dataset, mem_type, mem_space.get(), file.space.get(), H5P_DEFAULT, data),
                "cannot write " + path);
}

void append_rows(const Where& where, hid_t dataset, const std::string& path, hsize_t& length, hid_t mem_type,
                 hsize_t rows, const void* data) {
    if (rows == 0) return;
    extend(where, dataset, path, length + rows);
    write_rows(where, dataset, path, length, mem_type, rows, data);
    length += rows;
}

void write_encoded_chunk(const Where& where, hid_t dataset, const std::string& path, hsize_t first,
                         std::span<const unsigned char> encoded) {
    const hsize_t offset[2] = {first, 0};
    where.check(H5Dwrite_chunk(dataset, H5P_DEFAULT, 0, offset, encoded.size(), encoded.data()), "cannot write " + path);
}

std::vector<hsize_t> shape(const Where& where, hid_t dataset, const std::string& path) {
    const Id space = where.own(H5Dget_space(dataset), H5Sclose, "cannot read the shape of " + path);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0 || rank > 8) where.fail("cannot read the shape of " + path);
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    if (rank > 0) where.check(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), "cannot read the shape of " + path);
    return dims;
}

void read_rows(const Where& where, hid_t dataset, const std::string& path, hid_t mem_type, hsize_t first,
               hsize_t rows, void* out) {
    if (rows == 0) return;
    const Id file_space = where.own(H5Dget_space(dataset), H5Sclose, "cannot read the shape of " + path);
    const int rank = H5Sget_simple_extent_ndims(file_space.get());
    hsize_t dims[2] = {0, 1};
    if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(file_space.get(), dims, nullptr) < 0) {
        where.fail("unexpected shape of " + path);
    }
    if (first + rows > dims[0]) where.fail(path + ": rows " + std::to_string(first) + ".." +
                                           std::to_string(first + rows - 1) + " out of range (" +
                                           std::to_string(dims[0]) + " rows)");
    const hsize_t start[2] = {first, 0};
    const hsize_t count[2] = {rows, dims[1]};
    where.check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
                "cannot select rows of " + path);
    const Id mem_space = where.own(H5Screate_simple(rank, count, nullptr), H5Sclose, "cannot make a dataspace");
    where.check(H5Dread(dataset, mem_type, mem_space.get(), file_space.get(), H5P_DEFAULT, out),
                "cannot read " + path + " (corrupt or truncated file?)");
}

std::optional<double> read_double_attr(const Where& where, hid_t obj, const std::string& name) {
    if (!has_attr(obj, name)) return std::nullopt;
    const Id attr = where.own(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open attribute " + name);
    const Id type = where.own(H5Aget_type(attr.get()), H5Tclose, "cannot read attribute " + name);
    const Id space = where.own(H5Aget_space(attr.get()), H5Sclose, "cannot read attribute " + name);
    const H5T_class_t type_class = H5Tget_class(type.get());
    if ((type_class != H5T_FLOAT && type_class != H5T_INTEGER) || H5Sget_simple_extent_npoints(space.get()) != 1) {
        where.fail("attribute " + name + " is not a numeric scalar");
    }
    double value = 0;
    where.check(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value), "cannot read attribute " + name);
    return value;
}

}  // namespace collidescope::recorder::h5
