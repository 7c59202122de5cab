#pragma once
/// Point cache writers for tests: the simplest files that match the formats' descriptions in
/// collidescope/point_cache.hpp, one frame's positions after another (float32).

#include "collidescope/types.hpp"

#include <filesystem>
#include <vector>

namespace collidescope::testing {

/// Frames of positions: frames[k][v] is vertex v in frame k (every frame the same size).
using PositionFrames = std::vector<std::vector<Vec3>>;

/// Writes a PC2 file: little-endian header (version 1, start frame, sample rate) and frames.
void write_pc2(const std::filesystem::path& file, const PositionFrames& frames,
               float start_frame = 0.0f, float sample_rate = 1.0f);

/// Writes an MDD file: big-endian counts, `times` (one per frame, seconds) and frames.
void write_mdd(const std::filesystem::path& file, const PositionFrames& frames,
               const std::vector<float>& times);

}  // namespace collidescope::testing
