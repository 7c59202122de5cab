#pragma once
// Marks over a mesh's vertices or triangles that are reset in O(1) (engine/src/regions,
// private): a mark is current when it equals the generation, so a frame pays for what it marks,
// not for clearing arrays as long as the meshes. Kept per thread from call to call by its users.
// A large block (collidescope/large_blocks.hpp) once a mesh is large: the marks of a
// million-triangle mesh fault in a few huge pages, not a thousand small ones.

#include "collidescope/large_blocks.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace collidescope::regions {

struct StampedMarks {
    detail::LargeVector<std::uint32_t> values;
    std::uint32_t generation = 0;

    /// Clears every mark, for indices below `size`.
    void next(std::size_t size) {
        if (values.size() < size) values.resize(size, 0);
        if (++generation == 0) {  // wrapped: the old stamps could read as current
            std::fill(values.begin(), values.end(), 0);
            generation = 1;
        }
    }
    bool marked(std::size_t i) const { return values[i] == generation; }
    /// Marks i; false when it already was.
    bool mark(std::size_t i) {
        if (values[i] == generation) return false;
        values[i] = generation;
        return true;
    }
};

}  // namespace collidescope::regions
