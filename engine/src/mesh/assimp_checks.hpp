#pragma once
// What read_with_assimp checks around assimp (engine/src/mesh, private).
//
// assimp trusts its inputs more than we may: some importers allocate what a header declares
// before reading it (an OFF file that declares 353 billion vertices in 309 bytes runs for
// minutes), some hand back scenes with null pointers (the RAW importer leaves a null child
// node), and one prints to std::cerr (the OpenGEX parser). So: counts are checked against the
// file's size before assimp sees the file, the scene is checked before anything walks it, and
// std::cerr is silenced while assimp runs (the library never prints).

#include <filesystem>

struct aiScene;
namespace Assimp {
class Importer;
}

namespace collidescope {

/// Before importing: refuses a header whose counts the file's size cannot hold (OFF, also
/// gzipped; other formats pass). Throws InputError naming the file and the count.
void check_counts_fit(const std::filesystem::path& file);

/// After importing: every pointer a reader follows is non-null where its count says there
/// are elements (meshes, vertices, faces and their indices, bones and weights, morph targets,
/// nodes and their children and mesh references, animations and their channels and keys),
/// node mesh references are in range and the node graph is a tree. Throws InputError
/// "FILE: assimp returned a broken scene: ELEMENT ...".
void validate_assimp_scene(const aiScene& scene, const std::filesystem::path& file);

/// Imports `file` (a `.gz` gunzipped first) with every check above: counts before assimp
/// allocates, std::cerr silent while it parses, the scene validated before it is returned.
/// The scene lives as long as `importer`. Throws InputError naming the file.
const aiScene& import_checked(Assimp::Importer& importer, const std::filesystem::path& file);

/// Silences std::cerr while it lives (assimp's bundled OpenDDL parser writes to it). Guards
/// nest and may live on several threads; the stream is restored when the last one ends.
class QuietCerr {
public:
    QuietCerr();
    ~QuietCerr();
    QuietCerr(const QuietCerr&) = delete;
    QuietCerr& operator=(const QuietCerr&) = delete;
};

}  // namespace collidescope
