// Encoding the replay's frames: one PNG per frame (stb_image_write + zlib level 1, what `replay
// -o DIR` writes) against an H.264 MP4 (libx264 at several presets, what `replay --video
// clip.mp4` writes) and a GIF, on real replayed frames decoded from PNGs, so the comparison
// leaves out rendering. One iteration encodes every frame; counters give per-frame times.
// Process CPU time counts x264's own threads.
//
//   build/app/collidescope replay run.h5 -o /tmp/frames --size 1280x720
//   COLLIDESCOPE_BENCH_FRAMES=/tmp/frames build/bench/bench_video_encode --benchmark_counters_tabular=true

#include "png.hpp"
#include "open_video.hpp"

#include <benchmark/benchmark.h>
#include <stb_image.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

struct Frames {
    int width = 0;
    int height = 0;
    std::vector<std::vector<std::uint8_t>> rgba;
};

// Every frame_*.png of $COLLIDESCOPE_BENCH_FRAMES, in name order.
const Frames& frames() {
    static const Frames loaded = [] {
        Frames out;
        const char* dir = std::getenv("COLLIDESCOPE_BENCH_FRAMES");
        if (dir == nullptr) return out;
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            if (entry.path().extension() == ".png") files.push_back(entry.path());
        }
        std::sort(files.begin(), files.end());
        for (const auto& file : files) {
            int w = 0, h = 0, channels = 0;
            unsigned char* pixels = stbi_load(file.c_str(), &w, &h, &channels, 4);
            if (pixels == nullptr) continue;
            out.width = w;
            out.height = h;
            out.rgba.emplace_back(pixels, pixels + std::size_t(w) * std::size_t(h) * 4);
            stbi_image_free(pixels);
        }
        return out;
    }();
    return loaded;
}

bool have_frames(benchmark::State& state) {
    if (!frames().rgba.empty()) return true;
    state.SkipWithError("set COLLIDESCOPE_BENCH_FRAMES to a directory of replayed PNG frames");
    return false;
}

void per_frame(benchmark::State& state, std::uintmax_t bytes) {
    state.counters["frames"] = double(frames().rgba.size());
    state.counters["ms_per_frame"] = benchmark::Counter(double(frames().rgba.size()) * 1e-3,
                                                        benchmark::Counter::kIsIterationInvariantRate |
                                                            benchmark::Counter::kInvert);
    state.counters["bytes_per_frame"] = double(bytes) / double(frames().rgba.size());
}

void BM_png(benchmark::State& state) {
    if (!have_frames(state)) return;
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "bench_video_encode_png";
    std::filesystem::create_directories(dir);
    std::uintmax_t bytes = 0;
    for (auto _ : state) {
        bytes = 0;
        for (std::size_t i = 0; i < frames().rgba.size(); ++i) {
            const std::filesystem::path file = dir / ("frame_" + std::to_string(i) + ".png");
            collidescope::replays::write_png(file, frames().rgba[i], frames().width, frames().height);
            bytes += std::filesystem::file_size(file);
        }
    }
    per_frame(state, bytes);
    std::filesystem::remove_all(dir);
}

void clip(benchmark::State& state, const char* name, const std::string& preset) {
    if (!have_frames(state)) return;
    const std::filesystem::path file = std::filesystem::temp_directory_path() / name;
    std::uintmax_t bytes = 0;
    for (auto _ : state) {
        collidescope::replays::VideoSettings settings;
        settings.path = file;
        settings.width = frames().width;
        settings.height = frames().height;
        settings.h264_preset = preset;
        const auto encoder = collidescope::replays::open_video(settings);
        for (const auto& rgba : frames().rgba) encoder->add_frame(rgba);
        encoder->finish();
        bytes = std::filesystem::file_size(file);
    }
    per_frame(state, bytes);
    std::filesystem::remove(file);
}

void BM_mp4(benchmark::State& state, const std::string& preset) { clip(state, "bench_video_encode.mp4", preset); }
void BM_gif(benchmark::State& state) { clip(state, "bench_video_encode.gif", ""); }

}  // namespace

BENCHMARK(BM_png)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(BM_mp4, veryfast, "veryfast")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(BM_mp4, superfast, "superfast")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(BM_mp4, ultrafast, "ultrafast")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_CAPTURE(BM_mp4, medium, "medium")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(BM_gif)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK_MAIN();
