// skin: blocks of vertices in parallel; per vertex the weighted sum of its bones' matrices
// (12 multiply-adds per influence, which the compiler vectorises), then one transform.

#include "mesh/skinning.hpp"

#include "mesh/vertex_blocks.hpp"

#include <cassert>

namespace collidescope::animation {

void skin(std::span<const Vec3> positions, const Influences& influences,
          std::span<const Affine> bone_matrices, const Affine& fallback, std::span<Vec3> out) {
    assert(out.size() == positions.size() && influences.begin.size() == positions.size() + 1);
    for_vertex_blocks(positions.size(), 8192,
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t v = range.begin(); v != range.end(); ++v) {
            const std::uint32_t first = influences.begin[v], last = influences.begin[v + 1];
            if (first == last) {
                out[v] = apply(fallback, positions[v]);
                continue;
            }
            Affine blended = influences.weight[first] * bone_matrices[influences.bone[first]];
            for (std::uint32_t i = first + 1; i < last; ++i) {
                blended += influences.weight[i] * bone_matrices[influences.bone[i]];
            }
            out[v] = apply(blended, positions[v]);
        }
    });
}

}  // namespace collidescope::animation
