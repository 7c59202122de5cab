// Helpers of the recorder tests.

#include "recording_helpers.hpp"

#include "support/scene_builders.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/recorder.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <random>

namespace collidescope::testing {

std::uint64_t frames_complete_now(const std::filesystem::path& file) {
    try {
        return recorder::Recording(file).frames_complete();
    } catch (const InputError&) {
        return 0;
    }
}

void expect_complete_rows_equal(const recorder::Recording& part, const recorder::Recording& whole) {
    const auto indices = part.frame_indices();
    const auto whole_indices = whole.frame_indices();
    for (std::uint64_t r = 0; r < part.frames_complete(); ++r) {
        ASSERT_EQ(indices[r], whole_indices[r]);
        EXPECT_EQ(part.pairs(r), whole.pairs(r)) << "frame row " << r;
        for (std::uint32_t k = 0; k < part.objects().size(); ++k) {
            EXPECT_EQ(part.positions(k, r), whole.positions(k, r)) << "object " << k << " row " << r;
        }
    }
}
namespace {

class CaptureSink final : public TraceSink {
public:
    void on_frame(const FrameReport& report) override {
        CapturedFrame frame;
        frame.stats = report.stats;
        frame.pairs.assign(report.colliding_pairs.begin(), report.colliding_pairs.end());
        for (const ObjectFrame& object : report.frame.objects) {
            frame.vertices.push_back(object.vertices.to_vector());  // a view lives only during on_frame
            frame.triangles.push_back(object.topology->triangles);
        }
        frames.push_back(std::move(frame));
    }
    std::vector<CapturedFrame> frames;
};

// Opens `file` read-write for an edit; fails the test on error.
hid_t open_rw(const std::filesystem::path& file) {
    const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    EXPECT_GE(id, 0) << "cannot open " << file << " for writing";
    return id;
}

}  // namespace

std::vector<CapturedFrame> record_in_process(const Scene& scene, const std::filesystem::path& file,
                                             std::uint32_t begin, std::uint32_t end, bool self_collision,
                                             const std::string& method) {
    PipelineConfig pipeline_config;
    pipeline_config.method = method;
    pipeline_config.self_collision = self_collision;
    pipeline_config.threads = 2;
    return record_in_process(scene, file, begin, end, pipeline_config);
}

std::vector<CapturedFrame> record_in_process(const Scene& scene, const std::filesystem::path& file,
                                             std::uint32_t begin, std::uint32_t end, const PipelineConfig& pipeline_config) {
    const std::string& method = pipeline_config.method;
    const bool self_collision = pipeline_config.self_collision;
    Pipeline pipeline(pipeline_config);
    CaptureSink capture;
    recorder::SessionInfo session;
    session.scene = scene.name;
    session.method = method;
    session.self_collision = self_collision;
    session.frame_begin = begin;
    session.frame_end = end;
    for (std::uint32_t k = 0; k < scene.source->object_count(); ++k) session.object_names.push_back(scene.source->object_name(k));
    session.frame_times = scene.frame_times;  // as `record` passes them (app/record_command.cpp)
    session.fps = scene.fps;
    session.clip = scene.clip;
    session.up_axis = scene.up_axis;
    recorder::RecorderConfig config;
    config.path = file;
    config.queue_bytes = 1u << 16;  // small: the engine waits for the writer now and then
    recorder::Recorder recorder(config, session, scene.source->frame(begin));
    pipeline.add_sink(recorder);
    pipeline.add_sink(capture);
    for (std::uint32_t f = begin; f < end; ++f) pipeline.process(scene.source->frame(f));
    recorder.finish();
    return capture.frames;
}

Scene crossing_sheets(std::uint32_t cells, std::uint32_t frames) {
    std::vector<std::vector<MeshData>> meshes;
    const MeshData flat = grid_sheet(cells, 1.0);
    for (std::uint32_t f = 0; f < frames; ++f) {
        MeshData upright = flat;
        const double y = -0.2 + 1.4 * f / std::max<std::uint32_t>(frames - 1, 1);
        // (x, y, 0) -> (x, y_f, y - 0.5): a vertical sheet at y = y_f.
        for (Vec3& v : upright.vertices) v = Vec3(v.x() + 0.013, y, v.y() - 0.5);
        meshes.push_back({flat, upright});
    }
    Scene scene;
    scene.name = "crossing_sheets";
    scene.source = make_memory_source({"flat", "upright"}, std::move(meshes));
    return scene;
}

Scene varying_vertex_counts(std::uint64_t seed, std::uint32_t frames) {
    std::mt19937_64 rng(seed);
    std::vector<std::vector<MeshData>> meshes;
    for (std::uint32_t f = 0; f < frames; ++f) {
        const std::uint32_t cells = f == 0 ? 5 : std::uniform_int_distribution<std::uint32_t>(1, 12)(rng);
        const double wave = 0.37 * f;
        meshes.push_back({translated(grid_sheet(cells, 1.0), Vec3(0.01 * wave, 0.3, std::sin(wave))), grid_sheet(4, 1.0)});
    }
    Scene scene;
    scene.name = "vertex-counts";
    scene.source = make_memory_source({"changing", "fixed"}, std::move(meshes));
    return scene;
}

namespace {

// Element `index` of 1-D `dataset` set to `*value`, given as `mem_type`.
void overwrite_element(const std::filesystem::path& file, const std::string& dataset, std::uint64_t index, hid_t mem_type,
                       const void* value) {
    const hid_t f = open_rw(file);
    const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    ASSERT_GE(d, 0) << dataset;
    const hid_t space = H5Dget_space(d);
    const hsize_t start = index, count = 1;
    H5Sselect_hyperslab(space, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
    const hid_t mem = H5Screate_simple(1, &count, nullptr);
    EXPECT_GE(H5Dwrite(d, mem_type, mem, space, H5P_DEFAULT, value), 0);
    H5Sclose(mem);
    H5Sclose(space);
    H5Dclose(d);
    H5Fclose(f);
}

}  // namespace

void overwrite_f64(const std::filesystem::path& file, const std::string& dataset, std::uint64_t index, double value) {
    overwrite_element(file, dataset, index, H5T_NATIVE_DOUBLE, &value);
}

void overwrite_u64(const std::filesystem::path& file, const std::string& dataset, std::uint64_t index,
                   std::uint64_t value) {
    overwrite_element(file, dataset, index, H5T_NATIVE_UINT64, &value);
}

void set_int_attr(const std::filesystem::path& file, const std::string& object, const std::string& name,
                  std::int64_t value) {
    const hid_t f = open_rw(file);
    const hid_t o = H5Oopen(f, object.c_str(), H5P_DEFAULT);
    if (H5Aexists(o, name.c_str()) > 0) H5Adelete(o, name.c_str());
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(o, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Awrite(a, H5T_NATIVE_INT64, &value), 0);
    H5Aclose(a);
    H5Sclose(space);
    H5Oclose(o);
    H5Fclose(f);
}

void delete_attr(const std::filesystem::path& file, const std::string& object, const std::string& name) {
    const hid_t f = open_rw(file);
    EXPECT_GE(H5Adelete_by_name(f, object.c_str(), name.c_str(), H5P_DEFAULT), 0) << object << " " << name;
    H5Fclose(f);
}

void delete_link(const std::filesystem::path& file, const std::string& path) {
    const hid_t f = open_rw(file);
    EXPECT_GE(H5Ldelete(f, path.c_str(), H5P_DEFAULT), 0) << path;
    H5Fclose(f);
}

void write_foreign_hdf5(const std::filesystem::path& file) {
    const hid_t f = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t dims = 4;
    const hid_t space = H5Screate_simple(1, &dims, nullptr);
    const hid_t d = H5Dcreate2(f, "temperature", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const double values[4] = {1, 2, 3, 4};
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values);
    H5Dclose(d);
    H5Sclose(space);
    H5Fclose(f);
}

}  // namespace collidescope::testing
