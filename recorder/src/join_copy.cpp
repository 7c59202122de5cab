// Copying attributes and dataset rows between recordings (join).

#include "join_copy.hpp"

#include "chunk_codec.hpp"

#include <algorithm>
#include <exception>
#include <span>
#include <thread>

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

RowAppender::RowAppender(const h5::Where& where, hid_t target, std::string path)
    : m_where(where), m_target(target), m_path(std::move(path)) {
    const Layout layout = layout_of(where, target, m_path);
    m_type = where.own(H5Dget_type(target), H5Tclose, "cannot read the type of " + m_path);
    m_dcpl = where.own(H5Dget_create_plist(target), H5Pclose, "cannot read the layout of " + m_path);
    m_element_bytes = H5Tget_size(m_type.get());
    m_row_bytes = m_element_bytes * layout.dims[1];
    m_chunk = chunk_rows_of(m_dcpl.get());
    m_threads = std::max(1u, std::thread::hardware_concurrency());
    hsize_t chunk[2] = {0, 0};
    const bool whole_rows = m_chunk > 0 && (layout.rank == 1 || (H5Pget_chunk(m_dcpl.get(), 2, chunk) == 2 && chunk[1] == layout.dims[1]));
    if (!whole_rows) return;  // HDF5's writes
    const int filters = H5Pget_nfilters(m_dcpl.get());
    if (filters == 0) {
        m_encoding = Encoding::none;
    } else if (filters == 2) {
        unsigned flags = 0, values[8] = {};
        std::size_t count = 8;
        const H5Z_filter_t first = H5Pget_filter2(m_dcpl.get(), 0, &flags, &count, values, 0, nullptr, nullptr);
        count = 8;
        const H5Z_filter_t second = H5Pget_filter2(m_dcpl.get(), 1, &flags, &count, values, 0, nullptr, nullptr);
        if (first == H5Z_FILTER_SHUFFLE && second == H5Z_FILTER_DEFLATE && count >= 1 && values[0] >= 1 && values[0] <= 9) {
            m_encoding = Encoding::shuffle_deflate;
            m_level = static_cast<int>(values[0]);
        }
    }
}

hsize_t RowAppender::copy_raw_chunks(const h5::Where& source_where, hid_t source, hsize_t first, hsize_t rows, bool last) {
    const h5::Id source_dcpl = source_where.own(H5Dget_create_plist(source), H5Pclose, "cannot read the layout of " + m_path);
    if (m_chunk == 0 || !m_pending.empty() || first % m_chunk != 0 || m_rows % m_chunk != 0 ||
        H5Pequal(source_dcpl.get(), m_dcpl.get()) <= 0) {
        return 0;
    }
    std::vector<unsigned char> buffer;
    hsize_t done = 0;
    for (; done < rows && (done + m_chunk <= rows || last); done += m_chunk) {
        const hsize_t from[2] = {first + done, 0};
        const hsize_t to[2] = {m_rows + done, 0};
        hsize_t bytes = 0;
        // An unallocated chunk reads as the fill value in both files: nothing to copy.
        if (H5Dget_chunk_storage_size(source, from, &bytes) < 0 || bytes == 0) continue;
        buffer.resize(bytes);
        std::uint32_t filters = 0;
        source_where.check(H5Dread_chunk(source, H5P_DEFAULT, from, &filters, buffer.data()),
                           "cannot read a chunk of " + m_path + " (corrupt or truncated file?)");
        m_where.check(H5Dwrite_chunk(m_target, H5P_DEFAULT, filters, to, bytes, buffer.data()),
                      "cannot write a chunk of " + m_path);
        ++m_count.raw_chunks;
        m_count.raw_bytes += bytes;
    }
    return std::min(done, rows);
}

