#pragma once
// One animated model file sampled at a fixed rate (engine/src/scene, private).
//
// open_inputs makes one AnimatedFile per animated input; each of its mesh instances becomes an
// object of the FileSource, which asks here for the instance's vertices in frame k. The pose of
// frame k (node transforms, morph weights) is sampled once and shared by the file's instances.

#include "collidescope/scene.hpp"

#include "mesh/animated_model.hpp"
#include "mesh/model_pose.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace collidescope {

class AnimatedFile {
public:
    /// Picks the clip (`options.clip`: a name, else an index; default the first) and the rate
    /// (`options.fps`, default 30). Throws InputError naming the file: no such clip, fps not a
    /// positive finite number, more frames than a recording can number.
    AnimatedFile(std::filesystem::path file, animation::AnimatedModel model, const AnimationOptions& options);

    std::uint32_t frame_count() const { return m_frame_count; }
    double fps() const { return m_fps; }
    /// The clip's name, or its index when the file leaves it unnamed.
    const std::string& clip_name() const { return m_clip_name; }
    char up_axis() const { return m_model.up_axis; }
    /// Frame k's time in seconds from the clip's start: k / fps.
    std::vector<double> frame_times() const;

    std::uint32_t instance_count() const { return static_cast<std::uint32_t>(m_model.instances.size()); }
    const std::string& instance_name(std::uint32_t instance) const { return m_model.instances.at(instance).name; }
    const std::shared_ptr<const Topology>& topology(std::uint32_t instance) const { return m_topologies.at(instance); }

    /// Instance `instance`'s vertices in frame `frame` (< frame_count()), in scene space.
    std::vector<Vec3> vertices(std::uint32_t instance, std::uint32_t frame);

private:
    std::filesystem::path m_file;
    animation::AnimatedModel m_model;
    std::size_t m_clip = 0;
    std::string m_clip_name;
    double m_fps = 30;
    std::uint32_t m_frame_count = 1;
    std::vector<std::shared_ptr<const Topology>> m_topologies;
    animation::Pose m_pose;
    std::int64_t m_posed_frame = -1;  ///< the frame m_pose holds, -1 for none
    animation::PoseScratch m_scratch;
};

}  // namespace collidescope
