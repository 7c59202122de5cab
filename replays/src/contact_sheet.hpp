#pragma once
// The contact sheet (replays/src, private): a grid of selected frames with their frame
// numbers, mode and pairs, under a header with the legend.

#include "overlay.hpp"

#include "collidescope/replays/options.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::replays {

/// One frame on the sheet, already scaled down.
struct SheetTile {
    std::vector<std::uint8_t> rgba;  ///< tile_width x tile_height, top row first
    std::uint32_t frame = 0;
    int mode = 0;
    std::string method;
    std::uint64_t pairs = 0;
    double total_ms = 0;
};

/// Size of the tiles for width x height frames.
struct TileSize {
    int width = 0;
    int height = 0;
};
TileSize sheet_tile_size(int width, int height);

/// Ordinals (positions among the replayed frames) of the frames the sheet shows, ascending.
/// `totals` and `pairs` are per replayed frame.
std::vector<std::uint64_t> select_sheet_frames(SheetSelection selection, int count, const std::vector<double>& totals,
                                               const std::vector<std::uint64_t>& pairs);

/// Renders the sheet in its own GL context (of `gl`) and writes it as a PNG.
void write_contact_sheet(const std::filesystem::path& file, const std::vector<SheetTile>& tiles, const TileSize& tile,
                         const SessionView& session, SheetSelection selection, GlBackend gl);

}  // namespace collidescope::replays
