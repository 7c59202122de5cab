// Import speed in MB/s: a large binary PLY (float32 and float64, about 2 M triangles) through
// parse_ply (bytes in memory) and read_mesh_file (disk read + parse + validation, plain and
// gzipped), and the same mesh as OBJ text through parse_obj. The files are generated once in
// a temporary directory and removed at exit.
//
//   build/bench/bench_import --benchmark_min_time=0.5

#include "collidescope/mesh.hpp"

#include <benchmark/benchmark.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

namespace {

using namespace collidescope;

constexpr int k_grid = 1001;  // 1001 x 1001 vertices: 2,000,000 triangles

// A jittered height field, so coordinates look like real data rather than round numbers.
MeshData make_grid() {
    MeshData mesh;
    std::mt19937 random(42);
    std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
    mesh.vertices.reserve(k_grid * k_grid);
    for (int y = 0; y < k_grid; ++y) {
        for (int x = 0; x < k_grid; ++x) {
            const float dx = jitter(random), dy = jitter(random), dz = jitter(random);
            mesh.vertices.emplace_back(static_cast<float>(x) + dx, static_cast<float>(y) + dy, dz);
        }
    }
    for (std::uint32_t y = 0; y + 1 < k_grid; ++y) {
        for (std::uint32_t x = 0; x + 1 < k_grid; ++x) {
            const std::uint32_t v = y * k_grid + x;
            mesh.triangles.push_back({v, v + 1, v + k_grid});
            mesh.triangles.push_back({v + 1, v + k_grid + 1, v + k_grid});
        }
    }
    return mesh;
}

std::string to_obj(const MeshData& mesh) {
    std::string text;
    char line[96];
    for (const Vec3& v : mesh.vertices) {
        const int n = std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", v.x(), v.y(), v.z());
        text.append(line, static_cast<std::size_t>(n));
    }
    for (const TriIndices& t : mesh.triangles) {
        const int n = std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
        text.append(line, static_cast<std::size_t>(n));
    }
    return text;
}

void gzip(const std::filesystem::path& from, const std::filesystem::path& to) {
    const std::vector<std::byte> bytes = read_file_bytes(from);
    gzFile out = gzopen(to.c_str(), "wb6");
    if (out == nullptr || gzwrite(out, bytes.data(), static_cast<unsigned>(bytes.size())) <= 0) {
        throw std::runtime_error("cannot write " + to.string());
    }
    gzclose(out);
}

// The generated inputs, made on first use and deleted at exit.
struct Inputs {
    std::filesystem::path dir;
    std::filesystem::path ply_float, ply_double, ply_gz, obj;

    Inputs() {
        dir = std::filesystem::temp_directory_path() / ("collidescope_bench_import_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        const MeshData mesh = make_grid();
        ply_float = dir / "grid_float.ply";
        ply_double = dir / "grid_double.ply";
        ply_gz = dir / "grid_float.ply.gz";
        obj = dir / "grid.obj";
        write_ply(ply_float, mesh);
        write_ply(ply_double, mesh, true);
        gzip(ply_float, ply_gz);
        const std::string text = to_obj(mesh);
        std::FILE* out = std::fopen(obj.c_str(), "wb");
        std::fwrite(text.data(), 1, text.size(), out);
        std::fclose(out);
    }
    ~Inputs() {
        std::error_code error;
        std::filesystem::remove_all(dir, error);
    }
};

const Inputs& inputs() {
    static const Inputs instance;
    return instance;
}

void report(benchmark::State& state, std::size_t bytes, const MeshData& mesh) {
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes));
    state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
    state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}

void parse_ply_bench(benchmark::State& state, const std::filesystem::path& file) {
    const std::vector<std::byte> bytes = read_file_bytes(file);
    MeshData mesh;
    for (auto _ : state) {
        mesh = parse_ply(bytes, "bench.ply");
        benchmark::DoNotOptimize(mesh.vertices.data());
    }
    report(state, bytes.size(), mesh);
}

void BM_parse_ply_float(benchmark::State& state) { parse_ply_bench(state, inputs().ply_float); }
void BM_parse_ply_double(benchmark::State& state) { parse_ply_bench(state, inputs().ply_double); }

// Bytes counted are the file's size on disk (compressed for .gz).
void read_file_bench(benchmark::State& state, const std::filesystem::path& file) {
    MeshData mesh;
    for (auto _ : state) {
        mesh = read_mesh_file(file);
        benchmark::DoNotOptimize(mesh.vertices.data());
    }
    report(state, std::filesystem::file_size(file), mesh);
}

void BM_read_mesh_file_ply(benchmark::State& state) { read_file_bench(state, inputs().ply_float); }
void BM_read_mesh_file_ply_gz(benchmark::State& state) { read_file_bench(state, inputs().ply_gz); }

void BM_parse_obj(benchmark::State& state) {
    const std::vector<std::byte> bytes = read_file_bytes(inputs().obj);
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    MeshData mesh;
    for (auto _ : state) {
        mesh = parse_obj(text, "bench.obj");
        benchmark::DoNotOptimize(mesh.vertices.data());
    }
    report(state, bytes.size(), mesh);
}

BENCHMARK(BM_parse_ply_float)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_parse_ply_double)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_read_mesh_file_ply)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_read_mesh_file_ply_gz)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_parse_obj)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
