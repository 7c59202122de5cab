#pragma once
// Graceful stop on SIGINT and SIGTERM for the frame loops of `check` and `record`: the first
// signal only sets a flag, read between frames, so the current frame finishes, the outputs are
// closed as partial and the run says how many frames it wrote. The handler is one-shot: a
// second signal has the default effect and ends the process at once.

#include <string>

namespace collidescope::app {

/// Catches SIGINT and SIGTERM while alive; restores the previous handlers when destroyed.
/// Guards nest (made and destroyed in reverse order, on the main thread): an inner guard sees a
/// signal the outer one caught before it was made.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// The signal that asked to stop (SIGINT or SIGTERM), or 0 while none came.
    int signal() const;
};

/// "SIGINT", "SIGTERM" (or "signal N").
std::string signal_name(int signal);

/// Exit code of a run stopped by `signal`: 128 + signal, as a shell reports a process killed
/// by it (130 for SIGINT, 143 for SIGTERM), so scripts tell it from success, collisions (1)
/// and errors (2).
int interrupted_exit_code(int signal);

}  // namespace collidescope::app
