#pragma once
/// Scenes: objects with triangles and per-frame vertex positions (engine/src/scene).
///
/// A scene hands out frames one at a time through a FrameSource, so long animations and
/// large meshes never need to sit in memory whole. Topology is shared between frames and
/// changes only when a frame's triangles differ (a fractured mesh); its revision says so.

#include "collidescope/frame_vertices.hpp"
#include "collidescope/mesh.hpp"
#include "collidescope/types.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace collidescope {

/// The triangles of one object, shared by every frame until the topology changes.
struct Topology {
    std::vector<TriIndices> triangles;
    std::uint32_t vertex_count = 0;
    /// Increases whenever an object's triangles change; equal revisions mean equal topology.
    std::uint64_t revision = 0;
};

/// One object in one frame.
struct ObjectFrame {
    std::shared_ptr<const Topology> topology;
    /// size == topology->vertex_count. Owned by sources that read or generate positions; a
    /// view of the caller's memory from Session::step (FrameVertices says how long it lives).
    FrameVertices vertices;

    std::array<Vec3, 3> corners(std::uint32_t tri) const {
        const TriIndices& t = topology->triangles[tri];
        return {vertices[t[0]], vertices[t[1]], vertices[t[2]]};
    }
    std::size_t triangle_count() const { return topology->triangles.size(); }
};

/// A revision number no other Topology of this process has had (thread-safe): for a
/// Topology built outside a FrameSource (the embedding facade's objects).
std::uint64_t next_topology_revision();

/// All objects of one frame, in input order. A frame whose vertices view caller memory is
/// valid only while that memory is: the engine reads it only inside Pipeline::process.
struct Frame {
    std::uint32_t index = 0;  ///< frame number, from 0
    std::vector<ObjectFrame> objects;
    /// Bytes of positions converted at the input boundary to make this frame: the facade's
    /// step converts float32 or strided positions into doubles (V * 24 bytes per such object)
    /// and views packed doubles in place (0). Sources that read or generate positions leave
    /// 0. The update stage reports it as counts.positions_copied_bytes.
    std::uint64_t positions_copied_bytes = 0;
};

/// Hands out the frames of an animation. Not thread-safe: one caller at a time.
class FrameSource {
public:
    virtual ~FrameSource() = default;
    virtual std::uint32_t frame_count() const = 0;
    virtual std::uint32_t object_count() const = 0;
    virtual std::string object_name(std::uint32_t object) const = 0;
    /// Frame `index` (< frame_count()). Throws InputError on bad input.
    virtual Frame frame(std::uint32_t index) = 0;
};

/// A scene: named frames plus what the pipeline needs to know about them.
struct Scene {
    std::string name;
    std::string preset;               ///< generator preset ("" for files)
    std::uint64_t seed = 0;           ///< generator seed (0 for files)
    bool self_collision = false;      ///< default for --self (a manifest or data set may set it)
    std::shared_ptr<FrameSource> source;

    // What the inputs say about time and orientation. Animated model files and point caches
    // fill these; frame sequences, static meshes and generators leave them empty.
    /// frame_times[k]: frame k's time in seconds from the clip's start (size frame_count()),
    /// or empty when the inputs carry no time.
    std::vector<double> frame_times;
    double fps = 0;        ///< sampling rate of frame_times; 0 when the inputs do not say
    std::string clip;      ///< the source animation clip's name ("" when none)
    char up_axis = 0;      ///< 'x', 'y' or 'z' when a file says which axis is up; 0 otherwise
};

/// A source over frames held in memory (tests, benchmarks, generators that precompute).
/// Topology revisions are assigned here: consecutive frames whose triangles are equal share
/// one Topology.
std::shared_ptr<FrameSource> make_memory_source(std::vector<std::string> object_names,
                                                std::vector<std::vector<MeshData>> frames);

/// How animated model files (glTF, FBX, Collada, .X, ... through assimp) are sampled
/// (docs/reference/animation.md). Unset members take a manifest's top-level "fps" / "clip", else the
/// defaults: 30 frames per second, the first clip.
struct AnimationOptions {
    std::optional<double> fps;         ///< frames per second; frame k is the pose at k / fps s
    std::optional<std::string> clip;   ///< a clip's name, or its index (from 0)
};

/// Opens the command line's inputs as one scene. Each input is a mesh file (static over all
/// frames), a frame pattern (`cloth.%04d.ply` or `cloth.####.obj`, the consecutive existing
/// frames from the first match), or a `scene.json` manifest. Objects are numbered in input
/// order (a manifest contributes its objects in its order). Throws InputError on bad input
/// (missing files, patterns matching nothing, objects with different frame counts, a
/// malformed manifest). A model file with animation (anything assimp reads but .ply / .obj)
/// becomes one object per mesh instance, named "<node>/<mesh>", sampled per `animation`; its
/// frames are 0 .. floor(duration * fps), and it fills the scene's frame_times, fps, clip and
/// up_axis (docs/reference/animation.md).
Scene open_inputs(std::span<const std::string> inputs, const AnimationOptions& animation = {});

}  // namespace collidescope
