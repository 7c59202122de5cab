// Temporary soak driver: BetweenFrames against between_frames_reference on file inputs.
#include "collidescope/between_frames.hpp"
#include "collidescope/scene.hpp"

#include <tbb/global_control.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace collidescope;

static std::map<TrianglePair, IntervalContact> by_pair(const IntervalResult& r) {
    std::map<TrianglePair, IntervalContact> m;
    for (const auto& c : r.contacts) m.emplace(c.pair, c);
    return m;
}

int main(int argc, char** argv) {
    bool self = false;
    std::vector<std::string> inputs;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--self") self = true;
        else inputs.push_back(a);
    }
    Scene scene = open_inputs(inputs);
    std::vector<Frame> frames;
    for (std::uint32_t k = 0; k < scene.source->frame_count(); ++k) frames.push_back(scene.source->frame(k));
    BetweenFramesOptions options;
    options.self_collision = self;
    BetweenFramesOptions fine = options;
    fine.tolerance = 1e-12;
    fine.max_boxes = 20000;
    int bad = 0;
    std::size_t contacts = 0, left_out = 0, passes = 0, unresolved_fine = 0;
    std::vector<IntervalResult> one;
    for (const int threads : {1, 2}) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        BetweenFrames detector(options);
        for (std::size_t f = 0; f + 1 < frames.size(); ++f) {
            IntervalResult r = detector.detect(frames[f], frames[f + 1]);
            if (threads == 1) one.push_back(std::move(r));
            else if (!(r.contacts == one[f].contacts)) { ++bad; std::printf("THREADS differ interval %zu\n", f); }
        }
    }
    for (std::size_t f = 0; f + 1 < frames.size(); ++f) {
        const auto fast = by_pair(one[f]);
        const auto slow = by_pair(between_frames_reference(frames[f], frames[f + 1], options));
        for (const auto& [pair, found] : by_pair(between_frames_reference(frames[f], frames[f + 1], fine))) {
            if (!found.resolved) { ++unresolved_fine; continue; }
            const auto fit = fast.find(pair);
            if (fit != fast.end() && fit->second.toi > found.toi + 1e-6 && ++bad)
                std::printf("LATER THAN FINE interval %zu %u:%u %u:%u fast %.17g fine %.17g slow %.17g pass %d\n", f, pair.obj_a, pair.tri_a, pair.obj_b, pair.tri_b, fit->second.toi, found.toi, slow.count(pair) ? slow.at(pair).toi : -1.0, (int)fit->second.pass_through);
            if (!fast.count(pair)) { ++bad; std::printf("MISSED interval %zu %u:%u %u:%u toi %.17g\n", f, pair.obj_a, pair.tri_a, pair.obj_b, pair.tri_b, found.toi); }
        }
        for (const auto& [pair, found] : fast) {
            const auto it = slow.find(pair);
            if (it == slow.end()) { ++bad; std::printf("NOT IN REFERENCE interval %zu %u:%u %u:%u\n", f, pair.obj_a, pair.tri_a, pair.obj_b, pair.tri_b); continue; }
            if (found.pass_through != it->second.pass_through) { ++bad; std::printf("PASS FLAG interval %zu\n", f); }
            passes += found.pass_through;
        }
        contacts += fast.size();
        left_out += slow.size() - fast.size();
    }
    std::printf("contacts %zu pass %zu left_out %zu fine_unresolved %zu bad %d\n", contacts, passes, left_out, unresolved_fine, bad);
    return bad ? 3 : 0;
}
