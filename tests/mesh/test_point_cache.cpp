// PointCacheReader: PC2 and MDD round trips against the test writers and against files built
// byte by byte from the formats' descriptions, frames read in any order, and every bad header
// (truncated, lying counts, wrong magic or version, non-finite fields) and NaN coordinate.

#include "mesh/temp_files.hpp"
#include "support/point_cache_writer.hpp"

#include "collidescope/point_cache.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>

namespace collidescope {
namespace {

using namespace testing_files;
using testing::PositionFrames;
using ::testing::HasSubstr;

// `frames` frames of `points` float32-exact positions from a fixed seed.
PositionFrames random_frames(std::uint32_t frames, std::uint32_t points, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coordinate(-100.0, 100.0);
    PositionFrames out(frames, std::vector<Vec3>(points));
    for (auto& frame : out) {
        for (Vec3& v : frame) v = round_to_float32(Vec3(coordinate(rng), coordinate(rng), coordinate(rng)));
    }
    return out;
}

void expect_frames(PointCacheReader& reader, const PositionFrames& frames) {
    ASSERT_EQ(reader.layout().frame_count, frames.size());
    // Backwards: each frame is a seek, not a position in a stream.
    for (std::uint32_t k = static_cast<std::uint32_t>(frames.size()); k-- > 0;) {
        const std::vector<Vec3> read = reader.read_frame(k);
        ASSERT_EQ(read.size(), frames[k].size());
        for (std::size_t v = 0; v < read.size(); ++v) EXPECT_EQ(read[v], frames[k][v]) << "frame " << k << " vertex " << v;
    }
}

TEST(Pc2Reader, RoundTripsFramesAndTimes) {
    TempDir dir;
    const PositionFrames frames = random_frames(5, 7, 11);
    testing::write_pc2(dir / "body.pc2", frames, 10.0f, 2.0f);
    PointCacheReader reader(dir / "body.pc2");
    EXPECT_EQ(reader.layout().point_count, 7u);
    EXPECT_EQ(reader.layout().data_offset, 32u);
    EXPECT_FALSE(reader.layout().big_endian);
    // Two frames of the application per sample, read at 30 frames per second.
    ASSERT_EQ(reader.layout().frame_times.size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) EXPECT_DOUBLE_EQ(reader.layout().frame_times[k], static_cast<double>(k) * 2.0 / 30.0);
    EXPECT_DOUBLE_EQ(reader.layout().fps, 15.0);
    expect_frames(reader, frames);
}

TEST(Pc2Reader, ReadsAFileBuiltByteByByte) {
    TempDir dir;
    ByteWriter bytes(false);
    bytes.text(std::string_view("POINTCACHE2\0", 12));
    bytes.put<std::int32_t>(1);
    bytes.put<std::int32_t>(2);      // points
    bytes.put<float>(0.0f);          // start frame
    bytes.put<float>(1.0f);          // sample rate
    bytes.put<std::int32_t>(1);      // samples
    for (const float c : {1.5f, -2.0f, 3.25f, 0.0f, 1e-3f, -7.0f}) bytes.put<float>(c);
    write_bytes(dir / "hand.PC2", bytes.bytes());
    PointCacheReader reader(dir / "hand.PC2");
    const std::vector<Vec3> frame = reader.read_frame(0);
    ASSERT_EQ(frame.size(), 2u);
    EXPECT_EQ(frame[0], Vec3(1.5, -2.0, 3.25));
    EXPECT_EQ(frame[1], Vec3(0.0, double{1e-3f}, -7.0));
    EXPECT_EQ(reader.layout().fps, 30.0);
}

TEST(MddReader, RoundTripsFramesAndTimes) {
    TempDir dir;
    const PositionFrames frames = random_frames(4, 9, 12);
    testing::write_mdd(dir / "body.mdd", frames, {1.0f, 1.5f, 2.0f, 2.5f});
    PointCacheReader reader(dir / "body.mdd");
    EXPECT_EQ(reader.layout().point_count, 9u);
    EXPECT_EQ(reader.layout().data_offset, 8u + 4 * 4);
    EXPECT_TRUE(reader.layout().big_endian);
    EXPECT_EQ(reader.layout().frame_times, (std::vector<double>{0.0, 0.5, 1.0, 1.5}));
    EXPECT_DOUBLE_EQ(reader.layout().fps, 2.0);
    expect_frames(reader, frames);
}

TEST(MddReader, ReadsAFileBuiltByteByByte) {
    TempDir dir;
    ByteWriter bytes(true);
    bytes.put<std::int32_t>(2);  // frames
    bytes.put<std::int32_t>(1);  // points
    bytes.put<float>(0.0f);
    bytes.put<float>(0.25f);
    for (const float c : {1.0f, 2.0f, 3.0f, -4.0f, -5.0f, -6.5f}) bytes.put<float>(c);
    write_bytes(dir / "hand.mdd", bytes.bytes());
    PointCacheReader reader(dir / "hand.mdd");
    EXPECT_EQ(reader.read_frame(1), std::vector<Vec3>{Vec3(-4.0, -5.0, -6.5)});
    EXPECT_EQ(reader.read_frame(0), std::vector<Vec3>{Vec3(1.0, 2.0, 3.0)});
    EXPECT_EQ(reader.layout().fps, 4.0);
}

TEST(PointCacheReader, OneFrameHasNoFrameRate) {
    TempDir dir;
    testing::write_mdd(dir / "one.mdd", random_frames(1, 3, 13), {4.0f});
    PointCacheReader reader(dir / "one.mdd");
    EXPECT_EQ(reader.layout().frame_times, std::vector<double>{0.0});
    EXPECT_EQ(reader.layout().fps, 0.0);
}

TEST(PointCacheReader, KnowsItsExtensions) {
    EXPECT_TRUE(is_point_cache_file("a/body.pc2"));
    EXPECT_TRUE(is_point_cache_file("BODY.MDD"));
    EXPECT_FALSE(is_point_cache_file("body.obj"));
    EXPECT_FALSE(is_point_cache_file("body.pc2.gz"));
}

// A PC2 header with the given fields and `payload` bytes after it.
std::vector<std::byte> pc2_bytes(std::int32_t version, std::int32_t points, float start, float rate,
                                 std::int32_t samples, std::size_t payload, const char* magic = "POINTCACHE2") {
    ByteWriter bytes(false);
    bytes.text(std::string_view(magic, 11));
    bytes.put<char>('\0');
    bytes.put(version);
    bytes.put(points);
    bytes.put(start);
    bytes.put(rate);
    bytes.put(samples);
    for (std::size_t i = 0; i < payload; ++i) bytes.put<std::uint8_t>(0);
    return bytes.bytes();
}

std::string pc2_error(const std::vector<std::byte>& bytes) {
    TempDir dir;
    write_bytes(dir / "bad.pc2", bytes);
    return input_error([&] { PointCacheReader reader(dir / "bad.pc2"); });
}

TEST(Pc2ReaderErrors, HeadersThatLie) {
    // 2 samples x 3 points need 32 + 72 bytes.
    EXPECT_THAT(pc2_error(pc2_bytes(1, 3, 0, 1, 2, 71)),
                HasSubstr("bad.pc2: header: 2 samples x 3 points need 104 bytes, the file has 103 (truncated"));
    EXPECT_THAT(pc2_error(pc2_bytes(1, 3, 0, 1, 2, 73)),
                HasSubstr("bad.pc2: header: 2 samples x 3 points need 104 bytes, the file has 105 (the header's counts are wrong)"));
    // Counts no file could hold: refused before anything is allocated for them.
    const std::int32_t huge = std::numeric_limits<std::int32_t>::max();
    EXPECT_THAT(pc2_error(pc2_bytes(1, huge, 0, 1, huge, 12)),
                HasSubstr("bad.pc2: header: 2147483647 samples x 2147483647 points need more than 2^64 bytes, the file has 44 (truncated"));
    EXPECT_THAT(pc2_error(pc2_bytes(1, 3, 0, 1, 2, 72, "POINTCACHE3")), HasSubstr("bad.pc2: not a PC2 file"));
    EXPECT_THAT(pc2_error(pc2_bytes(2, 3, 0, 1, 2, 72)), HasSubstr("bad.pc2: header: version 2"));
    EXPECT_THAT(pc2_error(pc2_bytes(1, 0, 0, 1, 2, 0)), HasSubstr("bad.pc2: header: point count 0"));
    EXPECT_THAT(pc2_error(pc2_bytes(1, 3, 0, 1, -2, 0)), HasSubstr("bad.pc2: header: sample count -2"));
    EXPECT_THAT(pc2_error(pc2_bytes(1, 3, 0, 0, 2, 72)), HasSubstr("bad.pc2: header: sample rate 0"));
    EXPECT_THAT(pc2_error(pc2_bytes(1, 3, std::nanf(""), 1, 2, 72)),
                HasSubstr("bad.pc2: header: start frame is not finite"));
    std::vector<std::byte> cut = pc2_bytes(1, 3, 0, 1, 2, 0);
    cut.resize(20);
    EXPECT_THAT(pc2_error(cut), HasSubstr("bad.pc2: file truncated: a PC2 header needs 32 bytes, the file has 20"));
}

// An MDD header with the given counts and times and `payload` bytes after it.
std::vector<std::byte> mdd_bytes(std::int32_t frames, std::int32_t points, const std::vector<float>& times,
                                 std::size_t payload) {
    ByteWriter bytes(true);
    bytes.put(frames);
    bytes.put(points);
    for (const float t : times) bytes.put(t);
    for (std::size_t i = 0; i < payload; ++i) bytes.put<std::uint8_t>(0);
    return bytes.bytes();
}

std::string mdd_error(const std::vector<std::byte>& bytes) {
    TempDir dir;
    write_bytes(dir / "bad.mdd", bytes);
    return input_error([&] { PointCacheReader reader(dir / "bad.mdd"); });
}

TEST(MddReaderErrors, HeadersThatLie) {
    // 2 frames x 3 points need 8 + 8 + 72 bytes.
    EXPECT_THAT(mdd_error(mdd_bytes(2, 3, {0, 1}, 71)),
                HasSubstr("bad.mdd: header: 2 frames x 3 points need 88 bytes, the file has 87 (truncated"));
    EXPECT_THAT(mdd_error(mdd_bytes(2, 3, {0, 1}, 84)),
                HasSubstr("bad.mdd: header: 2 frames x 3 points need 88 bytes, the file has 100 (the header's counts are wrong)"));
    const std::int32_t huge = std::numeric_limits<std::int32_t>::max();
    EXPECT_THAT(mdd_error(mdd_bytes(huge, huge, {0, 1}, 12)), HasSubstr("bad.mdd: header: 2147483647 frames x 2147483647 points need"));
    EXPECT_THAT(mdd_error(mdd_bytes(0, 3, {}, 0)), HasSubstr("bad.mdd: header: frame count 0"));
    EXPECT_THAT(mdd_error(mdd_bytes(2, -1, {0, 1}, 0)), HasSubstr("bad.mdd: header: point count -1"));
    EXPECT_THAT(mdd_error(mdd_bytes(2, 3, {0, std::nanf("")}, 72)), HasSubstr("bad.mdd: time of frame 1 is not finite"));
    EXPECT_THAT(mdd_error(mdd_bytes(3, 3, {0, 1, 0.5f}, 108)),
                HasSubstr("bad.mdd: time of frame 2 (0.5 s) is before frame 1's (1 s)"));
    EXPECT_THAT(mdd_error(mdd_bytes(2, 3, {}, 0)), HasSubstr("bad.mdd: header: 2 frames x 3 points need 88 bytes, the file has 8"));
    std::vector<std::byte> cut = mdd_bytes(2, 3, {}, 0);
    cut.resize(5);
    EXPECT_THAT(mdd_error(cut), HasSubstr("bad.mdd: file truncated: an MDD header needs at least 8 bytes, the file has 5"));
}

TEST(PointCacheReaderErrors, NonFiniteCoordinatesNameFrameAndVertex) {
    TempDir dir;
    PositionFrames frames = random_frames(3, 4, 14);
    frames[2][3].y() = std::numeric_limits<double>::quiet_NaN();
    frames[1][0].z() = std::numeric_limits<double>::infinity();
    testing::write_pc2(dir / "nan.pc2", frames);
    testing::write_mdd(dir / "nan.mdd", frames, {0, 1, 2});
    for (const char* name : {"nan.pc2", "nan.mdd"}) {
        PointCacheReader reader(dir / name);
        EXPECT_EQ(reader.read_frame(0), frames[0]);
        EXPECT_THAT(input_error([&] { reader.read_frame(2); }),
                    HasSubstr(std::string(name) + ": frame 2, vertex 3: coordinate y is not finite (nan)"));
        EXPECT_THAT(input_error([&] { reader.read_frame(1); }),
                    HasSubstr(std::string(name) + ": frame 1, vertex 0: coordinate z is not finite (inf)"));
    }
}

TEST(PointCacheReaderErrors, MissingFilesAndOtherExtensions) {
    TempDir dir;
    EXPECT_THAT(input_error([&] { PointCacheReader reader(dir / "missing.pc2"); }), HasSubstr("missing.pc2: no such file"));
    write_text(dir / "body.obj", "v 0 0 0\n");
    EXPECT_THAT(input_error([&] { PointCacheReader reader(dir / "body.obj"); }),
                HasSubstr("body.obj: not a point cache (expected a .pc2 or .mdd file)"));
    std::filesystem::create_directories(dir / "folder.mdd");
    EXPECT_THAT(input_error([&] { PointCacheReader reader(dir / "folder.mdd"); }), HasSubstr("folder.mdd: not a regular file"));
}

// Resident memory of this process in bytes (Linux: /proc/self/statm, second field in pages).
std::uint64_t resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    std::uint64_t size = 0, resident = 0;
    statm >> size >> resident;
    return resident * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

// A 1.2 GB cache (a sparse file: 100,000 samples of 1,000 points at the origin) opens and
// reads any frame without the cache ever sitting in memory.
TEST(PointCacheReader, ALargeCacheIsReadAFrameAtATime) {
    TempDir dir;
    const std::vector<std::byte> header = pc2_bytes(1, 1000, 0, 1, 100000, 0);
    write_bytes(dir / "large.pc2", header);
    std::filesystem::resize_file(dir / "large.pc2", header.size() + std::uint64_t{100000} * 1000 * 12);
    const std::uint64_t before = resident_bytes();
    PointCacheReader reader(dir / "large.pc2");
    ASSERT_EQ(reader.layout().frame_count, 100000u);
    for (const std::uint32_t k : {99999u, 0u, 54321u}) {
        const std::vector<Vec3> frame = reader.read_frame(k);
        ASSERT_EQ(frame.size(), 1000u);
        EXPECT_EQ(frame[999], Vec3::Zero());
    }
    EXPECT_LT(resident_bytes() - std::min(before, resident_bytes()), std::uint64_t{64} << 20);
}

// Random bytes after a valid or random header, of random sizes: every file either opens and
// reads every frame, or throws InputError; nothing else (seed printed on failure).
TEST(PointCacheReaderErrors, RandomBytesOpenOrSayWhy) {
    TempDir dir;
    constexpr std::uint64_t k_seed = 28;
    std::mt19937_64 rng(k_seed);
    int opened = 0, refused = 0;
    for (int round = 0; round < 400; ++round) {
        SCOPED_TRACE("seed " + std::to_string(k_seed) + ", round " + std::to_string(round));
        const bool mdd = round % 2 == 1;
        const auto frames = static_cast<std::int32_t>(rng() % 4) - 1;  // -1 .. 2
        const auto points = static_cast<std::int32_t>(rng() % 4) - 1;
        ByteWriter bytes(mdd);
        if (mdd) {
            bytes.put(frames);
            bytes.put(points);
            for (std::int32_t k = 0; k < frames && rng() % 8 != 0; ++k) bytes.put(static_cast<float>(k));
        } else {
            bytes.text(std::string_view("POINTCACHE2\0", 12));
            bytes.put<std::int32_t>(rng() % 8 == 0 ? 2 : 1);
            bytes.put(points);
            bytes.put<float>(0.0f);
            bytes.put<float>(rng() % 8 == 0 ? 0.0f : 1.0f);
            bytes.put(frames);
        }
        // Often exactly what the counts need, else a random length.
        const bool exact = frames > 0 && points > 0 && rng() % 2 == 0;
        const std::size_t payload = exact ? std::size_t(frames) * std::size_t(points) * 12 : rng() % 100;
        for (std::size_t i = 0; i < payload; ++i) bytes.put<std::uint8_t>(static_cast<std::uint8_t>(rng() % 3 == 0 ? rng() : 0));
        const std::filesystem::path file = dir / (mdd ? "random.mdd" : "random.pc2");
        write_bytes(file, bytes.bytes());
        try {
            PointCacheReader reader(file);
            for (std::uint32_t k = 0; k < reader.layout().frame_count; ++k) {
                EXPECT_EQ(reader.read_frame(k).size(), reader.layout().point_count);
            }
            ++opened;
        } catch (const InputError& error) {
            EXPECT_THAT(error.what(), HasSubstr(file.string() + ": "));
            ++refused;
        }
    }
    // Both outcomes happen, so the test exercises both.
    EXPECT_GT(opened, 20);
    EXPECT_GT(refused, 20);
}

}  // namespace
}  // namespace collidescope