void RowAppender::append(const h5::Where& source_where, hid_t source, hsize_t first, hsize_t rows, bool last) {
    if (rows == 0) return;
    const Layout layout = layout_of(source_where, source, m_path);
    if (first + rows > layout.dims[0]) {
        source_where.fail(m_path + ": " + std::to_string(first + rows) + " rows needed, " +
                          std::to_string(layout.dims[0]) + " present");
    }
    h5::extend(m_where, m_target, m_path, m_rows + rows);
    const hsize_t raw = copy_raw_chunks(source_where, source, first, rows, last);
    m_rows += raw;
    // The rest read through HDF5 (decoded), in blocks of whole target chunks of about 32 MiB,
    // in the file's own type (no conversion).
    const hsize_t unit = std::max<hsize_t>(m_chunk, 1);
    const hsize_t block = std::max<hsize_t>(unit, (hsize_t{32} << 20) / std::max<std::size_t>(m_row_bytes, 1) / unit * unit);
    std::vector<unsigned char> buffer;
    for (hsize_t row = raw; row < rows;) {
        const hsize_t n = std::min(block, rows - row);
        buffer.resize(n * m_row_bytes);
        h5::read_rows(source_where, source, m_path, m_type.get(), first + row, n, buffer.data());
        m_count.rewritten_rows += n;
        if (m_encoding == Encoding::hdf5) {
            h5::write_rows(m_where, m_target, m_path, m_rows, m_type.get(), n, buffer.data());
            m_rows += n;
        } else {
            // Into the chunk being filled; each chunk written once, when full.
            const std::size_t chunk_bytes = m_chunk * m_row_bytes;
            for (std::size_t at = 0; at < buffer.size();) {
                const std::size_t take = std::min(chunk_bytes - m_pending.size(), buffer.size() - at);
                m_pending.insert(m_pending.end(), buffer.begin() + static_cast<std::ptrdiff_t>(at),
                                 buffer.begin() + static_cast<std::ptrdiff_t>(at + take));
                at += take;
                m_rows += take / m_row_bytes;
                if (m_pending.size() == chunk_bytes) {
                    if (m_encoding == Encoding::shuffle_deflate) {
                        m_full.emplace_back(m_rows - m_chunk, std::move(m_pending));
                        m_pending = {};
                        if (m_full.size() >= m_threads) write_full();
                    } else {
                        write_pending();
                    }
                }
            }
        }
        row += n;
    }
}

void RowAppender::write_pending() {
    if (m_pending.empty()) return;
    const std::size_t chunk_bytes = m_chunk * m_row_bytes;
    const hsize_t pending_rows = m_pending.size() / m_row_bytes;
    const hsize_t offset[2] = {m_rows - pending_rows, 0};
    if (m_encoding == Encoding::shuffle_deflate) {
        encode_shuffle_deflate(std::as_bytes(std::span<const unsigned char>(m_pending)), m_element_bytes, m_level, m_encoded,
                               chunk_bytes);
    } else {
        m_encoded.assign(m_pending.begin(), m_pending.end());
        m_encoded.resize(chunk_bytes, 0);
    }
    m_where.check(H5Dwrite_chunk(m_target, H5P_DEFAULT, 0, offset, m_encoded.size(), m_encoded.data()),
                  "cannot write a chunk of " + m_path);
    m_pending.clear();
}

void RowAppender::write_full() {
    if (m_full.empty()) return;
    const std::size_t chunk_bytes = m_chunk * m_row_bytes;
    std::vector<std::vector<unsigned char>> encoded(m_full.size());
    std::vector<std::exception_ptr> errors(m_full.size());
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < m_full.size(); ++i) {
        threads.emplace_back([&, i] {
            try {
                encode_shuffle_deflate(std::as_bytes(std::span<const unsigned char>(m_full[i].second)), m_element_bytes, m_level,
                                       encoded[i], chunk_bytes);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        });
    }
    for (std::thread& thread : threads) thread.join();
    for (const std::exception_ptr& error : errors) {
        if (error) std::rethrow_exception(error);
    }
    for (std::size_t i = 0; i < m_full.size(); ++i) {
        const hsize_t offset[2] = {m_full[i].first, 0};
        m_where.check(H5Dwrite_chunk(m_target, H5P_DEFAULT, 0, offset, encoded[i].size(), encoded[i].data()),
                      "cannot write a chunk of " + m_path);
    }
    m_full.clear();
}

void RowAppender::finish() {
    write_full();
    write_pending();
}

}  // namespace collidescope::recorder::join
