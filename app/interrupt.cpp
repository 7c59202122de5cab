// SIGINT / SIGTERM as a flag read between frames.

#include "interrupt.hpp"

#include <csignal>

#include <signal.h>

namespace collidescope::app {
namespace {

// Written by the handler only; sig_atomic_t is what a handler may store to.
volatile std::sig_atomic_t g_signal = 0;
int g_guards = 0;  ///< guards alive (main thread only)

void on_signal(int signal) { g_signal = signal; }

constexpr int k_signals[] = {SIGINT, SIGTERM};
struct sigaction g_previous[2];

}  // namespace

InterruptGuard::InterruptGuard() {
    // A guard inside another keeps what the outer one caught (a signal that came before the
    // inner one was made still stops the frame loop).
    if (g_guards++ == 0) g_signal = 0;
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    // SA_RESETHAND: a second Ctrl-C kills (the user insists); SA_RESTART: reads and writes in
    // flight on other threads are not cut short by EINTR.
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    for (int k = 0; k < 2; ++k) sigaction(k_signals[k], &action, &g_previous[k]);
}

InterruptGuard::~InterruptGuard() {
    --g_guards;
    for (int k = 0; k < 2; ++k) sigaction(k_signals[k], &g_previous[k], nullptr);
}

int InterruptGuard::signal() const { return g_signal; }

std::string signal_name(int signal) {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    return "signal " + std::to_string(signal);
}

int interrupted_exit_code(int signal) { return 128 + signal; }

}  // namespace collidescope::app
