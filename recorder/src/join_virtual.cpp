// Virtual datasets over the parts' rows (join_virtual.hpp).

#include "join_virtual.hpp"

namespace collidescope::recorder::join {

namespace fs = std::filesystem;

std::string source_name(const fs::path& part, const fs::path& output) {
    std::error_code error;
    // Physical paths on both sides (fs::relative resolves symlinks), as the kernel resolves
    // "dir/../x" and as HDF5 builds the output's directory from getcwd().
    fs::path name = fs::relative(part, fs::absolute(output, error).parent_path(), error);
    if (error || name.empty()) name = fs::absolute(part, error);
    std::string escaped;
    for (const char c : name.string()) escaped += c == '%' ? std::string("%%") : std::string(1, c);
    return escaped;
}

h5::Id create_virtual(const h5::Where& where, hid_t out, const std::string& path, hid_t type, int rank, hsize_t width,
                      const std::vector<VirtualPiece>& pieces) {
    hsize_t total = 0;
    for (const VirtualPiece& piece : pieces) total += piece.end - piece.begin;
    const h5::Id dcpl = where.own(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "cannot create a property list");
    const hsize_t dims[2] = {total, width};
    hsize_t at = 0;
    for (const VirtualPiece& piece : pieces) {
        const hsize_t rows = piece.end - piece.begin;
        if (rows == 0) continue;
        const h5::Id vspace = where.own(H5Screate_simple(rank, dims, nullptr), H5Sclose, "cannot make a dataspace");
        const hsize_t part_dims[2] = {piece.part_rows, width};
        const h5::Id sspace = where.own(H5Screate_simple(rank, part_dims, nullptr), H5Sclose, "cannot make a dataspace");
        const hsize_t count[2] = {rows, width};
        const hsize_t to[2] = {at, 0};
        const hsize_t from[2] = {piece.begin, 0};
        where.check(H5Sselect_hyperslab(vspace.get(), H5S_SELECT_SET, to, nullptr, count, nullptr), "cannot select rows of " + path);
        where.check(H5Sselect_hyperslab(sspace.get(), H5S_SELECT_SET, from, nullptr, count, nullptr), "cannot select rows of " + path);
        where.check(H5Pset_virtual(dcpl.get(), vspace.get(), piece.file.c_str(), path.c_str(), sspace.get()),
                    "cannot map " + path + " onto " + piece.file);
        at += rows;
    }
    const h5::Id space = where.own(H5Screate_simple(rank, dims, nullptr), H5Sclose, "cannot make a dataspace");
    return where.own(H5Dcreate2(out, path.c_str(), type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT), H5Dclose,
                     "cannot create virtual dataset " + path);
}

}  // namespace collidescope::recorder::join
