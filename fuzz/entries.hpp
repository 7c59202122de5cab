#pragma once
// One fuzz input through one reader, exactly as the app reads it (fuzz/, docs/how-to/fuzzing.md).
//
// Each entry returns Accepted when the input was read, Rejected when the library threw
// InputError (the expected answer to bad input); anything else (another exception, a crash,
// a sanitizer report, an HDF5 id left open) escapes, so libFuzzer reports it. The gcc test
// suite runs the same entries over the committed corpus and regression inputs
// (tests/fuzz/test_fuzz_inputs.cpp).

#include <cstddef>
#include <span>
#include <string_view>

namespace collidescope::fuzz {

enum class Outcome { Accepted, Rejected };

/// parse_ply then validate_mesh, as read_mesh_file does for a .ply file.
Outcome read_ply(std::span<const std::byte> bytes);
/// parse_obj then validate_mesh, as read_mesh_file does for a .obj file.
Outcome read_obj(std::span<const std::byte> bytes);
/// The bytes as a scene.json manifest beside a few small frame files (scene_entry.cpp);
/// open_inputs, then every frame read.
Outcome read_scene(std::span<const std::byte> bytes);
/// The bytes as a recording: what `inspect`, `validate` and `replay` read from it.
Outcome read_recording(std::span<const std::byte> bytes);
/// The bytes as a point cache file (.pc2 when they start with "POINTCACHE2", else .mdd):
/// PointCacheReader's header check, then every frame read.
Outcome read_cache(std::span<const std::byte> bytes);

/// The entry named `target` ("ply", "obj", "scene", "recording", "cache"); nullptr when there is none.
using Entry = Outcome (*)(std::span<const std::byte>);
Entry entry_named(std::string_view target);

}  // namespace collidescope::fuzz
