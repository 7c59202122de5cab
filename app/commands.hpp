#pragma once
// The subcommands of `collidescope`, one file each (check.cpp, ...). main.cpp registers them,
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

/// `collidescope check`: collision pairs per frame of a scene (check.cpp).
Command add_check_command(CLI::App& app);

}  // namespace collidescope::app
