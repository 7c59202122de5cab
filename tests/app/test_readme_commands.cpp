// The README's two commands and .ci/run: CI runs exactly README's test command, and both
// commands use the paths the build really produces.

#include "support/cli_runner.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace collidescope {
namespace {

const std::filesystem::path k_source_dir = COLLIDESCOPE_SOURCE_DIR;

// The command in the ```sh block right after `marker` in README.md ("" when missing).
std::string readme_command(const std::string& marker) {
    std::istringstream readme(testing::read_text(k_source_dir / "README.md"));
    bool after_marker = false;
    bool in_block = false;
    for (std::string line; std::getline(readme, line);) {
        if (line == "<!-- " + marker + " -->") {
            after_marker = true;
        } else if (after_marker && line == "```sh") {
            in_block = true;
        } else if (in_block) {
            return line;
        }
    }
    return "";
}

std::vector<std::string> lines_of(const std::filesystem::path& file) {
    std::istringstream text(testing::read_text(file));
    std::vector<std::string> lines;
    for (std::string line; std::getline(text, line);) lines.push_back(line);
    return lines;
}

// The lines a command prints on stdout (its exit status must be 0).
std::vector<std::string> output_lines(const std::string& command) {
    std::vector<std::string> lines;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return lines;
    std::string text;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
    const int status = ::pclose(pipe);
    EXPECT_EQ(status, 0) << command;
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);) lines.push_back(line);
    return lines;
}

// CI runs README's two commands on a bare Debian 12 system: .ci/run ends with the
// fresh-machine script, and what that script runs is exactly README's (a) and (b).
TEST(ReadmeCommands, CiRunsBothCommandsVerbatimOnAFreshMachine) {
    const std::string main_job = readme_command("readme-command-a");
    const std::string tests = readme_command("readme-command-b");
    ASSERT_NE(main_job, "");
    ASSERT_NE(tests, "");
    EXPECT_NE(tests.find("ctest"), std::string::npos) << tests;
    const std::vector<std::string> ci = lines_of(k_source_dir / ".ci/run");
    ASSERT_GE(ci.size(), 3u);
    EXPECT_EQ(ci.front(), "#!/usr/bin/env bash");
    EXPECT_NE(std::find(ci.begin(), ci.end(), "set -euo pipefail"), ci.end());
    // CI=true is set by CI's own script, not by whoever starts it: the test guards read it.
    EXPECT_NE(std::find(ci.begin(), ci.end(), "export CI=true"), ci.end());
    EXPECT_EQ(ci.back(), "scripts/fresh-machine.sh --commands a,b")
        << ".ci/run must end by running README's commands (a) and (b) on a fresh machine";
    const std::string script = (k_source_dir / "scripts/fresh-machine.sh").string();
    EXPECT_EQ(output_lines(script + " --commands a,b --print-commands"),
              (std::vector<std::string>{main_job, tests}));
    // The set-up part of (a) is the command up to the build of the binary it then runs.
    const std::vector<std::string> setup = output_lines(script + " --commands a-setup --print-commands");
    ASSERT_EQ(setup.size(), 1u);
    EXPECT_EQ(main_job.rfind(setup[0] + " && build/app/collidescope ", 0), 0u) << setup[0];
    EXPECT_NE(setup[0].find("--target collidescope"), std::string::npos) << setup[0];
}

TEST(ReadmeCommands, ScriptsAreExecutable) {
    for (const char* script : {".ci/run", "scripts/setup.sh", "scripts/sanitize.sh", "scripts/fresh-machine.sh"}) {
        struct stat info {};
        ASSERT_EQ(::stat((k_source_dir / script).c_str(), &info), 0) << script;
        EXPECT_NE(info.st_mode & S_IXUSR, 0u) << script << " is not executable";
    }
}

TEST(ReadmeCommands, MainJobRunsTheBuiltBinary) {
    const std::string command = readme_command("readme-command-a");
    ASSERT_NE(command, "");
    EXPECT_EQ(command.rfind("scripts/setup.sh && ", 0), 0u) << command;
    // The binary the command runs is where this build puts it, relative to its build dir; the
    // main job records a built-in scene, then replays that recording into PNGs and a contact sheet.
    const std::filesystem::path binary = COLLIDESCOPE_BIN;
    const std::string run = "build/" + binary.parent_path().filename().string() + "/" + binary.filename().string();
    const std::size_t record = command.find(" && " + run + " record --scene ");
    const std::size_t replay = command.find(" && " + run + " replay ");
    ASSERT_NE(record, std::string::npos) << command;
    ASSERT_NE(replay, std::string::npos) << command;
    EXPECT_LT(record, replay) << command;
    // The file replay reads is the one record wrote, and the contact sheet is asked for.
    const std::size_t output = command.find(" -o ", record);
    ASSERT_LT(output, replay) << command;
    const std::string recording = command.substr(output + 4, command.find(' ', output + 4) - output - 4);
    EXPECT_EQ(command.find(" replay " + recording + " -o "), replay + 4 + run.size()) << command;
    EXPECT_NE(command.find(" --contact-sheet ", replay), std::string::npos) << command;
}

}  // namespace
}  // namespace collidescope
