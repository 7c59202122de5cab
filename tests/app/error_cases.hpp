#pragma once
// A table-driven check of bad input through the command line: each case writes its files,
// runs `collidescope`, and expects its exit code and exactly one stderr line, the error, that
// names every given word (the file and the element: frame, object, vertex or face index, byte
// offset, line, dataset). With COLLIDESCOPE_ERROR_TABLE=FILE set, each case appends its row
// (class, command, the message as printed, exit code) to FILE as Markdown: docs/reference/robustness.md
// holds that table, copied from a real run.

#include "support/cli_runner.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace collidescope::testing {

struct ErrorCase {
    std::string what;                           ///< the class of bad input, in words
    std::function<void(const std::filesystem::path&)> setup;  ///< writes the files into the folder
    std::vector<std::string> args;              ///< the command line, after `collidescope`
    std::vector<std::string> names;             ///< words the error line must hold
    int exit_code = 2;
};

inline std::string joined(const std::vector<std::string>& args) {
    std::string line;
    for (const std::string& arg : args) line += (line.empty() ? "" : " ") + arg;
    return line;
}

/// Runs one case in `directory` (created empty by the caller) and checks it.
inline void expect_error_case(const ErrorCase& c, const std::filesystem::path& directory) {
    SCOPED_TRACE(c.what + ": collidescope " + joined(c.args));
    if (c.setup) c.setup(directory);
    const CliResult result = run_cli(c.args, directory);
    EXPECT_EQ(result.exit_code, c.exit_code) << result.err;
    const std::vector<std::string> lines = result.err_lines();
    ASSERT_EQ(lines.size(), 1u) << result.err;
    const std::string& line = lines[0];
    if (c.exit_code == 2) {
        EXPECT_EQ(line.rfind("collidescope: error: ", 0), 0u) << line;
    }
    for (const std::string& name : c.names) EXPECT_NE(line.find(name), std::string::npos) << line << "\ndoes not name " << name;
    if (const char* table = std::getenv("COLLIDESCOPE_ERROR_TABLE"); table != nullptr && *table != '\0') {
        std::string message = line;
        std::string escaped;
        for (const char ch : message) escaped += ch == '|' ? std::string("\\|") : std::string(1, ch);
        std::ofstream(table, std::ios::app) << "| " << c.what << " | `collidescope " << joined(c.args) << "` | `" << escaped
                                            << "` | " << result.exit_code << " |\n";
    }
}

}  // namespace collidescope::testing
