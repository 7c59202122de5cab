#pragma once
// The tree validator (engine/src/bvh): checks a Tree against its mesh, like Jolt's and
// Box2D's validators. Tests call it after every build, refit and swap.

#include "bvh/bvh.hpp"

#include <string>
#include <vector>

namespace collidescope::bvh {

/// What to check beyond the structure.
struct ValidateOptions {
    std::uint32_t max_leaf_size = 4;  ///< leaves hold 1 .. max_leaf_size triangles
    /// Also require every box to be exactly the union of its children / its triangles (true
    /// right after a build or refit on these vertices), and each stored triangle box its
    /// triangle's; containment is checked always (false: a swept tree, whose boxes also hold
    /// the other end).
    bool tight = true;
};

/// Checks: preorder structure (left child next, right child inside the parent's range, every
/// node reached exactly once), node count = 2 * leaves - 1, leaf sizes, leaf coverage (leaf
/// ranges tile triangle_ids in order, and every triangle appears exactly once), each child box
/// inside its parent's, each leaf box containing its triangles' boxes on `vertices`, and the
/// refit plan covering every node once. Returns one message per problem (empty: valid).
std::vector<std::string> validate(const Tree& tree, std::span<const TriIndices> triangles,
                                  std::span<const Vec3> vertices, const ValidateOptions& options = {});

}  // namespace collidescope::bvh
