// `collidescope join`: recordings of contiguous frame ranges of one session -> one recording.

#include "commands.hpp"
#include "number_checks.hpp"

#include "collidescope/recorder/join.hpp"

#include <cstdio>
#include <memory>

namespace collidescope::app {
namespace {

struct JoinCommandOptions {
    std::vector<std::string> parts;
    std::string output;
    recorder::JoinOptions join;
    bool virtual_layout = false;  ///< --virtual
};

int run_join(const JoinCommandOptions& options) {
    const std::vector<std::filesystem::path> parts(options.parts.begin(), options.parts.end());
    recorder::JoinOptions join = options.join;
    if (options.virtual_layout) join.layout = recorder::JoinLayout::Virtual;
    const recorder::JoinSummary summary = recorder::join_recordings(parts, options.output, join);
    std::string mapped;
    if (summary.virtual_datasets > 0) {
        mapped.append("; ").append(std::to_string(summary.virtual_datasets)).append(" datasets virtual, ");
        mapped.append(std::to_string(summary.virtual_rows)).append(" rows left in the parts, which must stay beside it");
    }
    std::fprintf(stderr, "joined %llu parts, %llu frames -> %s (%llu chunks copied raw, %.1f MiB; %llu rows re-encoded%s)%s\n",
                 static_cast<unsigned long long>(summary.parts), static_cast<unsigned long long>(summary.frames),
                 options.output.c_str(), static_cast<unsigned long long>(summary.raw_chunks),
                 static_cast<double>(summary.raw_bytes) / (1 << 20), static_cast<unsigned long long>(summary.rewritten_rows),
                 mapped.c_str(),
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
    join->add_flag("--virtual", options->virtual_layout,
                   "Map the large datasets onto the parts' rows (HDF5 virtual datasets) instead of copying them: fast and\n"
                   "small, but the parts are then the data and must stay beside the output (moved with it)");
    join->add_option("--virtual-min-rows", options->join.virtual_min_rows,
                     "With --virtual: map a dataset when the parts hold at least this many of its rows each, on average")
        ->check(whole_number(0, std::int64_t{1} << 40, "of rows"))
        ->capture_default_str();
    join->footer("The parts must come from one session (scene, method, options, build) with frame ranges that meet\n"
                 "exactly. The output is written as FILE.partial and renamed when complete; it reads as the recording\n"
                 "of one run (compare, validate, inspect, replay, h5py). With --virtual, the output names the parts by\n"
                 "their paths relative to its directory, and every reader checks they are there (a missing part is an\n"
                 "error naming it, never zeros). Exit codes: 0 joined, 2 error.");
    return {join, [options] { return run_join(*options); }};
}

}  // namespace collidescope::app
