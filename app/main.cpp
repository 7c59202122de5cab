// collidescope: the command line. Registers the subcommands, parses, runs one, and turns
// every error into one line on stderr and exit code 2 (the library never prints or exits).

#include "commands.hpp"
#include "ranks/ranks.hpp"

#include "collidescope/error.hpp"
#include "collidescope/memory.hpp"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

constexpr int k_exit_error = 2;

std::string version_line() {
    return std::string("collidescope ") + COLLIDESCOPE_VERSION + " (git " + COLLIDESCOPE_GIT_REVISION +
           ")";
}

// One line, whatever the message holds (a library's message may carry newlines).
int print_error(std::string message) {
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
    for (char& c : message) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    // One write: under mpirun every rank's stderr goes to the same terminal.
    std::cerr << "collidescope: error: " + collidescope::app::ranks::error_prefix() + message + '\n';
    return k_exit_error;
}

// --help and --version print and succeed; anything else is a usage error, exit 2.
int handle_parse_error(const CLI::App& app, const CLI::ParseError& error) {
    if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error);
    return print_error(std::string(error.what()) + " (see --help)");
}

int run(int argc, char** argv) {
    CLI::App app("Collision detection between deforming triangle meshes, with recorded "
                 "sessions and offscreen debug images.", "collidescope");
    app.set_version_flag("--version", version_line(), "Print the version and git revision");
    app.require_subcommand(1);
    const std::vector<collidescope::app::Command> commands = {
        collidescope::app::add_check_command(app),
        collidescope::app::add_record_command(app),
        collidescope::app::add_inspect_command(app),
        collidescope::app::add_validate_command(app),
        collidescope::app::add_compare_command(app),
        collidescope::app::add_join_command(app),
        collidescope::app::add_replay_command(app),
        collidescope::app::add_export_command(app),
        collidescope::app::add_bench_command(app),
    };
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return handle_parse_error(app, error);
    }
    try {
        for (const collidescope::app::Command& command : commands) {
            if (!command.parser->parsed()) continue;
            const std::string name = command.parser->get_name();
            if (collidescope::app::ranks::parallel() && name != "check" && name != "record" && name != "replay") {
                return print_error(name + " does not run frame-parallel: run it without mpirun (check, record and replay do)");
            }
            return command.run();
        }
        return print_error("no subcommand given (see --help)");
    } catch (const collidescope::InputError& error) {
        return print_error(error.what());
    } catch (const collidescope::UnavailableError& error) {
        return print_error(error.what());
    } catch (const std::exception& error) {
        return print_error(error.what());
    }
}

}  // namespace

int main(int argc, char** argv) {
    // Frames free and allocate the same large buffers again: keep them (collidescope/memory.hpp).
    collidescope::keep_freed_memory();
    // Under mpirun each rank runs the command on its block of frames; rank 0 assembles the
    // outputs (ranks.hpp). Serially this is just run().
    collidescope::app::ranks::Launch ranks(argc, argv);
    return ranks.finish(run(argc, argv));
}
