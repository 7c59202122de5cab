// sample_clip: channels sampled per node, then globals parent-first (nodes are in depth-first
// order, so one forward pass composes them).

#include "mesh/animation_clip.hpp"

#include <algorithm>

namespace collidescope::animation {
namespace {

// The keys around `ticks`: (i, i + 1, fraction), or (i, i, 0) when `ticks` lies outside the
// keys (held) or on the last key.
template <typename Key>
struct Bracket {
    const Key* a;
    const Key* b;
    double fraction;
};

template <typename Key>
Bracket<Key> bracket(std::span<const Key> keys, double ticks) {
    const auto after = std::upper_bound(keys.begin(), keys.end(), ticks,
                                        [](double t, const Key& key) { return t < key.time; });
    if (after == keys.begin()) return {&keys.front(), &keys.front(), 0.0};
    if (after == keys.end()) return {&keys.back(), &keys.back(), 0.0};
    const Key& b = *after;
    const Key& a = *(after - 1);  // a.time <= ticks < b.time
    return {&a, &b, (ticks - a.time) / (b.time - a.time)};
}

void compose_globals(const AnimatedModel& model, std::vector<Affine>& global) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const std::int32_t parent = model.nodes[n].parent;
        if (parent >= 0) global[n] = compose(global[static_cast<std::size_t>(parent)], global[n]);
    }
}

}  // namespace

Vec3 sample_vector(std::span<const VectorKey> keys, double ticks) {
    const Bracket<VectorKey> k = bracket(keys, ticks);
    if (k.a == k.b) return k.a->value;
    return (1 - k.fraction) * k.a->value + k.fraction * k.b->value;
}

Eigen::Quaterniond sample_rotation(std::span<const RotationKey> keys, double ticks) {
    const Bracket<RotationKey> k = bracket(keys, ticks);
    if (k.a == k.b) return k.a->value;
    return k.a->value.slerp(k.fraction, k.b->value).normalized();  // Eigen: the shorter arc
}

void sample_morph(std::span<const MorphKey> keys, double ticks, std::vector<double>& weights) {
    const Bracket<MorphKey> k = bracket(keys, ticks);
    weights.assign(std::max(k.a->weights.size(), k.b->weights.size()), 0.0);
    const auto at = [](const MorphKey& key, std::size_t i) { return i < key.weights.size() ? key.weights[i] : 0.0; };
    for (std::size_t i = 0; i < weights.size(); ++i) {
        weights[i] = k.a == k.b ? at(*k.a, i) : (1 - k.fraction) * at(*k.a, i) + k.fraction * at(*k.b, i);
    }
}

Affine trs(const Vec3& translation, const Eigen::Quaterniond& rotation, const Vec3& scaling) {
    Affine m;
    m.leftCols<3>() = rotation.toRotationMatrix() * scaling.asDiagonal();
    m.col(3) = translation;
    return m;
}

void rest_pose(const AnimatedModel& model, Pose& pose) {
    pose.global.resize(model.nodes.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) pose.global[n] = model.nodes[n].local;
    compose_globals(model, pose.global);
    pose.morph_weights.resize(model.nodes.size());
    for (std::vector<double>& weights : pose.morph_weights) weights.clear();
}

void sample_clip(const AnimatedModel& model, const Clip& clip, double ticks, Pose& pose) {
    pose.global.resize(model.nodes.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) pose.global[n] = model.nodes[n].local;
    for (const NodeChannel& channel : clip.channels) {
        pose.global[channel.node] = trs(sample_vector(channel.position, ticks),
                                        sample_rotation(channel.rotation, ticks),
                                        sample_vector(channel.scaling, ticks));
    }
    compose_globals(model, pose.global);
    pose.morph_weights.resize(model.nodes.size());
    for (std::vector<double>& weights : pose.morph_weights) weights.clear();
    for (const MorphChannel& morph : clip.morphs) sample_morph(morph.keys, ticks, pose.morph_weights[morph.node]);
}

}  // namespace collidescope::animation
