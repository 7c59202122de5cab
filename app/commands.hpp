#pragma once
// The subcommands of `collidescope`, one file each (check_command.cpp, ...). main.cpp registers them,
// parses the command line, and runs the one that was given.

#include <CLI/CLI.hpp>

#include <functional>

namespace collidescope::app {

/// A registered subcommand: its CLI11 parser and what runs it once parsed. `run` returns the
/// exit code (0 no collisions, 1 collisions found, 2 never: errors are thrown to main).
struct Command {
    CLI::App* parser = nullptr;
    std::function<int()> run;
};

/// `collidescope check`: collision pairs per frame of a scene (check_command.cpp).
Command add_check_command(CLI::App& app);

/// `collidescope record`: a session's trace to one HDF5 file (record_command.cpp, docs/reference/recording.md).
Command add_record_command(CLI::App& app);

/// `collidescope inspect`: what a recording holds, as text or JSON (inspect_command.cpp).
Command add_inspect_command(CLI::App& app);

/// `collidescope validate`: checks a recording's invariants; exit 1 when one fails (validate_command.cpp).
Command add_validate_command(CLI::App& app);

/// `collidescope compare`: pairs and times of two recordings; exit 1 when pairs differ (compare_command.cpp).
Command add_compare_command(CLI::App& app);

/// `collidescope replay`: a recording -> annotated PNG frames, a contact sheet; --diff two (replay_command.cpp).
Command add_replay_command(CLI::App& app);

/// `collidescope export`: a built-in scene as PLY frame sequences + scene.json (export_command.cpp).
Command add_export_command(CLI::App& app);

/// `collidescope join`: part recordings of contiguous frame ranges -> one recording (join_command.cpp).
Command add_join_command(CLI::App& app);

/// `collidescope bench`: every method on every data set, CSVs, plots, a table (bench_command.cpp).
Command add_bench_command(CLI::App& app);

}  // namespace collidescope::app
