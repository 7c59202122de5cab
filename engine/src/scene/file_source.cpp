// FileSource: frames read from mesh files on demand.

#include "scene/file_source.hpp"

#include "collidescope/error.hpp"

#include <atomic>
#include <stdexcept>

namespace collidescope {

std::size_t FileObject::frame_count() const {
    if (animated) return animated->frame_count();
    return cache ? cache_frames : files.size();
}

namespace {

// Revisions are unique across the process, so two objects (or two scenes) never share one
// by accident; 0 is never handed out.
std::atomic<std::uint64_t> g_next_revision{1};

class FileSource final : public FrameSource {
public:
    FileSource(std::vector<FileObject> objects, std::uint32_t frame_count)
        : m_frame_count(frame_count) {
        m_objects.reserve(objects.size());
        for (FileObject& object : objects) m_objects.push_back({std::move(object), nullptr, {}});
    }

    std::uint32_t frame_count() const override { return m_frame_count; }
    std::uint32_t object_count() const override {
        return static_cast<std::uint32_t>(m_objects.size());
    }
    std::string object_name(std::uint32_t object) const override {
        return m_objects.at(object).input.name;
    }

    Frame frame(std::uint32_t index) override {
        if (index >= m_frame_count) {
            throw std::out_of_range("frame " + std::to_string(index) + " of " +
                                    std::to_string(m_frame_count));
        }
        Frame frame;
        frame.index = index;
        frame.objects.reserve(m_objects.size());
        for (ObjectState& object : m_objects) frame.objects.push_back(object_frame(object, index));
        return frame;
    }

private:
    struct ObjectState {
        FileObject input;
        std::shared_ptr<const Topology> topology;  ///< the last frame's, for sharing
        std::vector<Vec3> static_vertices;          ///< a static object's vertices, read once
    };

    ObjectFrame object_frame(ObjectState& object, std::uint32_t index) {
        if (object.input.cache) return cached_frame(object, index);
        if (object.input.animated) {
            return {object.input.animated->topology(object.input.instance),
                    object.input.animated->vertices(object.input.instance, index)};
        }
        if (object.input.is_static) {
            if (!object.topology) {
                MeshData mesh = read(object, 0, index);
                object.static_vertices = std::move(mesh.vertices);
                share_topology(object, std::move(mesh.triangles), object.static_vertices.size());
            }
            return {object.topology, object.static_vertices};
        }
        MeshData mesh = read(object, index, index);
        share_topology(object, std::move(mesh.triangles), mesh.vertices.size());
        return {object.topology, std::move(mesh.vertices)};
    }

    // The mesh's triangles (read once) with the cache's positions of frame `index`.
    static ObjectFrame cached_frame(ObjectState& object, std::uint32_t index) {
        PointCacheReader& cache = *object.input.cache;
        if (!object.topology) {
            MeshData mesh = read(object, 0, index);
            check_cache_matches(object, mesh.vertices.size());
            share_topology(object, std::move(mesh.triangles), mesh.vertices.size());
        }
        try {
            return {object.topology, cache.read_frame(index)};
        } catch (const InputError& error) {
            throw InputError(std::string(error.what()) + " (object '" + object.input.name + "')");
        }
    }

    static void check_cache_matches(const ObjectState& object, std::size_t mesh_vertices) {
        const PointCacheReader& cache = *object.input.cache;
        if (cache.layout().point_count == mesh_vertices) return;
        throw InputError(object.input.files.at(0).string() + " has " + std::to_string(mesh_vertices) +
                         " vertices but its point cache " + cache.file().string() + " has " +
                         std::to_string(cache.layout().point_count) + " points per frame (object '" +
                         object.input.name + "')");
    }

    // Reads (and validates) one file; errors gain the object and frame.
    static MeshData read(const ObjectState& object, std::size_t file, std::uint32_t frame) {
        try {
            return read_mesh_file(object.input.files.at(file));
        } catch (const InputError& error) {
            std::string where = "object '" + object.input.name + "'";
            if (!object.input.is_static && !object.input.cache) where += ", frame " + std::to_string(frame);
            throw InputError(std::string(error.what()) + " (" + where + ")");
        }
    }

    // Keeps the previous Topology when the triangles did not change, else makes a new one.
    static void share_topology(ObjectState& object, std::vector<TriIndices>&& triangles,
                               std::size_t vertex_count) {
        const std::shared_ptr<const Topology>& previous = object.topology;
        if (previous && previous->vertex_count == vertex_count && previous->triangles == triangles) {
            return;
        }
        auto topology = std::make_shared<Topology>();
        topology->triangles = std::move(triangles);
        topology->vertex_count = static_cast<std::uint32_t>(vertex_count);
        topology->revision = next_topology_revision();
        object.topology = std::move(topology);
    }

    std::vector<ObjectState> m_objects;
    std::uint32_t m_frame_count;
};

}  // namespace

std::uint64_t next_topology_revision() {
    return g_next_revision.fetch_add(1, std::memory_order_relaxed);
}

std::shared_ptr<FrameSource> make_file_source(std::vector<FileObject> objects,
                                              std::uint32_t frame_count) {
    return std::make_shared<FileSource>(std::move(objects), frame_count);
}

}  // namespace collidescope
