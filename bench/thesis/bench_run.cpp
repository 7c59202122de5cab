// Runs every method on every frame of a scene, repeats, medians, and the cross-method check.

#include "bench_run.hpp"

#include "collidescope/pipeline.hpp"
#include "collidescope/stats.hpp"

#include <algorithm>
#include <memory>

namespace collidescope::app {
namespace {

std::vector<double> stage_values(const StageTimes& ms) {
    std::vector<double> values;
    for_each_stage(ms, [&](const char*, double value) { values.push_back(value); });
    return values;
}

std::vector<std::uint64_t> count_values(const FrameCounts& counts) {
    std::vector<std::uint64_t> values;
    for_each_count(counts, [&](const char*, std::uint64_t value) { values.push_back(value); });
    return values;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// Per method and frame, the stage values of every repeat.
using Samples = std::vector<std::vector<std::vector<std::vector<double>>>>;  // [m][f][rep][stage]

}  // namespace

std::vector<std::string> count_names() {
    std::vector<std::string> names;
    for_each_count(FrameCounts{}, [&](const char* name, std::uint64_t) { names.emplace_back(name); });
    return names;
}

std::size_t count_index(const std::string& name) {
    const std::vector<std::string> names = count_names();
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

BenchMismatch compare_pair_lists(const std::vector<TrianglePair>& reference,
                                 const std::vector<TrianglePair>& pairs) {
    BenchMismatch mismatch;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < reference.size() || j < pairs.size()) {
        if (j == pairs.size() || (i < reference.size() && reference[i] < pairs[j])) {
            ++mismatch.missing;
            ++i;
        } else if (i == reference.size() || pairs[j] < reference[i]) {
            ++mismatch.extra;
            ++j;
        } else {
            ++i;
            ++j;
        }
    }
    return mismatch;
}

BenchScene run_bench_scene(const Scene& scene, const BenchPlan& plan,
                           const std::function<void()>& on_step) {
    BenchScene result{scene.name, scene.preset, plan.methods, {}, {}, 0};
    const std::size_t methods = plan.methods.size();
    const std::uint32_t frames = plan.end - plan.begin;
    Samples samples(methods, std::vector<std::vector<std::vector<double>>>(frames));
    std::vector<std::vector<std::vector<std::uint64_t>>> counts(methods, std::vector<std::vector<std::uint64_t>>(frames));
    std::vector<std::vector<std::vector<double>>> hybrid(methods, std::vector<std::vector<double>>(frames));
    std::vector<std::vector<std::pair<std::uint8_t, std::uint8_t>>> modes(methods, std::vector<std::pair<std::uint8_t, std::uint8_t>>(frames, {0, 255}));

    // Method by method, each running the whole animation alone: a method's background work
    // (the AABB rebuild on its worker thread) must never run inside another method's timed
    // frame. Interleaving the methods frame by frame did that: whichever method came second
    // paid for the first one's rebuild, 8-14% of its total on E (docs/reference/datasets.md, "bench").
    std::vector<std::vector<TrianglePair>> reference(frames);  // the first method's, first run
    for (int rep = 0; rep < plan.repeat; ++rep) {
        for (std::size_t m = 0; m < methods; ++m) {
            // A fresh pipeline each run (methods keep trees and GPU state across frames),
            // destroyed, its worker joined, before the next method starts.
            PipelineConfig config;
            config.method = plan.methods[m];
            config.self_collision = plan.self_collision;
            config.threads = plan.threads;
            config.gpu = plan.gpu;
            config.aabb = plan.aabb;
            config.adaptive = plan.adaptive;
            Pipeline pipeline(config);
            for (std::uint32_t f = 0; f < frames; ++f) {
                const Frame frame = scene.source->frame(plan.begin + f);
                if (rep == 0 && m == 0 && f == 0) {
                    for (const ObjectFrame& object : frame.objects) result.triangles += object.triangle_count();
                }
                FrameResult frame_result = pipeline.process(frame);
                samples[m][f].push_back(stage_values(frame_result.stats.ms));
                if (rep == 0) counts[m][f] = count_values(frame_result.stats.counts);
                if (rep == 0 && frame_result.stats.hybrid) {
                    for_each_hybrid_value(*frame_result.stats.hybrid,
                                          [&](const char*, double value, const char*) { hybrid[m][f].push_back(value); });
                }
                if (rep == 0 && frame_result.stats.decision) {
                    modes[m][f] = {frame_result.stats.decision->mode, frame_result.stats.decision->action};
                }
                if (rep == 0 && m == 0) {
                    reference[f] = std::move(frame_result.colliding_pairs);
                } else {
                    BenchMismatch mismatch = compare_pair_lists(reference[f], frame_result.colliding_pairs);
                    if (mismatch.missing + mismatch.extra > 0) {  // any repeat: a flaky method is wrong too
                        mismatch.frame = plan.begin + f;
                        mismatch.method = plan.methods[m];
                        mismatch.reference = plan.methods[0];
                        result.mismatches.push_back(mismatch);
                    }
                }
                on_step();
            }
        }
    }

    for (std::size_t m = 0; m < methods; ++m) {
        for (std::uint32_t f = 0; f < frames; ++f) {
            const std::size_t stages = samples[m][f].front().size();
            std::vector<double> ms(stages);
            for (std::size_t s = 0; s < stages; ++s) {
                std::vector<double> values;
                for (const std::vector<double>& run : samples[m][f]) values.push_back(run[s]);
                ms[s] = median(std::move(values));
            }
            result.frames.push_back({plan.methods[m], plan.begin + f, std::move(ms), counts[m][f], modes[m][f].first,
                                     modes[m][f].second, std::move(hybrid[m][f])});
        }
    }
    return result;
}

}  // namespace collidescope::app
