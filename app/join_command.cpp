// `collidescope join`: recordings of contiguous frame ranges of one session -> one recording.

#include "commands.hpp"

#include "collidescope/recorder/join.hpp"

#include <cstdio>
#include <memory>

namespace collidescope::app {
namespace {

struct JoinCommandOptions {
    std::vector<std::string> parts;
    std::string output;
    recorder::JoinOptions join;
};

int run_join(const JoinCommandOptions& options) {
    const std::vector<std::filesystem::path> parts(options.parts.begin(), options.parts.end());
    const recorder::JoinSummary summary = recorder::join_recordings(parts, options.output, options.join);
    std::fprintf(stderr, "joined %llu parts, %llu frames -> %s (%llu chunks copied raw, %.1f MiB; %llu rows re-encoded)%s\n",
                 static_cast<unsigned long long>(summary.parts), static_cast<unsigned long long>(summary.frames),
                 options.output.c_str(), static_cast<unsigned long long>(summary.raw_chunks),
                 static_cast<double>(summary.raw_bytes) / (1 << 20), static_cast<unsigned long long>(summary.rewritten_rows),
                 summary.complete ? "" : "; PARTIAL: some parts were incomplete, the output is not marked finished");
    return 0;
}

}  // namespace

Command add_join_command(CLI::App& app) {
    auto options = std::make_shared<JoinCommandOptions>();
    CLI::App* join = app.add_subcommand(
        "join", "Join recordings of contiguous frame ranges (record --frames A:B) into one recording");
    join->add_option("parts", options->parts, "Part recordings, in any order")->required()->type_name("PART.h5");
    join->add_option("-o,--output", options->output, "The joined recording")->required()->type_name("FILE.h5");
    join->add_flag("--allow-incomplete", options->join.allow_incomplete,
                   "Join the complete frames of parts that did not finish (a killed rank); the output is then partial");
    join->footer("The parts must come from one session (scene, method, options, build) with frame ranges that meet\n"
                 "exactly. The output is written as FILE.partial and renamed when complete; it reads as the recording\n"
                 "of one run (compare, validate, inspect, replay, h5py). Exit codes: 0 joined, 2 error.");
    return {join, [options] { return run_join(*options); }};
}

}  // namespace collidescope::app
