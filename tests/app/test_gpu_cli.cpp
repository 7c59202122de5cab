// Mode 2 on the command line: --method gpu's options, and what happens when no GL context can
// be made (Mesa refuses an OpenGL 4.5 core context when told its GL version is 3.3; libglvnd
// finds no EGL vendor when pointed at none): check exits 2 with the reason, bench skips the GPU
// methods and says why.

#include "support/cli_runner.hpp"
#include "mesh/temp_files.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

namespace collidescope {
namespace {

using testing::read_text;
using testing::run_cli;
using testing_files::TempDir;

// Sets an environment variable for the scope (the child processes inherit it).
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : m_name(name) { ::setenv(name, value, 1); }
    ~ScopedEnv() { ::unsetenv(m_name); }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* m_name;
};

TEST(GpuCli, GpuMethodsMatchBruteWithTheirOptions) {
    TempDir dir;
    ASSERT_EQ(run_cli({"check", "--scene", "D:small", "--pairs", "brute.tsv", "--exit-zero", "-q"}, dir.path()).exit_code, 0);
    const std::vector<std::vector<std::string>> variants = {
        {"--method", "gpu"},
        {"--method", "gpu-naive"},
        {"--method", "gpu", "--gpu-cull", "flags", "--gpu-resolution", "16", "--gpu-views", "y"},
        {"--method", "gpu", "--gpu-fixed-views", "--gpu-no-sort", "--gpu-fixed-p", "--triangles-per-query", "3"},
        {"--method", "gpu", "--gl", "egl"},
        {"--method", "hybrid", "--gl", "egl"},
        {"--method", "gpu", "--gl", "osmesa"},
    };
    for (const std::vector<std::string>& variant : variants) {
        std::vector<std::string> args = {"check", "--scene", "D:small", "--pairs", "gpu.tsv", "--exit-zero", "-q"};
        args.insert(args.end(), variant.begin(), variant.end());
        const auto result = run_cli(args, dir.path());
        ASSERT_EQ(result.exit_code, 0) << result.err;
        EXPECT_EQ(read_text(dir.path() / "gpu.tsv"), read_text(dir.path() / "brute.tsv")) << variant.back();
    }
}

TEST(GpuCli, BadGpuViewsIsAUsageError) {
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "demo:small", "--method", "gpu", "--gpu-views", "xw"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("--gpu-views"), std::string::npos) << result.err;
}

TEST(GpuCli, NoContextMeansExit2WithTheReason) {
    const ScopedEnv no_gl45("MESA_GL_VERSION_OVERRIDE", "3.3");
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "demo:small", "--method", "gpu"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("GPU cull unavailable"), std::string::npos) << result.err;
    EXPECT_EQ(result.err_lines().size(), 1u) << result.err;
}

// With no EGL vendor library, libglvnd offers no display: --gl egl cannot be had, and says so.
TEST(GpuCli, NoEglMeansExit2WithTheReason) {
    const ScopedEnv no_vendor("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json");
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "demo:small", "--method", "gpu", "--gl", "egl"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("GPU cull unavailable: EGL"), std::string::npos) << result.err;
    EXPECT_EQ(result.err_lines().size(), 1u) << result.err;
}

TEST(GpuCli, UnknownGlBackendIsAUsageError) {
    TempDir dir;
    const auto result = run_cli({"check", "--scene", "demo:small", "--method", "gpu", "--gl", "glx"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("--gl"), std::string::npos) << result.err;
}

TEST(GpuCli, BenchSkipsUnavailableMethodsAndSaysWhy) {
    const ScopedEnv no_gl45("MESA_GL_VERSION_OVERRIDE", "3.3");
    TempDir dir;
    const auto result = run_cli({"bench", "--scenes", "demo:small", "--repeat", "1", "-o", "out"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.err.find("skipping method gpu: GPU cull unavailable"), std::string::npos) << result.err;
    EXPECT_NE(result.out.find("aabb"), std::string::npos) << result.out;
    EXPECT_EQ(result.out.find("gpu"), std::string::npos) << result.out;
}

}  // namespace
}  // namespace collidescope
