#pragma once
// A tiny animated model written by the tests (through assimp's exporter, as .assbin, which
// keeps every value as given): a two-triangle quad skinned to one bone that rises along z,
// so every pose is known exactly, and broken variants for the bad-input tests.

#include <filesystem>

namespace collidescope::testing {

struct TinyRigOptions {
    bool nan_key = false;        ///< the bone's second position key is NaN
    bool zero_weights = false;   ///< every bone weight is 0
    bool unknown_bone = false;   ///< the bone names a node that does not exist
    bool second_clip = false;    ///< adds a clip "idle" (one key, at rest) after "rise"
};

/// Writes the rig to `file` (.assbin). The quad: vertices (0,0,0) (1,0,0) (1,1,0) (0,1,0) and a
/// fifth vertex at (1,1,0) again (a seam split: the weld makes it vertex 2), triangles
/// (0,1,2) and (0,4,3), all weighted 1 to bone "arm". Clip "rise": 10 ticks at 10 ticks per
/// second, the bone's position (0,0,0) at tick 0 and (0,0,2) at tick 10: z = 2 t for t in
/// [0, 1] seconds. Node "body" holds the mesh (unnamed once read back: assbin drops mesh
/// names); "arm" is its sibling; the root is "root".
void write_tiny_rig(const std::filesystem::path& file, const TinyRigOptions& options = {});

}  // namespace collidescope::testing
