#pragma once
// Draws a frame's meshes into an offscreen framebuffer (replays/src, private): flat-shaded
// triangles, one colour per object, the triangle state (colliding, in the PCS, culled) from a
// per-triangle buffer looked up by gl_PrimitiveID. One per render thread, in that thread's GL
// context.

#include "frame_data.hpp"
#include "collidescope/gl_api.hpp"

#include "collidescope/replays/camera.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace collidescope::replays {

/// Base colour of object `object` (linear RGB in [0, 1]); never red, amber or green, which
/// mean collision, PCS and --diff.
std::array<float, 3> object_colour(std::uint32_t object);
/// Colours of the triangle states, as the shader draws them before lighting.
std::array<float, 3> state_colour(TriangleState state);

class MeshRenderer {
public:
    /// A width x height RGBA8 + depth framebuffer, bound. Needs a current GL 4.5 context.
    MeshRenderer(int width, int height);
    ~MeshRenderer();
    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;

    /// Binds the framebuffer and clears it to the background.
    void clear();
    /// Draws every object of `frame` seen by `camera` into camera.viewport. `source` tells
    /// recordings apart (--diff) in the cache of index buffers.
    void draw(const FrameData& frame, const Camera& camera, unsigned layers, std::uint32_t source = 0);
    /// The image, RGBA, top row first (PNG order).
    std::vector<std::uint8_t> read_rgba() const;

    int width() const { return m_width; }
    int height() const { return m_height; }

private:
    struct Mesh {
        GLuint vertices = 0;
        GLuint indices = 0;
        GLuint states = 0;
        GLuint states_texture = 0;
        GLuint vao = 0;
        GLsizei index_count = 0;
    };
    Mesh& mesh_for(std::uint32_t source, std::uint32_t object, const ObjectFrame& frame);

    int m_width;
    int m_height;
    GLuint m_framebuffer = 0;
    GLuint m_colour = 0;
    GLuint m_depth = 0;
    GLuint m_program = 0;
    // Keyed by (source, object); the index buffer is reloaded when the topology changes.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::size_t, Mesh>> m_meshes;
};

}  // namespace collidescope::replays
