// Group commit (RecordingWriter::append of several frames, one append per dataset and one flush)
// against the obvious path, one frame per append: the two files hold the same datasets with
// the same bytes, for frames that keep their vertex count and for frames that change it.

#include "frame_copier.hpp"
#include "recording_writer.hpp"

#include "mesh/temp_files.hpp"
#include "recording_helpers.hpp"
#include "support/scene_builders.hpp"

#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <csignal>
#include <map>
#include <regex>

#include <sys/resource.h>

namespace collidescope::recorder {
namespace {

using testing_files::TempDir;

class CopySink final : public TraceSink {
public:
    explicit CopySink(const std::string& file) : copier(file) {}
    void on_frame(const FrameReport& report) override { records.push_back(copier.copy(report)); }
    FrameCopier copier;
    std::vector<FrameRecord> records;
};

/// Every dataset of `file`: path -> (shape, raw bytes in the file's type).
std::map<std::string, std::pair<std::vector<hsize_t>, std::vector<unsigned char>>> datasets_of(const std::string& file) {
    std::map<std::string, std::pair<std::vector<hsize_t>, std::vector<unsigned char>>> out;
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EXPECT_GE(f, 0) << file;
    H5Ovisit2(
        f, H5_INDEX_NAME, H5_ITER_INC,
        [](hid_t root, const char* name, const H5O_info_t* info, void* data) -> herr_t {
            if (info->type != H5O_TYPE_DATASET) return 0;
            auto& all = *static_cast<decltype(out)*>(data);
            const hid_t d = H5Dopen2(root, name, H5P_DEFAULT);
            const hid_t space = H5Dget_space(d);
            const hid_t type = H5Dget_type(d);
            std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
            H5Sget_simple_extent_dims(space, dims.data(), nullptr);
            std::vector<unsigned char> bytes(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) * H5Tget_size(type));
            if (!bytes.empty()) H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
            all[name] = {dims, bytes};
            H5Tclose(type);
            H5Sclose(space);
            H5Dclose(d);
            return 0;
        },
        &out, H5O_INFO_BASIC);
    H5Fclose(f);
    return out;
}

/// Writes `records` to `file`, `batch(i)` frames per append starting at record i.
template <class Batch>
void write(const std::string& file, const Scene& scene, const std::vector<std::string>& methods,
           const std::vector<FrameRecord>& records, Batch batch) {
    SessionInfo session;
    session.scene = scene.name;
    session.method = "brute";
    session.frame_end = static_cast<std::uint32_t>(records.size());
    for (std::uint32_t k = 0; k < scene.source->object_count(); ++k) session.object_names.push_back(scene.source->object_name(k));
    RecordingWriter trace(file, session, scene.source->frame(0), methods, 1);
    for (std::size_t i = 0; i < records.size();) {
        const std::size_t n = std::min(batch(i), records.size() - i);
        const std::vector<RecordingWriter::Keep> keeps(n);
        trace.append(std::span(records).subspan(i, n), keeps);
        i += n;
    }
    trace.close();
}

/// The records of frames [0, frames) of `scene`, as the recorder queues them.
std::vector<FrameRecord> copy_frames(const Scene& scene, std::uint32_t frames, CopySink& sink) {
    PipelineConfig config;
    config.method = "brute";
    Pipeline pipeline(config);
    pipeline.add_sink(sink);
    for (std::uint32_t f = 0; f < frames; ++f) pipeline.process(scene.source->frame(f));
    return sink.records;
}

void expect_group_commit_writes_what_single_frames_write(const Scene& scene, std::uint32_t frames) {
    TempDir dir;
    const std::string single = (dir.path() / "single.h5").string();
    const std::string grouped = (dir.path() / "grouped.h5").string();
    CopySink sink(single);
    copy_frames(scene, frames, sink);

    write(single, scene, sink.copier.methods(), sink.records, [](std::size_t) { return std::size_t{1}; });
    write(grouped, scene, sink.copier.methods(), sink.records, [](std::size_t i) { return i % 7 + 1; });
    const auto a = datasets_of(single);
    const auto b = datasets_of(grouped);
    std::printf("%zu datasets compared\n", a.size());
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [name, data] : a) {
        ASSERT_TRUE(b.count(name)) << name;
        EXPECT_EQ(b.at(name).first, data.first) << name;
        EXPECT_TRUE(b.at(name).second == data.second) << name << " differs";
    }
    EXPECT_GT(a.at("frames/index").first[0], 0u);
}

TEST(GroupCommit, WritesWhatSingleFramesWrite) {
    expect_group_commit_writes_what_single_frames_write(testing::crossing_sheets(6, 30), 30);
}

TEST(GroupCommit, WritesWhatSingleFramesWriteWhenVertexCountsChange) {
    const std::uint64_t seed = 78;
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    const Scene scene = testing::varying_vertex_counts(seed, 30);
    expect_group_commit_writes_what_single_frames_write(scene, 30);
}

// A group whose disk space cannot be reserved is written one frame at a time: every frame that
// fits is kept and the error names the first that does not (a file size limit stands in for a
// full disk, as in tests/recorder/test_record_interrupt.cpp).
TEST(GroupCommit, AGroupThatDoesNotFitKeepsTheFramesThatDo) {
    TempDir dir;
    const Scene scene = testing::crossing_sheets(30, 40);
    CopySink sink((dir.path() / "x.h5").string());
    const std::vector<FrameRecord> records = copy_frames(scene, 40, sink);
    const std::string whole = (dir.path() / "whole.h5").string();
    write(whole, scene, sink.copier.methods(), records, [](std::size_t) { return std::size_t{1}; });
    const auto whole_bytes = std::filesystem::file_size(whole);

    const std::string limited = (dir.path() / "limited.h5").string();
    SessionInfo session;
    session.scene = scene.name;
    session.frame_end = 40;
    session.object_names = {"flat", "upright"};
    std::string error;
    std::uint64_t written = 0;
    {
        RecordingWriter trace(limited, session, scene.source->frame(0), sink.copier.methods(), 1);
        trace.append(std::span(records).first(5), std::vector<RecordingWriter::Keep>(5));  // a first group that fits
        const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit old_limit{};
        getrlimit(RLIMIT_FSIZE, &old_limit);
        rlimit limit = old_limit;
        limit.rlim_cur = whole_bytes / 2;
        setrlimit(RLIMIT_FSIZE, &limit);
        try {
            trace.append(std::span(records).subspan(5), std::vector<RecordingWriter::Keep>(35));  // one group: it does not fit
        } catch (const InputError& failure) {
            error = failure.what();
        }
        setrlimit(RLIMIT_FSIZE, &old_limit);
        std::signal(SIGXFSZ, old_handler);
        written = trace.frames_written();
        EXPECT_FALSE(trace.damaged());
        trace.close();
    }
    std::printf("%s\n%llu frames written\n", error.c_str(), static_cast<unsigned long long>(written));
    std::smatch match;
    ASSERT_TRUE(std::regex_search(error, match, std::regex(": frame ([0-9]+): cannot reserve"))) << error;
    EXPECT_EQ(std::stoull(match[1].str()), written);  // frames 0..N-1 kept, frame N named
    EXPECT_GT(written, 5u);
    EXPECT_LT(written, 40u);
    const Recording rec(limited);
    EXPECT_EQ(rec.frames_complete(), written);
    const Recording reference(whole);
    testing::expect_complete_rows_equal(rec, reference);
}

}  // namespace
}  // namespace collidescope::recorder
