#pragma once
// The view configuration matrix (engine/src/gpucull, private; thesis 4.2.1, Algorithm 2,
// Equations 4.1-4.2). Rows are the (up to three) cull passes of a frame, columns the views
// x, y, z; each entry scores how well that view culled at that pass. Each frame every pass
// takes its best-scoring view not yet used in the frame, except one pass, drawn at random,
// which explores a random unused view (one exploration per frame).
//
// The extracted equations lost their operators; our reading, which fits the prose ("a very
// heavy weight" on the last frame's success):
//   (4.1) M[p][v] = M[p][v] / 4 + 3/4 * culled      culled = fraction of the remaining PCS that
//                                                   pass p with view v removed (1 when the PCS
//                                                   was already empty)
//   step 2  M[0][v] = max(M[0][v], M[p][v])          for the views v of passes p = 2, 3: row 1
//                                                   is raised to what later passes scored
//   (4.2) M[p][v] *= DECAY_RATE                     every entry decays
// Step 2 is "view options for cull pass 1 are increased by options for cull passes 2 and 3",
// an exploration term. Read as a plain sum (M[0][v] += M[1][v] + M[2][v]) it accumulates
// every frame while (4.1) damps the chosen entries, so with DECAY_RATE 0.9 row 1 would settle
// at several times the scores it is compared with and never pick the view that actually culled
// best at pass 1 (tests/gpucull/test_mechanisms.cpp shows the case); raising row 1 to the later
// passes' scores keeps the intent and the scale.

#include "collidescope/gpu_cull.hpp"

#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace collidescope::gpucull {

/// Options of the matrix.
struct ViewConfigurationConfig {
    double decay_rate = 0.9;     ///< DECAY_RATE of Equation 4.2
    bool explore = true;         ///< one random pass per frame takes a random unused view
    std::uint64_t seed = 1;      ///< of the exploration draws (deterministic runs)
};

/// The 3x3 matrix and its choices. Not thread-safe.
class ViewConfiguration {
public:
    explicit ViewConfiguration(ViewConfigurationConfig config = {});

    /// The views (0 = x, 1 = y, 2 = z) for the frame's `passes` (1..3) cull passes, distinct.
    std::vector<int> choose(int passes);
    /// Algorithm 2 after a frame: `culled[p]` is the fraction of the remaining PCS that pass p
    /// (which used views[p]) removed.
    void update(const std::vector<int>& views, const std::vector<double>& culled);

    /// update()'s `culled` from a frame's trace: per triangle-level view, the fraction of the
    /// remaining PCS it removed; passes the frame skipped (the PCS emptied) count as 1.
    static std::vector<double> culled_fractions(const GpuFrameInfo& info, std::size_t passes);

    using Matrix = std::array<std::array<double, 3>, 3>;
    const Matrix& matrix() const { return m_matrix; }

private:
    ViewConfigurationConfig m_config;
    Matrix m_matrix{};
    std::mt19937_64 m_random;
};

}  // namespace collidescope::gpucull
