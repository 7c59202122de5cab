// Running the command line from tests.

#include "app/cli_runner.hpp"

#include "support/brute_reference.hpp"

#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace collidescope::testing {
namespace {

std::string shell_quote(const std::string& word) {
    std::string quoted = "'";
    for (const char c : word) {
        if (c == '\'') {
            quoted += "'\\''";  // close, escaped quote, reopen
        } else {
            quoted += c;
        }
    }
    quoted += '\'';
    return quoted;
}

std::string frame_file_name(const std::string& name, int number) {
    char digits[16];
    std::snprintf(digits, sizeof digits, "%04d", number);
    return name + "." + digits + ".ply";
}

}  // namespace

std::vector<std::string> CliResult::err_lines() const {
    std::vector<std::string> lines;
    std::istringstream in(err);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

CliResult run_cli(const std::vector<std::string>& args, const std::filesystem::path& directory) {
    const std::filesystem::path out = directory / "cli.stdout";
    const std::filesystem::path err = directory / "cli.stderr";
    std::string command = "cd ";
    command += shell_quote(directory.string());
    command += " && ";
    command += shell_quote(COLLIDESCOPE_BIN);
    for (const std::string& arg : args) {
        command += ' ';
        command += shell_quote(arg);
    }
    command += " </dev/null >";
    command += shell_quote(out.string());
    command += " 2>";
    command += shell_quote(err.string());
    const int status = std::system(command.c_str());
    CliResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_text(out);
    result.err = read_text(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return result;
}

std::vector<FramePair> parse_pairs_tsv(const std::string& text) {
    std::vector<FramePair> pairs;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (end == std::string::npos) ADD_FAILURE() << "last line without newline: " << line;
        std::uint32_t fields[5] = {};
        const char* cursor = line.data();
        const char* const line_end = line.data() + line.size();
        bool ok = true;
        for (int k = 0; k < 5 && ok; ++k) {
            const auto [next, error] = std::from_chars(cursor, line_end, fields[k]);
            ok = error == std::errc() && next != cursor && (k == 4 ? next == line_end : next != line_end && *next == '\t');
            cursor = next + 1;
        }
        if (!ok) {
            ADD_FAILURE() << "malformed TSV line: '" << line << "'";
            break;
        }
        pairs.push_back({fields[0], {fields[1], fields[2], fields[3], fields[4]}});
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return pairs;
}

std::vector<std::string> write_scene_files(const Scene& scene, const std::filesystem::path& directory,
                                           int first_number) {
    std::vector<std::string> patterns;
    for (std::uint32_t o = 0; o < scene.source->object_count(); ++o) {
        patterns.push_back((directory / (scene.source->object_name(o) + ".%04d.ply")).string());
    }
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        const Frame frame = scene.source->frame(f);
        for (std::uint32_t o = 0; o < frame.objects.size(); ++o) {
            const MeshData mesh{frame.objects[o].vertices, frame.objects[o].topology->triangles};
            write_ply(directory / frame_file_name(scene.source->object_name(o), first_number + static_cast<int>(f)), mesh);
        }
    }
    return patterns;
}

std::vector<FramePair> reference_frame_pairs(const Scene& scene, bool self_collision) {
    std::vector<FramePair> pairs;
    for (std::uint32_t f = 0; f < scene.source->frame_count(); ++f) {
        for (const TrianglePair& pair : reference_colliding_pairs(scene.source->frame(f), self_collision)) {
            pairs.push_back({f, pair});
        }
    }
    return pairs;
}

}  // namespace collidescope::testing
