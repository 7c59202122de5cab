// `collidescope compare`: the pairs and stage times of two recordings.

#include "commands.hpp"
#include "number_checks.hpp"

#include "collidescope/recorder/compare.hpp"
#include "collidescope/recorder/reader.hpp"

#include <cstdio>
#include <iostream>
#include <memory>

namespace collidescope::app {
namespace {

struct CompareOptions {
    std::string a;
    std::string b;
    std::size_t max_frames = 20;  ///< differing frames listed
};

std::string ratio(double a, double b) {
    if (a <= 0) return b <= 0 ? "-" : "inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", b / a);
    return text;
}

void print_stages(const recorder::ComparisonReport& report) {
    std::printf("time per stage over matched frames (ms):   median a     median b    ratio b/a      total a      total b    ratio b/a\n");
    for (const recorder::StageComparison& s : report.stages) {
        std::printf("  %-20s %28.3f %12.3f %12s %12.3f %12.3f %12s\n", s.stage.c_str(), s.median_a, s.median_b,
                    ratio(s.median_a, s.median_b).c_str(), s.total_a, s.total_b, ratio(s.total_a, s.total_b).c_str());
    }
}

int run_compare(const CompareOptions& options) {
    const recorder::Recording a(options.a);
    const recorder::Recording b(options.b);
    const recorder::ComparisonReport report = recorder::compare_recordings(a, b);
    std::printf("a = %s (%llu frames), b = %s (%llu frames): %llu frames matched by frame number\n", options.a.c_str(),
                static_cast<unsigned long long>(a.frames_complete()), options.b.c_str(),
                static_cast<unsigned long long>(b.frames_complete()), static_cast<unsigned long long>(report.matched_frames));
    if (report.frames_only_a + report.frames_only_b > 0) {
        std::printf("frames only in a: %llu, only in b: %llu\n", static_cast<unsigned long long>(report.frames_only_a),
                    static_cast<unsigned long long>(report.frames_only_b));
    }
    if (report.time_differences > 0) {
        std::printf("times: %llu matched frames were sampled at other times, the first frame %u (fps %g vs %g)\n",
                    static_cast<unsigned long long>(report.time_differences), *report.first_time_difference, a.fps(),
                    b.fps());
    }
    if (report.differences.empty()) {
        std::printf("pairs: identical in every matched frame\n");
    } else {
        std::printf("pairs: first difference at frame %u; %zu frames differ\n", report.differences.front().frame,
                    report.differences.size());
        std::printf("frame\tonly_in_a\tonly_in_b\n");
        for (std::size_t i = 0; i < report.differences.size() && i < options.max_frames; ++i) {
            const recorder::FrameDifference& d = report.differences[i];
            std::printf("%u\t%llu\t%llu\n", d.frame, static_cast<unsigned long long>(d.only_a),
                        static_cast<unsigned long long>(d.only_b));
        }
        if (report.differences.size() > options.max_frames) {
            std::printf("... %zu more frames differ (--max-frames)\n", report.differences.size() - options.max_frames);
        }
    }
    print_stages(report);
    return report.identical_pairs() ? 0 : 1;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
    auto options = std::make_shared<CompareOptions>();
    CLI::App* compare = app.add_subcommand("compare", "Compare the pairs and times of two recordings; exit 1 when pairs differ");
    compare->add_option("a", options->a, "First recording")->required()->type_name("A.h5");
    compare->add_option("b", options->b, "Second recording")->required()->type_name("B.h5");
    compare->add_option("--max-frames", options->max_frames, "Differing frames to list")
        ->check(whole_number(0, 1000000, "of frames"))
        ->capture_default_str();
    compare->footer("Frames are matched by scene frame number. Exit codes: 0 the same frames with identical pairs,\n"
                    "1 pairs (or the recorded frames) differ, 2 error.");
    return {compare, [options] { return run_compare(*options); }};
}

}  // namespace collidescope::app
