#pragma once
// `collidescope bench`, the measuring part: every method on every frame of one scene, each
// animation run `repeat` times with fresh pipelines, and every frame's pairs checked to be the
// same for all methods.

#include "collidescope/aabb_options.hpp"
#include "collidescope/adaptive_options.hpp"
#include "collidescope/gpu_cull.hpp"
#include "collidescope/scene.hpp"
#include "collidescope/types.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace collidescope::app {

/// What to run on one scene.
struct BenchPlan {
    std::vector<std::string> methods;  ///< names from method_names(), in report order
    std::uint32_t begin = 0;           ///< first frame
    std::uint32_t end = 0;             ///< one past the last frame
    int repeat = 1;                    ///< runs of the whole animation per method (>= 1)
    int threads = 0;                   ///< worker threads, 0 = all hardware threads
    bool self_collision = false;
    GpuCullConfig gpu;                 ///< options of the GPU cull methods
    AabbOptions aabb;                  ///< options of the AABB hierarchies
    AdaptiveOptions adaptive;          ///< options of the decision system (adaptive methods)
};

/// One method on one frame: per-stage milliseconds (median over the repeats, in
/// for_each_stage order) and counts (of the first run, in for_each_count order).
struct BenchFrame {
    std::string method;
    std::uint32_t frame = 0;
    std::vector<double> ms;
    std::vector<std::uint64_t> counts;
    std::uint8_t mode = 0;       ///< adaptive methods: the mode in force (1 or 2) in the first run; 0 otherwise
    std::uint8_t action = 255;   ///< adaptive methods: DecisionAction of the first run; 255 otherwise
    /// The hybrid framework's analysis (for_each_hybrid_value order) of the first run; empty
    /// when the method did not run it on this frame.
    std::vector<double> hybrid;
    double total_ms() const { return ms.back(); }  ///< `total` is the last stage
};

/// A frame where a method's pairs differ from the first method's.
struct BenchMismatch {
    std::uint32_t frame = 0;
    std::string method;
    std::string reference;          ///< the first method
    std::uint64_t missing = 0;      ///< pairs the reference found and the method did not
    std::uint64_t extra = 0;        ///< pairs the method found and the reference did not
};

/// Everything measured on one scene.
struct BenchScene {
    std::string name;    ///< "A", ...
    std::string preset;  ///< "small", ...
    std::vector<std::string> methods;
    std::vector<BenchFrame> frames;  ///< method-major: all frames of methods[0], then methods[1]...
    std::vector<BenchMismatch> mismatches;
    std::uint64_t triangles = 0;     ///< in the first frame, all objects
};

/// The names of BenchFrame::counts, in order.
std::vector<std::string> count_names();

/// The position of the count `name` (e.g. "colliding_pairs") in BenchFrame::counts.
std::size_t count_index(const std::string& name);

/// Counts the pairs in `reference` but not in `pairs` (missing) and the reverse (extra); both
/// lists sorted and unique, as the pipeline returns them.
BenchMismatch compare_pair_lists(const std::vector<TrianglePair>& reference,
                                 const std::vector<TrianglePair>& pairs);

/// Runs the plan on `scene`: per repeat, each method in turn runs every frame with a fresh
/// pipeline, alone (no other method's pipeline exists meanwhile). Frames are produced before
/// the clock starts (frame generation or import is not measured: ms.total covers the
/// pipeline only). `on_step` is called after every frame of every method and repeat (for a
/// progress bar).
BenchScene run_bench_scene(const Scene& scene, const BenchPlan& plan,
                           const std::function<void()>& on_step);

}  // namespace collidescope::app
