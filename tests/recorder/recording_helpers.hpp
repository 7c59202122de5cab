#pragma once
// Helpers of the recorder tests: recording a scene in-process while capturing what the engine
// reported, scenes for the tests, and editing a recording with HDF5 directly (to break it).

#include "collidescope/pipeline.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::testing {

/// Frames complete in `file` now, or 0 while it cannot be opened (yet): for polling a
/// recording another process is writing.
std::uint64_t frames_complete_now(const std::filesystem::path& file);

/// Every complete row of `part` has the frame index, pairs and positions of the same row of
/// `whole` (the uninterrupted recording of the same run).
void expect_complete_rows_equal(const recorder::Recording& part, const recorder::Recording& whole);

/// What the engine reported for one frame, copied.
struct CapturedFrame {
    FrameStats stats;
    std::vector<TrianglePair> pairs;
    std::vector<std::vector<Vec3>> vertices;             ///< per object
    std::vector<std::vector<TriIndices>> triangles;      ///< per object
};

/// Runs frames [begin, end) of `scene` through `method` with a Recorder writing `file` and
/// returns what every frame reported.
std::vector<CapturedFrame> record_in_process(const Scene& scene, const std::filesystem::path& file,
                                             std::uint32_t begin, std::uint32_t end, bool self_collision,
                                             const std::string& method = "brute");
/// The same with a whole pipeline configuration (method, self collision, GPU cull options).
std::vector<CapturedFrame> record_in_process(const Scene& scene, const std::filesystem::path& file,
                                             std::uint32_t begin, std::uint32_t end, const PipelineConfig& config);

/// Two sheets of `cells` x `cells` cells (2 cells^2 triangles each): one flat at z = 0, one
/// upright, sweeping through it along y over `frames` frames (apart, crossing, apart).
Scene crossing_sheets(std::uint32_t cells, std::uint32_t frames);

/// Two objects over `frames` frames: "changing", a grid sheet of 5 x 5 cells at frame 0 and of
/// 1 to 12 cells (drawn from `seed`) after, moving; "fixed", a 4 x 4 sheet. Vertex counts above
/// and below the first frame's, which sizes the recording's positions chunks.
Scene varying_vertex_counts(std::uint64_t seed, std::uint32_t frames);

/// Overwrites element `index` of a 1-D integer dataset.
void overwrite_u64(const std::filesystem::path& file, const std::string& dataset, std::uint64_t index,
                   std::uint64_t value);
/// Overwrites element `index` of a 1-D floating-point dataset.
void overwrite_f64(const std::filesystem::path& file, const std::string& dataset, std::uint64_t index, double value);
/// Sets (or replaces) an integer attribute of object `object` ("/" for the root).
void set_int_attr(const std::filesystem::path& file, const std::string& object, const std::string& name,
                  std::int64_t value);
/// Deletes attribute `name` of `object`.
void delete_attr(const std::filesystem::path& file, const std::string& object, const std::string& name);
/// Deletes the link `path` (a group or dataset) from the file.
void delete_link(const std::filesystem::path& file, const std::string& path);
/// Writes an HDF5 file that is not a recording (one dataset, no schema attribute).
void write_foreign_hdf5(const std::filesystem::path& file);

}  // namespace collidescope::testing
