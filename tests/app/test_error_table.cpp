// Every class of bad input a user's files can hold, through `collidescope check` (and record):
// exit 2 and one line naming the file and the element, saying what was expected
// (tests/app/error_cases.hpp; docs/reference/robustness.md holds the table these cases print).

#include "app/error_cases.hpp"
#include "mesh/temp_files.hpp"
#include "support/point_cache_writer.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace collidescope {
namespace {

namespace fs = std::filesystem;
using testing::ErrorCase;
using testing_files::TempDir;
using testing_files::write_text;

std::string ply_header(const std::string& format, int vertices, int faces, const std::string& face_list = "uchar int") {
    return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
           "\nproperty list " + face_list + " vertex_indices\nend_header\n";
}

std::string ascii_ply(const std::string& body, int vertices, int faces) { return ply_header("ascii", vertices, faces) + body; }

constexpr const char* k_vertices = "0 0 0\n1 0 0\n0 1 0\n";

// A file writer for ErrorCase::setup.
std::function<void(const fs::path&)> file(const std::string& name, const std::string& text) {
    return [=](const fs::path& dir) { write_text(dir / name, text); };
}

// good.ply beside every case: check needs a second object for the bad one to be object 1.
std::vector<std::string> check(std::vector<std::string> inputs) {
    std::vector<std::string> args = {"check", "good.ply"};
    args.insert(args.end(), inputs.begin(), inputs.end());
    return args;
}

std::vector<ErrorCase> mesh_cases() {
    const std::string be_vertices(3 * 12 - 5, '\0');  // the third vertex cut 5 bytes short
    return {
        {"missing file", nullptr, check({"missing.ply"}), {"missing.ply", "no such file"}},
        {"a directory given as a mesh", [](const fs::path& d) { fs::create_directory(d / "dir.ply"); }, check({"dir.ply"}),
         {"dir.ply", "directory"}},
        {"PLY: no magic", file("magic.ply", "solid x\n"), check({"magic.ply"}), {"magic.ply", "line 1", "'ply'"}},
        {"PLY: header cut before end_header", file("header.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nprop"),
         check({"header.ply"}), {"header.ply", "line 4", "'prop'", "end_header"}},
        {"PLY: unknown format", file("format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n"), check({"format.ply"}),
         {"format.ply", "line 2", "binary_middle_endian"}},
        {"PLY: unknown property type",
         file("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n"), check({"type.ply"}),
         {"type.ply", "line 4", "quad"}},
        {"PLY: no x/y/z on vertices",
         file("xyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float u\nend_header\n0\n"), check({"xyz.ply"}),
         {"xyz.ply", "'x'"}},
        {"PLY: floating-point face indices", file("float.ply", ply_header("ascii", 3, 1, "uchar float") + k_vertices + "3 0 1 2\n"),
         check({"float.ply"}), {"float.ply", "floating-point"}},
        {"PLY binary little-endian: body cut short",
         [](const fs::path& d) {
             write_ply(d / "whole.ply", testing::grid_sheet(4, 1.0));
             const std::string bytes = testing::read_text(d / "whole.ply");
             write_text(d / "cut.ply", bytes.substr(0, bytes.size() - 20));
         },
         check({"cut.ply"}), {"cut.ply", "face 30", "byte"}},
        {"PLY binary big-endian: vertices cut short", file("be.ply", ply_header("binary_big_endian", 3, 1) + be_vertices),
         check({"be.ply"}), {"be.ply", "vertex 2", "byte"}},
        {"PLY binary: negative list length",
         file("neg.ply", ply_header("binary_little_endian", 3, 1, "int int") + std::string(36, '\0') + "\xff\xff\xff\xff"),
         check({"neg.ply"}), {"neg.ply", "face 0", "negative", "byte"}},
        {"PLY ascii: bad number", file("number.ply", ascii_ply("0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", 3, 1)), check({"number.ply"}),
         {"number.ply", "vertex 1", "line 11", "'x'"}},
        {"PLY ascii: body cut short", file("short.ply", ascii_ply("0 0 0\n1 0 0\n", 3, 1)), check({"short.ply"}),
         {"short.ply", "vertex 2", "expected 3 vertex"}},
        {"PLY: face index out of range", file("index.ply", ascii_ply(std::string(k_vertices) + "3 0 1 7\n", 3, 1)),
         check({"index.ply"}), {"index.ply", "face 0", "vertex index 7", "3 vertices"}},
        {"PLY: face with 2 corners", file("corners.ply", ascii_ply(std::string(k_vertices) + "2 0 1\n", 3, 1)),
         check({"corners.ply"}), {"corners.ply", "face 0", "at least 3"}},
        {"PLY: NaN coordinate", file("nan.ply", ascii_ply("0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", 3, 1)), check({"nan.ply"}),
         {"nan.ply", "vertex 1", "y"}},
        {"PLY: no triangles", file("empty.ply", ascii_ply(k_vertices, 3, 0)), check({"empty.ply"}), {"empty.ply", "no triangles"}},
        {"gzip: corrupt .ply.gz", file("bad.ply.gz", std::string("\x1f\x8b\x08\x00", 4) + std::string(40, 'z')),
         check({"bad.ply.gz"}), {"bad.ply.gz", "gzip"}},
        {"OBJ: bad number", file("number.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n"), check({"number.obj"}),
         {"number.obj", "line 2", "'zero'"}},
        {"OBJ: vertex with 2 coordinates", file("two.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n"), check({"two.obj"}),
         {"two.obj", "line 2", "3 coordinates"}},
        {"OBJ: face index 0", file("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), check({"zero.obj"}),
         {"zero.obj", "line 4", "start at 1"}},
        {"OBJ: face index out of range", file("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"), check({"range.obj"}),
         {"range.obj", "line 4", "9"}},
        {"OBJ: face with 2 corners", file("corners.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"), check({"corners.obj"}),
         {"corners.obj", "line 4", "at least 3"}},
        {"OBJ: infinite coordinate", file("inf.obj", "v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n"), check({"inf.obj"}),
         {"inf.obj", "vertex 1", "z"}},
        {"other formats (assimp): unreadable", file("broken.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n"),
         check({"broken.stl"}), {"broken.stl", "assimp"}},
        {"OFF: counts the file cannot hold (assimp would allocate them)",
         file("huge.off", "OFF\n353535235358 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), check({"huge.off"}),
         {"huge.off", "header", "353535235358 vertices"}},
        {"assimp: a scene with a null node (RAW, two groups)", file("two.raw", "a\n0 0 0 1 0 0 0 1 0\n\nb\n0 0 1 1 0 1 0 1 1\n"),
         check({"two.raw"}), {"two.raw", "broken scene", "node '<RawRoot>'", "children 1 of 2"}},
        // assimp's OpenGEX parser writes "nullptr returned by creating DDLNode." to std::cerr.
        {"assimp: no mesh in the file (OpenGEX camera)", file("camera.ogex", "CameraObject {}\n"), check({"camera.ogex"}),
         {"camera.ogex", "no triangles"}},
    };
}

std::vector<ErrorCase> scene_cases() {
    const auto sequence = [](const std::string& prefix, int frames) {
        return [=](const fs::path& d) {
            for (int f = 0; f < frames; ++f) write_ply(d / (prefix + std::to_string(f) + ".ply"), testing::grid_sheet(2, 1.0));
        };
    };
    return {
        {"frame pattern matching no file", nullptr, check({"nothing.####.ply"}), {"nothing.####.ply", "no file matches"}},
        {"frame pattern with two number fields", sequence("seq.", 2), check({"seq.%d.%04d.ply"}),
         {"seq.%d.%04d.ply", "more than one"}},
        {"frame pattern with a gap in its numbers",
         [=](const fs::path& d) {
             sequence("gap.", 3)(d);
             write_ply(d / "gap.5.ply", testing::grid_sheet(2, 1.0));
         },
         check({"gap.%d.ply"}), {"gap.%d.ply", "gap.3.ply is missing", "gap.5.ply exists", "0 to 5"}},
        {"objects with different frame counts",
         [=](const fs::path& d) {
             sequence("long.", 3)(d);
             sequence("short.", 2)(d);
         },
         {"check", "long.%d.ply", "short.%d.ply"}, {"short.%d.ply", "long.%d.ply", "frames"}},
        {"bad file in a later frame",
         [=](const fs::path& d) {
             sequence("seq.", 4)(d);
             write_text(d / "seq.2.ply", ascii_ply(std::string(k_vertices) + "3 0 1 5\n", 3, 1));
         },
         {"check", "-q", "seq.%d.ply"}, {"seq.2.ply", "face 0", "object 'seq'", "frame 2"}},
        {"scene.json: malformed JSON", file("broken.json", "{\"objects\": [ {\"pattern\": "), check({"broken.json"}),
         {"broken.json", "line 1", "column"}},
        {"scene.json: wrong type", file("wrong.json", "{\"objects\": 3}"), {"check", "wrong.json"},
         {"wrong.json", "objects", "expected"}},
        {"scene.json: object without pattern", file("nopattern.json", "{\"objects\": [{\"name\": \"a\"}]}"),
         {"check", "nopattern.json"}, {"nopattern.json", "objects[0].pattern", "missing"}},
        {"scene.json: pattern matching no file", file("none.json", "{\"objects\": [{\"pattern\": \"none.%04d.ply\"}]}"),
         {"check", "none.json"}, {"none.%04d.ply"}},
        {"scene.json: more frames than files",
         [=](const fs::path& d) {
             sequence("seq.", 2)(d);
             write_text(d / "frames.json", "{\"frames\": 5, \"objects\": [{\"pattern\": \"seq.%d.ply\"}]}");
         },
         {"check", "frames.json"}, {"frames.json", "frames", "5"}},
        {"--frames past the last frame", nullptr, {"check", "good.ply", "--frames", "0:5"}, {"--frames '0:5'", "1 frames"}},
        {"--pairs in a missing folder", nullptr, {"check", "good.ply", "--pairs", "no/dir/pairs.tsv"}, {"no/dir/pairs.tsv"}},
        {"record -o in a missing folder", nullptr, {"record", "good.ply", "-o", "no/dir/run.h5"}, {"no/dir/run.h5"}},
    };
}

// Point caches beside good.ply (a 2 x 2 grid sheet: 9 vertices): `good.ply@CACHE`.
std::vector<ErrorCase> point_cache_cases() {
    const auto frames = [](std::size_t points, std::size_t count) {
        return testing::PositionFrames(count, std::vector<Vec3>(points, Vec3(0.5, 0.5, 0.0)));
    };
    const auto cut = [](const fs::path& file, std::uintmax_t bytes) { fs::resize_file(file, fs::file_size(file) - bytes); };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {
        {"PC2: cut short", [=](const fs::path& d) { testing::write_pc2(d / "cut.pc2", frames(9, 3)); cut(d / "cut.pc2", 5); },
         check({"good.ply@cut.pc2"}), {"cut.pc2", "header", "3 samples x 9 points", "truncated"}},
        {"PC2: counts that lie (bytes left over)",
         [=](const fs::path& d) {
             testing::write_pc2(d / "lie.pc2", frames(9, 3));
             std::ofstream(d / "lie.pc2", std::ios::app) << "extra";
         },
         check({"good.ply@lie.pc2"}), {"lie.pc2", "header", "counts are wrong"}},
        {"PC2: no magic", file("magic.pc2", std::string(40, 'x')), check({"good.ply@magic.pc2"}), {"magic.pc2", "POINTCACHE2"}},
        {"MDD: cut short", [=](const fs::path& d) { testing::write_mdd(d / "cut.mdd", frames(9, 2), {0, 1}); cut(d / "cut.mdd", 1); },
         check({"good.ply@cut.mdd"}), {"cut.mdd", "header", "2 frames x 9 points", "truncated"}},
        {"MDD: NaN time", [=](const fs::path& d) { testing::write_mdd(d / "time.mdd", frames(9, 2), {0.0f, std::nanf("")}); },
         check({"good.ply@time.mdd"}), {"time.mdd", "time of frame 1", "not finite"}},
        {"point cache: NaN position in a later frame",
         [=](const fs::path& d) {
             testing::PositionFrames positions = frames(9, 3);
             positions[2][4].y() = nan;
             testing::write_mdd(d / "nan.mdd", positions, {0.0f, 0.1f, 0.2f});
         },
         {"check", "-q", "good.ply@nan.mdd"}, {"nan.mdd", "frame 2", "vertex 4", "coordinate y", "object 'good'"}},
        {"point cache: vertex count differs from the mesh's",
         [=](const fs::path& d) { testing::write_pc2(d / "short.pc2", frames(8, 2)); }, check({"good.ply@short.pc2"}),
         {"good.ply", "9 vertices", "short.pc2", "8 points"}},
        {"point cache: frame count differs from a sequence's",
         [=](const fs::path& d) {
             testing::write_pc2(d / "three.pc2", frames(9, 3));
             for (int f = 0; f < 2; ++f) write_ply(d / ("seq." + std::to_string(f) + ".ply"), testing::grid_sheet(2, 1.0));
         },
         {"check", "seq.%d.ply", "good.ply@three.pc2"}, {"seq.%d.ply", "2 frames", "good.ply@three.pc2", "3 frames"}},
        {"scene.json: cache without mesh", file("nomesh.json", R"({"objects": [{"pattern": "good.ply", "cache": "x.pc2"}]})"),
         {"check", "nomesh.json"}, {"nomesh.json", "objects[0].cache", "mesh"}},
        {"scene.json: missing cache", file("nocache.json", R"({"objects": [{"mesh": "good.ply", "cache": "none.pc2"}]})"),
         {"check", "nocache.json"}, {"none.pc2", "no such file"}},
    };
}

class ErrorTable : public ::testing::Test {
protected:
    void run_all(const std::vector<ErrorCase>& cases) {
        for (const ErrorCase& c : cases) {
            const TempDir dir;
            write_ply(dir / "good.ply", testing::grid_sheet(2, 1.0));
            testing::expect_error_case(c, dir.path());
        }
    }
};

TEST_F(ErrorTable, MeshFilesNameTheFileAndTheElement) { run_all(mesh_cases()); }

TEST_F(ErrorTable, ScenesPatternsAndOptionsNameTheFileAndTheElement) { run_all(scene_cases()); }

TEST_F(ErrorTable, PointCachesNameTheFileAndTheElement) { run_all(point_cache_cases()); }

}  // namespace
}  // namespace collidescope
