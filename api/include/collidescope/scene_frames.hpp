#pragma once
/// The frames of a scene `collidescope check` can run (a built-in data set, or mesh files,
/// frame patterns and scene.json manifests), handed out as plain arrays: what a Session takes.
/// For examples, tests and benchmarks of an embedding, and for comparing a loop with `check`.

#include "collidescope/export.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace collidescope {

class COLLIDESCOPE_API SceneFrames {
public:
    /// A built-in scene, `NAME[:PRESET]` as `check --scene` takes it (C:small, demo, ...).
    /// Throws InputError naming the known scenes on an unknown name.
    static SceneFrames builtin(std::string_view spec);
    /// Input files as `check INPUT...` takes them. Throws InputError on bad input.
    static SceneFrames open(std::span<const std::string> inputs);

    ~SceneFrames();
    SceneFrames(SceneFrames&&) noexcept;
    SceneFrames& operator=(SceneFrames&&) noexcept;

    std::uint32_t frame_count() const;
    std::uint32_t object_count() const;
    std::string object_name(std::uint32_t object) const;
    std::string name() const;     ///< the scene's name
    bool self_collision() const;  ///< the scene's own self-collision setting (check's default)

    /// Makes frame `frame` (< frame_count()) current; any order, sequential is cheapest.
    void load(std::uint32_t frame);
    /// The current frame's triangles of `object` (valid until the next load).
    std::span<const std::array<std::uint32_t, 3>> triangles(std::uint32_t object) const;
    /// The current frame's positions of `object`: packed x y z doubles (valid until the next load).
    std::span<const double> positions(std::uint32_t object) const;

private:
    struct Impl;
    explicit SceneFrames(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

}  // namespace collidescope
