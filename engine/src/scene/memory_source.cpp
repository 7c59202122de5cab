// MemorySource: frames held in memory (tests, benchmarks, built-in scene generators).
//
// The meshes are validated once, here, at the boundary (validate_mesh: at least one
// triangle, indices in range, finite coordinates), and consecutive frames of an object whose
// triangles are equal share one Topology, so a method sees an unchanged revision exactly when
// it may refit instead of rebuilding.

#include "scene/file_source.hpp"

#include "collidescope/error.hpp"
#include "collidescope/scene.hpp"

#include <stdexcept>

namespace collidescope {
namespace {

class MemorySource final : public FrameSource {
public:
    MemorySource(std::vector<std::string> object_names,
                 std::vector<std::vector<ObjectFrame>> frames)
        : m_object_names(std::move(object_names)), m_frames(std::move(frames)) {}

    std::uint32_t frame_count() const override {
        return static_cast<std::uint32_t>(m_frames.size());
    }
    std::uint32_t object_count() const override {
        return static_cast<std::uint32_t>(m_object_names.size());
    }
    std::string object_name(std::uint32_t object) const override {
        return m_object_names.at(object);
    }

    Frame frame(std::uint32_t index) override {
        if (index >= m_frames.size()) {
            throw std::out_of_range("frame " + std::to_string(index) + " of " +
                                    std::to_string(m_frames.size()));
        }
        Frame frame;
        frame.index = index;
        frame.objects = m_frames[index];
        return frame;
    }

private:
    std::vector<std::string> m_object_names;
    std::vector<std::vector<ObjectFrame>> m_frames;  ///< [frame][object]
};

std::string describe(const std::string& object_name, std::size_t object, std::size_t frame) {
    return "memory scene: object " + std::to_string(object) + " '" + object_name + "', frame " +
           std::to_string(frame);
}

// Checks the frames' shape: at least one frame, every frame with one mesh per object name.
void validate_shape(const std::vector<std::string>& object_names,
                    const std::vector<std::vector<MeshData>>& frames) {
    if (object_names.empty()) throw InputError("memory scene: no objects");
    if (frames.empty()) throw InputError("memory scene: no frames");
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (frames[f].size() != object_names.size()) {
            throw InputError("memory scene: frame " + std::to_string(f) + " has " +
                             std::to_string(frames[f].size()) + " objects, expected " +
                             std::to_string(object_names.size()));
        }
    }
}

}  // namespace

std::shared_ptr<FrameSource> make_memory_source(std::vector<std::string> object_names,
                                                std::vector<std::vector<MeshData>> frames) {
    validate_shape(object_names, frames);
    std::vector<std::vector<ObjectFrame>> object_frames(frames.size());
    std::vector<std::shared_ptr<const Topology>> previous(object_names.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        object_frames[f].reserve(object_names.size());
        for (std::size_t o = 0; o < object_names.size(); ++o) {
            MeshData& mesh = frames[f][o];
            validate_mesh(mesh, describe(object_names[o], o, f));
            const std::shared_ptr<const Topology>& last = previous[o];
            if (!last || last->vertex_count != mesh.vertices.size() ||
                last->triangles != mesh.triangles) {
                auto topology = std::make_shared<Topology>();
                topology->triangles = std::move(mesh.triangles);
                topology->vertex_count = static_cast<std::uint32_t>(mesh.vertices.size());
                topology->revision = next_topology_revision();
                previous[o] = std::move(topology);
            }
            object_frames[f].push_back({previous[o], std::move(mesh.vertices)});
        }
    }
    return std::make_shared<MemorySource>(std::move(object_names), std::move(object_frames));
}

}  // namespace collidescope
