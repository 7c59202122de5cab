// The rebuild policy's rules.

#include "bvh/rebuild_policy.hpp"

namespace collidescope::bvh {

std::string_view rebuild_reason_name(RebuildReason reason) {
    switch (reason) {
        case RebuildReason::None: return "none";
        case RebuildReason::Initial: return "initial";
        case RebuildReason::Topology: return "topology";
        case RebuildReason::Thesis: return "thesis";
        case RebuildReason::Quality: return "quality";
    }
    return "none";
}

bool RebuildPolicy::quality_rebuild_pays(const RebuildInputs& inputs) const {
    if (!(inputs.quality > m_config.quality_limit)) return false;
    if (m_config.payback_frames <= 0 || inputs.quality > m_config.in_frame_quality) return true;
    const double saved_per_frame = inputs.traversal_ms * (1 - 1 / inputs.quality);
    return saved_per_frame * m_config.payback_frames >= inputs.rebuild_ms;
}

RebuildReason RebuildPolicy::decide(const RebuildInputs& inputs) const {
    if (!inputs.has_tree) return RebuildReason::Initial;
    if (inputs.topology_changed) return RebuildReason::Topology;
    switch (m_config.rule) {
        case RebuildRule::Quality:
            return quality_rebuild_pays(inputs) ? RebuildReason::Quality : RebuildReason::None;
        case RebuildRule::Thesis:
            return inputs.detection_ms > m_config.thesis_fraction * inputs.rebuild_ms ? RebuildReason::Thesis
                                                                                       : RebuildReason::None;
        case RebuildRule::Never:
            return RebuildReason::None;
    }
    return RebuildReason::None;
}

}  // namespace collidescope::bvh
