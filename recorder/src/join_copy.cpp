// Copying attributes and dataset rows between recordings (join).

#include "join_copy.hpp"

#include <algorithm>

namespace collidescope::recorder::join {
namespace {

herr_t collect_attribute_name(hid_t, const char* name, const H5A_info_t*, void* data) {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
}

struct Layout {
    int rank = 0;
    hsize_t dims[2] = {0, 1};
};

Layout layout_of(const h5::Where& where, hid_t dataset, const std::string& path) {
    const std::vector<hsize_t> dims = h5::shape(where, dataset, path);
    if (dims.empty() || dims.size() > 2) where.fail(path + ": not a 1-D or 2-D dataset");
    Layout layout;
    layout.rank = static_cast<int>(dims.size());
    for (std::size_t d = 0; d < dims.size(); ++d) layout.dims[d] = dims[d];
    return layout;
}

/// Rows per chunk, 0 when the dataset is not chunked.
hsize_t chunk_rows_of(hid_t dcpl) {
    if (H5Pget_layout(dcpl) != H5D_CHUNKED) return 0;
    hsize_t chunk[2] = {0, 0};
    if (H5Pget_chunk(dcpl, 2, chunk) < 1) return 0;
    return chunk[0];
}

}  // namespace

std::vector<Attribute> read_attributes(const h5::Where& where, hid_t object, const std::string& what) {
    std::vector<std::string> names;
    hsize_t index = 0;
    // Native order: the order of creation for the compact storage the recorder keeps.
    where.check(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_NATIVE, &index, collect_attribute_name, &names),
                "cannot list the attributes of " + what);
    std::vector<Attribute> attributes;
    for (const std::string& name : names) {
        Attribute attribute;
        attribute.name = name;
        const h5::Id attr = where.own(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose,
                                      "cannot open attribute " + name + " of " + what);
        attribute.type = where.own(H5Aget_type(attr.get()), H5Tclose, "cannot read attribute " + name + " of " + what);
        attribute.space = where.own(H5Aget_space(attr.get()), H5Sclose, "cannot read attribute " + name + " of " + what);
        if (H5Tis_variable_str(attribute.type.get()) > 0) {
            attribute.variable_string = true;
            attribute.text = h5::read_string_attr(where, object, name).value_or("");
        } else {
            const H5T_class_t type_class = H5Tget_class(attribute.type.get());
            if (type_class == H5T_VLEN || type_class == H5T_REFERENCE || H5Tdetect_class(attribute.type.get(), H5T_VLEN) > 0) {
                where.fail("attribute " + name + " of " + what + " has a variable-length type join cannot copy");
            }
            const hssize_t points = H5Sget_simple_extent_npoints(attribute.space.get());
            const std::size_t size = H5Tget_size(attribute.type.get());
            if (points < 0 || size == 0) where.fail("cannot read attribute " + name + " of " + what);
            attribute.bytes.resize(static_cast<std::size_t>(points) * size);
            where.check(H5Aread(attr.get(), attribute.type.get(), attribute.bytes.data()),
                        "cannot read attribute " + name + " of " + what);
        }
        attributes.push_back(std::move(attribute));
    }
    return attributes;
}

bool same_value(const Attribute& a, const Attribute& b) {
    if (a.variable_string || b.variable_string) return a.variable_string == b.variable_string && a.text == b.text;
    return H5Tequal(a.type.get(), b.type.get()) > 0 && H5Sextent_equal(a.space.get(), b.space.get()) > 0 &&
           a.bytes == b.bytes;
}

void write_attribute(const h5::Where& where, hid_t object, const Attribute& attribute) {
    if (attribute.variable_string) {
        h5::write_attr(where, object, attribute.name, attribute.text);
        return;
    }
    const h5::Id attr = where.own(H5Acreate2(object, attribute.name.c_str(), attribute.type.get(), attribute.space.get(),
                                             H5P_DEFAULT, H5P_DEFAULT),
                                  H5Aclose, "cannot create attribute " + attribute.name);
    where.check(H5Awrite(attr.get(), attribute.type.get(), attribute.bytes.data()),
                "cannot write attribute " + attribute.name);
}

CopyCount copy_rows(const h5::Where& source_where, hid_t source, const h5::Where& target_where, hid_t target,
                    const std::string& path, hsize_t first, hsize_t rows, hsize_t at, bool last) {
    CopyCount count;
    if (rows == 0) return count;
    const Layout layout = layout_of(source_where, source, path);
    if (first + rows > layout.dims[0]) {
        source_where.fail(path + ": " + std::to_string(first + rows) + " rows needed, " +
                          std::to_string(layout.dims[0]) + " present");
    }
    h5::extend(target_where, target, path, at + rows);

    const h5::Id source_dcpl = source_where.own(H5Dget_create_plist(source), H5Pclose, "cannot read the layout of " + path);
    const h5::Id target_dcpl = target_where.own(H5Dget_create_plist(target), H5Pclose, "cannot read the layout of " + path);
    const hsize_t chunk = chunk_rows_of(target_dcpl.get());
    hsize_t done = 0;
    if (chunk > 0 && first % chunk == 0 && at % chunk == 0 && H5Pequal(source_dcpl.get(), target_dcpl.get()) > 0) {
        std::vector<unsigned char> buffer;
        for (; done < rows && (done + chunk <= rows || last); done += chunk) {
            const hsize_t from[2] = {first + done, 0};
            const hsize_t to[2] = {at + done, 0};
            hsize_t bytes = 0;
            // An unallocated chunk reads as the fill value in both files: nothing to copy.
            if (H5Dget_chunk_storage_size(source, from, &bytes) < 0 || bytes == 0) continue;
            buffer.resize(bytes);
            std::uint32_t filters = 0;
            source_where.check(H5Dread_chunk(source, H5P_DEFAULT, from, &filters, buffer.data()),
                               "cannot read a chunk of " + path + " (corrupt or truncated file?)");
            target_where.check(H5Dwrite_chunk(target, H5P_DEFAULT, filters, to, bytes, buffer.data()),
                               "cannot write a chunk of " + path);
            ++count.raw_chunks;
            count.raw_bytes += bytes;
        }
        done = std::min(done, rows);
    }
    if (done == rows) return count;

    // The rest through HDF5 (decoded and encoded again), in blocks of whole target chunks of
    // about 32 MiB, read and written in the file's own type (no conversion).
    const h5::Id type = source_where.own(H5Dget_type(source), H5Tclose, "cannot read the type of " + path);
    const std::size_t row_bytes = H5Tget_size(type.get()) * layout.dims[1];
    const hsize_t unit = std::max<hsize_t>(chunk, 1);
    const hsize_t block = std::max<hsize_t>(unit, (hsize_t{32} << 20) / std::max<std::size_t>(row_bytes, 1) / unit * unit);
    std::vector<unsigned char> buffer;
    for (hsize_t row = done; row < rows;) {
        const hsize_t n = std::min(block, rows - row);
        buffer.resize(n * row_bytes);
        h5::read_rows(source_where, source, path, type.get(), first + row, n, buffer.data());
        h5::write_rows(target_where, target, path, at + row, type.get(), n, buffer.data());
        count.rewritten_rows += n;
        row += n;
    }
    return count;
}

}  // namespace collidescope::recorder::join
