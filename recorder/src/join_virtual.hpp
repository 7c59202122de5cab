#pragma once
// The virtual side of `join` (join_recordings.cpp plans it): a dataset of the output whose rows
// are mappings onto the parts' rows (HDF5 virtual datasets, H5Pset_virtual), nothing copied.

#include "h5.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::recorder::join {

/// One part's rows of a dataset, in output order.
struct VirtualPiece {
    std::string file;       ///< source_name() of the part
    hsize_t begin = 0;      ///< first row of the part's dataset
    hsize_t end = 0;        ///< one past the last
    hsize_t part_rows = 0;  ///< the part dataset's length
};

/// The name a virtual dataset of `output` stores for part file `part`: relative to the
/// output's directory (so the output and its parts move together), absolute when no relative
/// path exists; '%' doubled (HDF5 reads source names as printf-like patterns).
std::string source_name(const std::filesystem::path& part, const std::filesystem::path& output);

/// Creates `path` in `out`: a fixed-size virtual dataset of file type `type`, `width` columns
/// (`rank` 1 or 2), whose rows are the pieces' rows in order; the source dataset in each part
/// is `path` too.
h5::Id create_virtual(const h5::Where& where, hid_t out, const std::string& path, hid_t type, int rank, hsize_t width,
                      const std::vector<VirtualPiece>& pieces);

}  // namespace collidescope::recorder::join
