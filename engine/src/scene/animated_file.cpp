// AnimatedFile: clip choice, frame count, and posing on demand.

#include "scene/animated_file.hpp"

#include "collidescope/error.hpp"

#include <cmath>
#include <limits>

namespace collidescope {
namespace {

// A recording numbers frames with 32 bits; anything near that is a mistake (fps 1e9).
constexpr double k_max_frames = 10'000'000;

bool is_index(const std::string& text) {
    return !text.empty() && text.size() < 10 &&
           text.find_first_not_of("0123456789") == std::string::npos;
}

std::string clip_list(const animation::AnimatedModel& model) {
    std::string list;
    for (std::size_t c = 0; c < model.clips.size(); ++c) {
        list += (list.empty() ? "" : ", ") + std::to_string(c) + " '" + model.clips[c].name + "'";
    }
    return list;
}

// By name first, then as an index.
std::size_t find_clip(const animation::AnimatedModel& model, const std::string& wanted,
                      const std::filesystem::path& file) {
    for (std::size_t c = 0; c < model.clips.size(); ++c) {
        if (model.clips[c].name == wanted) return c;
    }
    if (is_index(wanted) && std::stoul(wanted) < model.clips.size()) return std::stoul(wanted);
    throw InputError(file.string() + ": no clip '" + wanted + "' (clips: " + clip_list(model) + ")");
}

}  // namespace

AnimatedFile::AnimatedFile(std::filesystem::path file, animation::AnimatedModel model,
                           const AnimationOptions& options)
    : m_file(std::move(file)), m_model(std::move(model)) {
    if (m_model.clips.empty()) throw InputError(m_file.string() + ": no animation clip");
    if (options.clip) m_clip = find_clip(m_model, *options.clip, m_file);
    const animation::Clip& clip = m_model.clips[m_clip];
    m_clip_name = clip.name.empty() ? std::to_string(m_clip) : clip.name;
    m_fps = options.fps.value_or(30.0);
    if (!std::isfinite(m_fps) || m_fps <= 0) {
        throw InputError(m_file.string() + ": fps " + std::to_string(m_fps) + " is not a positive number");
    }
    // floor(duration * fps), with duration * fps computed as ticks * fps / ticks-per-second so
    // that whole-frame durations (20 ticks at 24 per second, 30 fps: 25) come out whole.
    const double last = std::floor(clip.duration_ticks * m_fps / clip.ticks_per_second);
    if (!(last < k_max_frames)) {
        throw InputError(m_file.string() + ": clip '" + m_clip_name + "' at " + std::to_string(m_fps) +
                         " fps has more than " + std::to_string(static_cast<long>(k_max_frames)) + " frames");
    }
    m_frame_count = static_cast<std::uint32_t>(last) + 1;
    for (const animation::MeshInstance& instance : m_model.instances) {
        auto topology = std::make_shared<Topology>();
        topology->triangles = instance.triangles;
        topology->vertex_count = static_cast<std::uint32_t>(instance.base.size());
        topology->revision = next_topology_revision();
        m_topologies.push_back(std::move(topology));
    }
}

std::vector<double> AnimatedFile::frame_times() const {
    std::vector<double> times(m_frame_count);
    for (std::uint32_t k = 0; k < m_frame_count; ++k) times[k] = k / m_fps;
    return times;
}

std::vector<Vec3> AnimatedFile::vertices(std::uint32_t instance, std::uint32_t frame) {
    if (m_posed_frame != frame) {
        const animation::Clip& clip = m_model.clips[m_clip];
        animation::sample_clip(m_model, clip, frame * clip.ticks_per_second / m_fps, m_pose);
        m_posed_frame = frame;
    }
    std::vector<Vec3> out;
    animation::pose_instance(m_model.instances.at(instance), m_pose, m_scratch, out);
    for (std::size_t v = 0; v < out.size(); ++v) {
        if (std::isfinite(out[v].x()) && std::isfinite(out[v].y()) && std::isfinite(out[v].z())) continue;
        throw InputError(m_file.string() + ": " + instance_name(instance) + " vertex " + std::to_string(v) +
                         " is not finite in frame " + std::to_string(frame));
    }
    return out;
}

}  // namespace collidescope
