// embed_cpp: a simulation loop that calls collidescope once per frame.
//
//   embed_cpp SCENE [PAIRS.tsv [RUN.h5]]
//
// The "simulation" is a built-in data set (SCENE as `collidescope check --scene` takes it), so
// the pairs can be checked against `check --pairs`: they are written in its TSV format. With
// RUN.h5 the session records what `collidescope record` would; `replay` and `inspect` read it.

#include <collidescope/error.hpp>
#include <collidescope/scene_frames.hpp>
#include <collidescope/session.hpp>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

int run(const std::string& spec, const char* pairs_path, const char* record_path) {
    collidescope::SceneFrames scene = collidescope::SceneFrames::builtin(spec);
    collidescope::Session session({.method = "adaptive",
                                   .self_collision = scene.self_collision(),
                                   .record = record_path != nullptr ? record_path : "",
                                   .scene = scene.name()});
    scene.load(0);
    for (std::uint32_t k = 0; k < scene.object_count(); ++k) {
        session.add_object(scene.triangles(k), scene.object_name(k));  // triangles once
    }
    std::FILE* pairs_file = pairs_path != nullptr ? std::fopen(pairs_path, "w") : nullptr;
    if (pairs_path != nullptr && pairs_file == nullptr) throw std::runtime_error(std::string("cannot write ") + pairs_path);
    std::uint64_t total = 0;
    std::vector<collidescope::VertexView> positions(scene.object_count());
    for (std::uint32_t frame = 0; frame < scene.frame_count(); ++frame) {
        scene.load(frame);  // the simulation's step: new positions, in its own arrays
        for (std::uint32_t k = 0; k < scene.object_count(); ++k) positions[k] = collidescope::vertex_view(scene.positions(k));
        const std::span<const collidescope::CollidingPair> pairs = session.step(positions);
        for (const collidescope::CollidingPair& p : pairs) {
            if (pairs_file != nullptr) std::fprintf(pairs_file, "%u\t%u\t%u\t%u\t%u\n", frame, p.obj_a, p.tri_a, p.obj_b, p.tri_b);
        }
        total += pairs.size();
        const collidescope::StepStats& stats = session.stats();
        std::printf("frame %u: %zu colliding pairs, %.3f ms (%s)\n", frame, pairs.size(), stats.ms.total, stats.method.c_str());
    }
    session.close();  // finishes the recording
    if (pairs_file != nullptr) std::fclose(pairs_file);
    std::printf("total: %u frames, %llu colliding pairs\n", scene.frame_count(), static_cast<unsigned long long>(total));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 4) {
        std::fprintf(stderr, "usage: embed_cpp SCENE [PAIRS.tsv [RUN.h5]]\n");
        return 2;
    }
    try {
        return run(argv[1], argc > 2 ? argv[2] : nullptr, argc > 3 ? argv[3] : nullptr);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "embed_cpp: error: %s\n", error.what());
        return 2;
    }
}
