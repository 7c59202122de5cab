// `collidescope validate`: checks a recording's invariants, for CI pipelines.

#include "commands.hpp"

#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/validate.hpp"

#include <iostream>
#include <memory>
#include <set>

namespace collidescope::app {
namespace {

struct ValidateOptions {
    std::string file;
    bool allow_incomplete = false;  ///< accept a recording that was interrupted (killed)
    bool quiet = false;
};

int run_validate(const ValidateOptions& options) {
    const recorder::Recording recording(options.file);
    const recorder::ValidationReport report = recorder::validate_recording(recording);
    for (const std::string& line : report.problems) std::cerr << options.file << ": " << line << '\n';
    if (report.problems_omitted > 0) std::cerr << options.file << ": ... and " << report.problems_omitted << " more\n";
    bool ok = report.problems.empty();
    // Killed, stopped by a signal or cut short by a write error: partial, whatever its frames hold.
    const std::string partial = recording.partial_reason();
    if (!partial.empty() && !options.allow_incomplete) {
        std::cerr << options.file << ": partial: " << partial << "; " << report.frames_complete
                  << " frames complete (--allow-incomplete accepts it)\n";
        ok = false;
    }
    if (!options.quiet && !recording.virtual_sources().empty()) {
        // Opening checked every part: present, HDF5, with the rows each mapping reads.
        std::set<std::string> datasets, parts;
        for (const recorder::VirtualSource& source : recording.virtual_sources()) {
            datasets.insert(source.dataset);
            parts.insert(source.file);
        }
        std::string names;
        for (const std::string& part : parts) names += (names.empty() ? "" : ", ") + part;
        std::cerr << options.file << ": virtual join: " << datasets.size() << " datasets map rows of " << parts.size()
                  << " part files (" << names << "), every one present with the rows it needs\n";
    }
    if (!options.quiet) {
        std::cerr << options.file << ": " << (ok ? "valid" : "INVALID") << ", schema " << recording.version_major() << "."
                  << recording.version_minor() << ", " << report.frames_complete << " frames complete"
                  << (partial.empty() ? "" : " (partial)") << '\n';
    }
    return ok ? 0 : 1;
}

}  // namespace

Command add_validate_command(CLI::App& app) {
    auto options = std::make_shared<ValidateOptions>();
    CLI::App* validate = app.add_subcommand("validate", "Check a recording's invariants; exit 1 when one fails");
    validate->add_option("file", options->file, "A recording")->required()->type_name("FILE.h5");
    validate->add_flag("--allow-incomplete", options->allow_incomplete,
                       "Accept an interrupted recording (its complete frames are still checked)");
    validate->add_flag("-q,--quiet", options->quiet, "Only the problems on stderr");
    validate->footer(
        "Checks: schema version, a unit on every dataset, per-frame datasets of equal length, monotone frame numbers,\n"
        "offsets starting at 0, non-decreasing and in range, pairs canonical, sorted and naming existing triangles,\n"
        "counts (colliding_pairs, triangles) matching the arrays, positions of the topology in force, known methods,\n"
        "finite non-negative times, and that the recording is complete: the writer finished and no signal stopped it\n"
        "early (a partial recording is invalid unless --allow-incomplete). A virtual join (join --virtual, mpirun record):\n"
        "every part file it maps is present, readable and holds the rows its mappings read (listed).\n"
        "Exit codes: 0 valid, 1 invalid (problems on stderr), 2 error (not a recording, unreadable, newer schema).");
    return {validate, [options] { return run_validate(*options); }};
}

}  // namespace collidescope::app
