// apply_morph: one pass per vertex block, targets in index order (so equal inputs give equal
// sums: welded vertices stay together).

#include "mesh/morph.hpp"

#include "mesh/vertex_blocks.hpp"

#include <cassert>

namespace collidescope::animation {

void apply_morph(std::span<const Vec3> base, std::span<const std::vector<Vec3>> targets,
                 std::span<const double> weights, std::span<Vec3> out) {
    assert(weights.size() <= targets.size() && out.size() == base.size());
    for_vertex_blocks(base.size(), 4096,
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t v = range.begin(); v != range.end(); ++v) {
            Vec3 p = base[v];
            for (std::size_t i = 0; i < weights.size(); ++i) {
                if (weights[i] != 0) p += weights[i] * (targets[i][v] - base[v]);
            }
            out[v] = p;
        }
    });
}

}  // namespace collidescope::animation
