// The recorder's positions encoder (recorder/src/chunk_codec.hpp) against what HDF5's shuffle
// and deflate filters do with the same chunk (shuffle, then zlib's compress2 at the same level
// over all of it): MB/s of raw positions and bytes out per byte in. The chunk is one frame of
// a rotated wavy sheet, float32, as data set C's recordings hold them.
//
//   build/bench/bench_chunk_codec --benchmark_counters_tabular=true

#include "chunk_codec.hpp"

#include <benchmark/benchmark.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace {

std::vector<std::byte> sheet_chunk(std::uint32_t n) {
    std::vector<float> xyz;
    const double a = 0.3, b = 0.7;
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const double x = -1.0 + 2.0 * i / (n - 1), y = -1.0 + 2.0 * j / (n - 1);
            const double z = 0.1 * std::sin(5.0 * x) * std::cos(3.0 * y);
            const double x1 = std::cos(a) * x - std::sin(a) * y, y1 = std::sin(a) * x + std::cos(a) * y;
            xyz.insert(xyz.end(), {static_cast<float>(x1), static_cast<float>(std::cos(b) * y1 - std::sin(b) * z),
                                   static_cast<float>(std::sin(b) * y1 + std::cos(b) * z)});
        }
    }
    std::vector<std::byte> out(xyz.size() * sizeof(float));
    std::memcpy(out.data(), xyz.data(), out.size());
    return out;
}

void report(benchmark::State& state, std::size_t raw, std::size_t encoded) {
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * raw));
    state.counters["ratio"] = static_cast<double>(encoded) / static_cast<double>(raw);
}

// What H5Z shuffle + deflate do: transpose the bytes, then compress2 over the whole chunk.
void hdf5_filters(benchmark::State& state) {
    const std::vector<std::byte> raw = sheet_chunk(static_cast<std::uint32_t>(state.range(0)));
    std::vector<unsigned char> shuffled(raw.size()), out(compressBound(static_cast<uLong>(raw.size())));
    const std::size_t n = raw.size() / 4;
    uLongf size = 0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t b = 0; b < 4; ++b) shuffled[b * n + i] = static_cast<unsigned char>(raw[4 * i + b]);
        }
        size = static_cast<uLongf>(out.size());
        compress2(out.data(), &size, shuffled.data(), static_cast<uLong>(shuffled.size()), 1);
        benchmark::DoNotOptimize(out.data());
    }
    report(state, raw.size(), size);
}

void encoder(benchmark::State& state) {
    const std::vector<std::byte> raw = sheet_chunk(static_cast<std::uint32_t>(state.range(0)));
    std::vector<unsigned char> out;
    for (auto _ : state) {
        collidescope::recorder::encode_shuffle_deflate(raw, 4, 1, out);
        benchmark::DoNotOptimize(out.data());
    }
    report(state, raw.size(), out.size());
}

// A frame that fills a third of its chunk (a vertex count other than the first frame's).
void encoder_partial(benchmark::State& state) {
    const std::vector<std::byte> raw = sheet_chunk(static_cast<std::uint32_t>(state.range(0)));
    std::vector<unsigned char> out;
    const std::size_t part = raw.size() / 12 * 4;
    for (auto _ : state) {
        collidescope::recorder::encode_shuffle_deflate(std::span(raw).first(part), 4, 1, out, raw.size());
        benchmark::DoNotOptimize(out.data());
    }
    report(state, part, out.size());
}

}  // namespace

BENCHMARK(hdf5_filters)->Arg(101)->Arg(400)->Unit(benchmark::kMicrosecond);
BENCHMARK(encoder)->Arg(101)->Arg(400)->Unit(benchmark::kMicrosecond);
BENCHMARK(encoder_partial)->Arg(101)->Arg(400)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
