// SceneFrames: a FrameSource's frames as plain arrays.

#include "collidescope/scene_frames.hpp"

#include "collidescope/datasets.hpp"
#include "collidescope/error.hpp"
#include "collidescope/scene.hpp"

namespace collidescope {

struct SceneFrames::Impl {
    Scene scene;
    Frame frame;
    bool loaded = false;

    const ObjectFrame& object(std::uint32_t k) const {
        if (!loaded) throw std::logic_error("SceneFrames: load a frame first");
        return frame.objects.at(k);
    }
};

SceneFrames::SceneFrames(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
SceneFrames::~SceneFrames() = default;
SceneFrames::SceneFrames(SceneFrames&&) noexcept = default;
SceneFrames& SceneFrames::operator=(SceneFrames&&) noexcept = default;

SceneFrames SceneFrames::builtin(std::string_view spec) {
    auto impl = std::make_unique<Impl>();
    impl->scene = make_builtin_scene(spec);
    return SceneFrames(std::move(impl));
}

SceneFrames SceneFrames::open(std::span<const std::string> inputs) {
    auto impl = std::make_unique<Impl>();
    impl->scene = open_inputs(inputs);
    return SceneFrames(std::move(impl));
}

std::uint32_t SceneFrames::frame_count() const { return m_impl->scene.source->frame_count(); }
std::uint32_t SceneFrames::object_count() const { return m_impl->scene.source->object_count(); }
std::string SceneFrames::object_name(std::uint32_t object) const { return m_impl->scene.source->object_name(object); }
std::string SceneFrames::name() const { return m_impl->scene.name; }
bool SceneFrames::self_collision() const { return m_impl->scene.self_collision; }

void SceneFrames::load(std::uint32_t frame) {
    if (frame >= frame_count()) {
        throw InputError("scene '" + m_impl->scene.name + "': no frame " + std::to_string(frame) + " (it has " +
                         std::to_string(frame_count()) + ")");
    }
    m_impl->frame = m_impl->scene.source->frame(frame);
    m_impl->loaded = true;
}

std::span<const std::array<std::uint32_t, 3>> SceneFrames::triangles(std::uint32_t object) const {
    return m_impl->object(object).topology->triangles;
}

std::span<const double> SceneFrames::positions(std::uint32_t object) const {
    const FrameVertices& vertices = m_impl->object(object).vertices;
    return {vertices.empty() ? nullptr : vertices.front().data(), vertices.size() * 3};
}

}  // namespace collidescope
