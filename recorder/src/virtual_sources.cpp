// Virtual datasets' sources: listed, resolved as HDF5 resolves them, checked (virtual_sources.hpp).

#include "virtual_sources.hpp"

#include <cstdlib>
#include <map>

namespace collidescope::recorder::virtual_sources {
namespace {

namespace fs = std::filesystem;

// A string property of mapping `i` (H5Pget_virtual_filename or _dsetname).
template <class Get>
std::string mapping_text(Get get, hid_t dcpl, std::size_t i) {
    const ssize_t size = get(dcpl, i, nullptr, 0);
    if (size < 0) return "";
    std::string text(static_cast<std::size_t>(size) + 1, '\0');
    get(dcpl, i, text.data(), text.size());
    text.resize(static_cast<std::size_t>(size));
    return text;
}

// First row and rows of a selection's bounds in its first dimension.
std::pair<std::uint64_t, std::uint64_t> row_bounds(hid_t space) {
    hsize_t start[H5S_MAX_RANK] = {}, end[H5S_MAX_RANK] = {};
    if (H5Sget_select_npoints(space) <= 0 || H5Sget_select_bounds(space, start, end) < 0) return {0, 0};
    return {start[0], end[0] - start[0] + 1};
}

// "%%" -> "%": source names are printf-like patterns in HDF5 (H5Pset_virtual).
std::string unescape(const std::string& name) {
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i) {
        out += name[i];
        if (name[i] == '%' && i + 1 < name.size() && name[i + 1] == '%') ++i;
    }
    return out;
}

bool is_file(const fs::path& path) {
    std::error_code error;
    return fs::is_regular_file(path, error);
}

void mapping_sources(const h5::Where& where, hid_t file, const std::string& path, std::vector<VirtualSource>& out) {
    const h5::Id dataset = h5::open_dataset(where, file, path);
    if (!is_virtual(dataset.get())) return;
    const h5::Id dcpl = where.own(H5Dget_create_plist(dataset.get()), H5Pclose, "cannot read the layout of " + path);
    std::size_t count = 0;
    where.check(H5Pget_virtual_count(dcpl.get(), &count), "cannot read the mappings of virtual dataset " + path);
    for (std::size_t i = 0; i < count; ++i) {
        VirtualSource source;
        source.dataset = path;
        source.file = mapping_text(H5Pget_virtual_filename, dcpl.get(), i);
        source.source_dataset = mapping_text(H5Pget_virtual_dsetname, dcpl.get(), i);
        const h5::Id vspace = where.own(H5Pget_virtual_vspace(dcpl.get(), i), H5Sclose, "cannot read a mapping of " + path);
        const h5::Id sspace = where.own(H5Pget_virtual_srcspace(dcpl.get(), i), H5Sclose, "cannot read a mapping of " + path);
        std::tie(source.first, source.rows) = row_bounds(vspace.get());
        source.source_first = row_bounds(sspace.get()).first;
        source.resolved = resolve(where.file(), source.file).string();
        out.push_back(std::move(source));
    }
}

}  // namespace

bool is_virtual(hid_t dataset) {
    const hid_t dcpl = H5Dget_create_plist(dataset);
    if (dcpl < 0) return false;
    const bool result = H5Pget_layout(dcpl) == H5D_VIRTUAL;
    H5Pclose(dcpl);
    return result;
}

std::vector<VirtualSource> list(const h5::Where& where, hid_t file) {
    std::vector<std::string> datasets;
    where.check(H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_NATIVE, h5::collect_dataset, &datasets, H5O_INFO_BASIC),
                "cannot list the datasets");
    std::vector<VirtualSource> sources;
    for (const std::string& path : datasets) mapping_sources(where, file, path, sources);
    return sources;
}

fs::path resolve(const fs::path& recording, const std::string& stored) {
    const fs::path name = unescape(stored);
    fs::path tail = name;
    if (name.is_absolute()) {
        if (is_file(name)) return name;
        tail = name.filename();  // HDF5 then searches for the last component alone
    }
    if (const char* prefixes = std::getenv("HDF5_VDS_PREFIX"); prefixes != nullptr) {
        std::string list = prefixes;
        for (std::size_t at = 0; at <= list.size();) {
            const std::size_t colon = std::min(list.find(':', at), list.size());
            const std::string prefix = list.substr(at, colon - at);
            if (!prefix.empty() && is_file(fs::path(prefix) / tail)) return fs::path(prefix) / tail;
            at = colon + 1;
        }
    }
    std::error_code error;
    const fs::path beside = fs::absolute(recording, error).parent_path() / tail;
    if (!error && is_file(beside)) return beside;
    return {};
}

void check(const h5::Where& where, const std::vector<VirtualSource>& sources) {
    std::map<std::string, h5::Id> opened;  // each part file opened once
    for (const VirtualSource& source : sources) {
        const std::string mapped = source.dataset + " maps rows of " + source.file;
        if (source.resolved.empty()) {
            where.fail(mapped + ", which is missing (a virtual join reads its parts: keep them beside it, at that relative path)");
        }
        auto found = opened.find(source.resolved);
        if (found == opened.end()) {
            hid_t id = H5Fopen(source.resolved.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, H5P_DEFAULT);
            if (id < 0) id = H5Fopen(source.resolved.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
            if (id < 0) where.fail(mapped + ", which is unreadable (" + source.resolved + ": not an HDF5 file, or corrupt)");
            found = opened.emplace(source.resolved, h5::Id(id, H5Fclose)).first;
        }
        const hid_t part = found->second.get();
        if (!h5::exists(part, source.source_dataset)) {
            where.fail(mapped + ", which has no dataset " + source.source_dataset + " (not that run's part?)");
        }
        const h5::Where part_where(source.resolved);
        const h5::Id dataset = h5::open_dataset(part_where, part, source.source_dataset);
        const std::vector<hsize_t> dims = h5::shape(part_where, dataset.get(), source.source_dataset);
        const std::uint64_t held = dims.empty() ? 0 : dims[0];
        if (held < source.source_first + source.rows) {
            where.fail(mapped + ", which holds " + std::to_string(held) + " rows of " + source.source_dataset + ", not the " +
                       std::to_string(source.source_first + source.rows) + " the mapping reads (truncated or replaced part?)");
        }
    }
}

}  // namespace collidescope::recorder::virtual_sources
