// make_memory_source: topology sharing and revisions, frames, and validation. (The memory
// source lives in engine/src/scene; its tests sit here with the pipeline that consumes it.)

#include "support/scene_builders.hpp"

#include "collidescope/error.hpp"
#include "collidescope/scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace collidescope {
namespace {

std::string input_error_message(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected an InputError";
    return "";
}

TEST(MemorySource, SharesTopologyWhileTrianglesStayEqual) {
    const MeshData sheet = testing::grid_sheet(2, 1.0);
    MeshData changed = sheet;
    changed.triangles.pop_back();
    const std::shared_ptr<FrameSource> source = make_memory_source(
        {"a", "b"}, {{sheet, sheet}, {testing::translated(sheet, Vec3(1, 0, 0)), changed}, {sheet, changed}});
    ASSERT_EQ(source->frame_count(), 3u);
    ASSERT_EQ(source->object_count(), 2u);
    EXPECT_EQ(source->object_name(1), "b");
    const Frame f0 = source->frame(0), f1 = source->frame(1), f2 = source->frame(2);

    // Object a: same triangles throughout, one Topology.
    EXPECT_EQ(f0.objects[0].topology, f1.objects[0].topology);
    EXPECT_EQ(f1.objects[0].topology, f2.objects[0].topology);
    EXPECT_EQ(f1.objects[0].vertices[0], Vec3(1, 0, 0));
    // Object b: changes at frame 1, then stays.
    EXPECT_NE(f0.objects[1].topology->revision, f1.objects[1].topology->revision);
    EXPECT_EQ(f1.objects[1].topology, f2.objects[1].topology);
    EXPECT_EQ(f1.objects[1].triangle_count(), sheet.triangles.size() - 1);
    // Revisions are unique across objects, even for equal triangles.
    EXPECT_NE(f0.objects[0].topology->revision, f0.objects[1].topology->revision);
    EXPECT_EQ(f2.index, 2u);
}

TEST(MemorySource, RevisionsAreUniqueAcrossSources) {
    const MeshData sheet = testing::grid_sheet(1, 1.0);
    const auto first = make_memory_source({"a"}, {{sheet}});
    const auto second = make_memory_source({"a"}, {{sheet}});
    EXPECT_NE(first->frame(0).objects[0].topology->revision, second->frame(0).objects[0].topology->revision);
}

TEST(MemorySource, RejectsFramesWithAnotherObjectCount) {
    const MeshData sheet = testing::grid_sheet(1, 1.0);
    const std::string message = input_error_message([&] { make_memory_source({"a", "b"}, {{sheet, sheet}, {sheet}}); });
    EXPECT_NE(message.find("frame 1"), std::string::npos) << message;
}

TEST(MemorySource, RejectsNoFramesOrNoObjects) {
    EXPECT_THROW(make_memory_source({"a"}, {}), InputError);
    EXPECT_THROW(make_memory_source({}, {{}}), InputError);
}

TEST(MemorySource, ValidatesMeshesNamingObjectAndFrame) {
    const MeshData sheet = testing::grid_sheet(1, 1.0);
    MeshData bad_index = sheet;
    bad_index.triangles[0][1] = 99;
    MeshData nan = sheet;
    nan.vertices[2].y() = std::numeric_limits<double>::quiet_NaN();
    for (const MeshData& bad : {bad_index, nan, MeshData{}}) {
        const std::string message = input_error_message([&] { make_memory_source({"a", "b"}, {{sheet, sheet}, {sheet, bad}}); });
        EXPECT_NE(message.find("'b'"), std::string::npos) << message;
        EXPECT_NE(message.find("frame 1"), std::string::npos) << message;
    }
}

TEST(MemorySource, RejectsFramesOutOfRange) {
    const auto source = make_memory_source({"a"}, {{testing::grid_sheet(1, 1.0)}});
    EXPECT_THROW(source->frame(1), std::out_of_range);
}

}  // namespace
}  // namespace collidescope
