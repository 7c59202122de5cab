// The `brute` method's frame: every box-overlapping triangle pair, then the exact test.

#include "methods/brute_method.hpp"

#include "brute/brute_cull.hpp"
#include "stages/narrow_phase.hpp"
#include "stats/stopwatch.hpp"

namespace collidescope {
namespace {

class BruteMethod final : public Method {
public:
    std::string_view name() const override { return "brute"; }

    void detect(const FrameContext& context, std::vector<TrianglePair>& pairs, FrameStats& stats) override {
        Stopwatch stopwatch;
        const std::vector<TrianglePair> candidates = brute::brute_cull(context, stats);
        stats.ms.cull += stopwatch.lap_ms();
        narrow_phase(context.frame, candidates, pairs, stats);
    }
};

}  // namespace

std::unique_ptr<Method> make_brute_method() { return std::make_unique<BruteMethod>(); }

}  // namespace collidescope
