#pragma once
// `collidescope check --between-frames`: continuous detection over each interval between
// consecutive frames (collidescope/between_frames.hpp), with check's outputs.

#include "engine_cli_options.hpp"

#include <string>
#include <vector>

namespace collidescope::app {

/// What `check --between-frames` reads from check's options.
struct BetweenFramesRun {
    std::vector<std::string> inputs;
    std::string scene;
    std::string frames;
    std::string pairs;
    std::string stats;
    double tolerance = 0;  ///< --ccd-tolerance (0: 1e-6 of each interval's extent)
    bool exit_zero = false;
    bool quiet = false;
    EngineOptions engine;
};

/// A toi as printed with `unit` (1e-9: nine decimals): rounded down, so the printed number is
/// still a lower bound (printf rounds to nearest: less 0.6 units first, never below 0).
double printed_toi(double toi, double unit);

/// Runs it; returns the exit code (0 none, 1 contact in some interval).
int run_check_between(const BetweenFramesRun& run);

}  // namespace collidescope::app
