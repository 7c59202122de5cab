#pragma once
// Virtual datasets (a virtual join, `join --virtual`, docs/how-to/mpi.md): where their rows live, and
// the check that every part file they map is there. HDF5 reads the rows of a missing or
// unreadable source as the fill value (zeros) without an error, so every reader of ours lists
// and checks the sources when it opens a recording, and the join refuses a virtual file as a
// part (H5Dread_chunk does not work on a virtual layout, and its mappings name files relative
// to it).

#include "h5.hpp"

#include "collidescope/recorder/recording_info.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::recorder::virtual_sources {

/// True when `dataset` has the virtual layout (H5D_VIRTUAL).
bool is_virtual(hid_t dataset);

/// Every mapping of every virtual dataset of `file` (opened from where.file()), in the file's
/// order, `resolved` filled in where the source file is found ("" where not).
std::vector<VirtualSource> list(const h5::Where& where, hid_t file);

/// Where HDF5 1.10 opens source file `name` (as stored: "%%" for "%") of a virtual dataset in
/// the file at `recording` (H5F_prefix_open_file): an absolute name as is; then each directory
/// of HDF5_VDS_PREFIX (':'-separated); then the recording's own directory, as opened. HDF5
/// then also tries `name` relative to the current directory, which could read another run's
/// parts: that is not followed here, so such a file counts as missing. "" when not found.
std::filesystem::path resolve(const std::filesystem::path& recording, const std::string& name);

/// Fails (one line naming the part file and the dataset) unless every source was found, opens
/// as HDF5 and holds its dataset with at least the rows its mapping reads.
void check(const h5::Where& where, const std::vector<VirtualSource>& sources);

}  // namespace collidescope::recorder::virtual_sources
