#pragma once
/// Options of the replayer (docs/how-to/replay.md): what a frame shows, the camera, the image size.

#include "collidescope/gl_backend.hpp"
#include "collidescope/option_names.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

namespace collidescope::replays {

/// Layers of a frame, each switchable with `--show` (bits of ReplayOptions::layers).
enum Layer : unsigned {
    k_layer_meshes = 1,      ///< the meshes, shaded, one colour per object
    k_layer_collisions = 2,  ///< colliding triangles in the collision colour
    k_layer_pcs = 4,         ///< triangles left in the GPU cull's PCS in one colour, culled ones dimmed
    k_layer_depth = 8,       ///< the recorded depth buffers as thumbnails, with their legend bar
    k_layer_overlay = 16,    ///< the Dear ImGui panel: frame, mode, decision, times, PCS, queries, view matrix
    k_layer_timeline = 32,   ///< per-frame total time coloured by mode, current frame marked
    k_layer_legend = 64,     ///< the colour legend of the triangle states and objects
    k_layer_regions = 128,   ///< intersection curves as thick lines, each region labelled (record --regions)
    k_layer_all = 255,
};

/// Parses a comma-separated list of layer names ("meshes,collisions,pcs,depth,overlay,timeline,
/// legend", or "all", or "none"). Throws InputError naming the unknown name.
unsigned parse_layers(const std::string& list);

/// Where the camera looks from.
struct CameraSpec {
    enum class Kind {
        Auto,   ///< frames the bounds of every replayed frame, from a fixed direction
        Orbit,  ///< as Auto, turning about the vertical (z) axis around the bounds' centre
        Fixed,  ///< an explicit eye and target
        Focus,  ///< as Auto, framing each frame's colliding triangles, smoothed over frames (focus_path)
        Region, ///< as Focus, framing one region (`region:ID`, record --regions) in the frames it lives
    };
    Kind kind = Kind::Auto;
    /// Orbit: degrees turned per replayed frame; 0 = one full turn over the replayed frames.
    double degrees_per_frame = 0;
    std::array<double, 3> eye{};     ///< Fixed: the eye, input length units
    std::array<double, 3> target{};  ///< Fixed: the point looked at
    bool target_given = false;       ///< Fixed: false = the bounds' centre
    double fov_degrees = 40;         ///< vertical field of view
    /// The world axis that points up on screen: 'x', 'y' or 'z' (`--up`; the recording's
    /// `up_axis` when it has one; 0 = 'z'). Auto, Orbit and Focus look from above the front
    /// right in that frame; Orbit turns about it.
    char up = 0;
    std::uint32_t region = 0;  ///< Region: the region's id
};

/// Parses `x`, `y` or `z` for CameraSpec::up. Throws InputError naming the text.
char parse_up_axis(const std::string& text);

/// Parses `auto`, `orbit`, `orbit:DEG` (degrees per frame), `focus`, `region:ID` or
/// `fixed:EX,EY,EZ[:TX,TY,TZ]`.
/// Throws InputError naming the spec.
CameraSpec parse_camera(const std::string& spec);

/// Which frames the contact sheet shows.
enum class SheetSelection {
    Every,       ///< evenly spaced over the replayed frames
    Collisions,  ///< the frames with colliding pairs (evenly spaced among them when too many)
    Slowest,     ///< the frames with the largest total time, in frame order
};

/// The names of SheetSelection (--sheet-frames).
inline constexpr OptionNames<SheetSelection, 3> k_sheet_selection_names{
    {{"every", SheetSelection::Every},
     {"collisions", SheetSelection::Collisions},
     {"slowest", SheetSelection::Slowest}}};

/// Options of one replay.
struct ReplayOptions {
    std::filesystem::path output_dir;  ///< PNGs go here (created when missing); "" = no PNGs (--video alone)
    /// The frames as a clip too (docs/how-to/replay.md, "Video"): .mp4 (H.264) or .gif; "" = none. At
    /// the recording's fps, or 30 when it does not say.
    std::filesystem::path video;
    /// Scene frames to replay, half-open [frame_begin, frame_end); rows whose /frames/index lies
    /// outside are skipped. The default is every recorded frame.
    std::uint32_t frame_begin = 0;
    std::uint32_t frame_end = UINT32_MAX;
    /// Frame-parallel replays (one process renders one block, app/ranks/ranks.hpp): render only the
    /// replayed frames whose scene frame number lies in [part_begin, part_end), with everything
    /// that depends on all of them (the camera's bounds and orbit angle, the focus path, the
    /// frame's position on the timeline, the contact sheet's choice of frames) computed over the
    /// whole [frame_begin, frame_end), so each PNG is byte for byte a whole replay's. The
    /// contact sheet's frames outside the part are rendered for it alone (no PNG). The clip
    /// needs every frame: a part with `video` is an error. The default is the whole replay.
    std::uint32_t part_begin = 0;
    std::uint32_t part_end = UINT32_MAX;
    int width = 1280;   ///< pixels
    int height = 720;   ///< pixels
    CameraSpec camera;
    unsigned layers = k_layer_all;  ///< Layer bits
    /// Render threads, each with its own GL context; 0 = one per hardware thread.
    int threads = 0;
    /// The GL contexts' implementation (`--gl`), as for the GPU cull.
    GlBackend gl = GlBackend::Auto;
    std::filesystem::path contact_sheet;  ///< "" = none
    SheetSelection sheet_selection = SheetSelection::Every;
    int sheet_count = 12;  ///< frames on the contact sheet, at most
    /// Also render, for every replayed frame whose interval into the next recorded frame has a
    /// pass-through (record --between-frames), its moment of first contact:
    /// `output_dir`/contact_NNNN.png (NNNN = the interval's first scene frame), the meshes
    /// interpolated to the earliest pass-through's time, that pair highlighted and ringed.
    bool contact_moments = false;
};

}  // namespace collidescope::replays
