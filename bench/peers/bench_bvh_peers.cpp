// Peers on the data sets' frames: Embree 3 rtcCollide (user geometries, refit build quality
// on a dynamic scene) and FCL 0.7 (BVHModel<AABB>, refit, exhaustive contacts), next to the
// `aabb` method, between objects (self-collision off: neither peer does it). Per data set:
// ms per frame of each, and how each peer's pairs differ from the exact ones (missed exact
// pairs, extra pairs). Embree reports box-overlap candidates (float boxes), FCL its own
// floating-point triangle test. Built only when both packages are installed (bench/CMakeLists).
//
//   build-bvh/bench/bench_bvh_peers [--benchmark_filter=C]

#include "methods/aabb_method.hpp"
#include "common/object_level.hpp"

#include "collidescope/datasets.hpp"

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <fcl/fcl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <set>

namespace {

using namespace collidescope;
using Clock = std::chrono::steady_clock;
using PairSet = std::vector<TrianglePair>;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The objects' topology revisions: a peer rebuilds from scratch when they change (fractures).
std::vector<std::uint64_t> revisions(const Frame& frame) {
    std::vector<std::uint64_t> out;
    for (const ObjectFrame& object : frame.objects) out.push_back(object.topology->revision);
    return out;
}

// ---- Embree: one scene per object, a user geometry whose primitives are the triangles.
struct EmbreeObject {
    const ObjectFrame* mesh = nullptr;  // the current frame's object (bounds callback reads it)
    RTCScene scene = nullptr;
    RTCGeometry geometry = nullptr;
};

void embree_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* object = static_cast<const EmbreeObject*>(args->geometryUserPtr);
    const std::array<Vec3, 3> c = object->mesh->corners(args->primID);
    RTCBounds* b = args->bounds_o;
    // Float boxes rounded outward (nextafter), so they contain the double box.
    const auto lo = [&](int k) { return std::nextafter(static_cast<float>(std::min({c[0][k], c[1][k], c[2][k]})), -INFINITY); };
    const auto hi = [&](int k) { return std::nextafter(static_cast<float>(std::max({c[0][k], c[1][k], c[2][k]})), INFINITY); };
    b->lower_x = lo(0); b->lower_y = lo(1); b->lower_z = lo(2);
    b->upper_x = hi(0); b->upper_y = hi(1); b->upper_z = hi(2);
}

struct EmbreeCollect {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    std::mutex mutex;
    PairSet* pairs = nullptr;
};

void embree_collide(void* user, RTCCollision* collisions, unsigned int count) {
    auto* collect = static_cast<EmbreeCollect*>(user);
    const std::lock_guard<std::mutex> lock(collect->mutex);
    for (unsigned int i = 0; i < count; ++i) {
        collect->pairs->push_back({collect->a, collisions[i].primID0, collect->b, collisions[i].primID1});
    }
}

class EmbreePeer {
public:
    EmbreePeer() : m_device(rtcNewDevice(nullptr)) {}
    ~EmbreePeer() {
        release();
        rtcReleaseDevice(m_device);
    }
    // Refit (or first build, or rebuild after a topology change) for the frame, then collide
    // every object pair.
    PairSet frame(const Frame& frame, std::span<const ObjectPair> object_pairs) {
        if (m_objects.empty() || revisions(frame) != m_revisions) {
            release();
            create(frame);
            m_revisions = revisions(frame);
        }
        for (std::size_t o = 0; o < m_objects.size(); ++o) {
            m_objects[o].mesh = &frame.objects[o];
            rtcCommitGeometry(m_objects[o].geometry);
            rtcCommitScene(m_objects[o].scene);
        }
        PairSet pairs;
        for (const ObjectPair& pair : object_pairs) {
            if (pair.a == pair.b) continue;
            EmbreeCollect collect;
            collect.a = pair.a;
            collect.b = pair.b;
            collect.pairs = &pairs;
            rtcCollide(m_objects[pair.a].scene, m_objects[pair.b].scene, &embree_collide, &collect);
        }
        return pairs;
    }

private:
    void release() {
        for (EmbreeObject& o : m_objects) rtcReleaseScene(o.scene);
        m_objects.clear();
    }

    void create(const Frame& frame) {
        m_objects.resize(frame.objects.size());
        for (std::size_t o = 0; o < frame.objects.size(); ++o) {
            EmbreeObject& object = m_objects[o];
            object.mesh = &frame.objects[o];
            object.scene = rtcNewScene(m_device);
            rtcSetSceneFlags(object.scene, RTC_SCENE_FLAG_DYNAMIC);  // needed for a real refit
            object.geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_USER);
            rtcSetGeometryUserPrimitiveCount(object.geometry, static_cast<unsigned>(frame.objects[o].triangle_count()));
            rtcSetGeometryUserData(object.geometry, &object);
            rtcSetGeometryBoundsFunction(object.geometry, &embree_bounds, nullptr);
            rtcSetGeometryBuildQuality(object.geometry, RTC_BUILD_QUALITY_REFIT);
            rtcAttachGeometry(object.scene, object.geometry);
            rtcReleaseGeometry(object.geometry);
        }
    }

    RTCDevice m_device;
    std::vector<EmbreeObject> m_objects;
    std::vector<std::uint64_t> m_revisions;
};

// ---- FCL: one BVHModel<AABB> per object, refit bottom-up every frame.
class FclPeer {
public:
    PairSet frame(const Frame& frame, std::span<const ObjectPair> object_pairs) {
        if (m_models.empty() || revisions(frame) != m_revisions) {
            m_models.clear();
            m_objects.clear();
            create(frame);
            m_revisions = revisions(frame);
        }
        for (std::size_t o = 0; o < m_models.size(); ++o) {
            m_models[o]->beginUpdateModel();
            m_models[o]->updateSubModel(points(frame.objects[o]));
            m_models[o]->endUpdateModel(true, true);  // refit, bottom-up
            m_objects[o]->computeAABB();
        }
        PairSet pairs;
        for (const ObjectPair& pair : object_pairs) {
            if (pair.a == pair.b) continue;
            fcl::CollisionRequestd request(std::numeric_limits<std::size_t>::max(), true);
            request.num_max_contacts = std::numeric_limits<std::size_t>::max();  // exhaustive
            fcl::CollisionResultd result;
            fcl::collide(m_objects[pair.a].get(), m_objects[pair.b].get(), request, result);
            for (std::size_t i = 0; i < result.numContacts(); ++i) {
                const fcl::Contactd& contact = result.getContact(i);
                pairs.push_back({pair.a, static_cast<std::uint32_t>(contact.b1), pair.b, static_cast<std::uint32_t>(contact.b2)});
            }
        }
        return pairs;
    }

private:
    using Model = fcl::BVHModel<fcl::AABBd>;

    static std::vector<fcl::Vector3d> points(const ObjectFrame& mesh) {
        std::vector<fcl::Vector3d> out(mesh.vertices.begin(), mesh.vertices.end());
        return out;
    }

    void create(const Frame& frame) {
        for (const ObjectFrame& mesh : frame.objects) {
            auto model = std::make_shared<Model>();
            std::vector<fcl::Triangle> triangles;
            for (const TriIndices& t : mesh.topology->triangles) triangles.emplace_back(t[0], t[1], t[2]);
            model->beginModel();
            model->addSubModel(points(mesh), triangles);
            model->endModel();
            m_models.push_back(model);
            m_objects.push_back(std::make_unique<fcl::CollisionObjectd>(model));
        }
    }

    std::vector<std::shared_ptr<Model>> m_models;
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> m_objects;
    std::vector<std::uint64_t> m_revisions;
};

// Pairs in `got` not in `exact` (extra) and in `exact` not in `got` (missed).
std::pair<std::size_t, std::size_t> difference(PairSet got, const PairSet& exact) {
    std::sort(got.begin(), got.end());
    got.erase(std::unique(got.begin(), got.end()), got.end());
    PairSet extra;
    PairSet missed;
    std::set_difference(got.begin(), got.end(), exact.begin(), exact.end(), std::back_inserter(extra));
    std::set_difference(exact.begin(), exact.end(), got.begin(), got.end(), std::back_inserter(missed));
    return {extra.size(), missed.size()};
}

const char* const k_sets[] = {"A", "B", "C", "D", "E1", "E2", "E3", "E4"};

void BM_peers(benchmark::State& state) {
    const Scene scene = make_builtin_scene(k_sets[state.range(0)]);
    const std::uint32_t frames = std::min<std::uint32_t>(scene.source->frame_count(), static_cast<std::uint32_t>(state.range(1)));
    state.SetLabel(k_sets[state.range(0)]);
    double ours_ms = 0, embree_ms = 0, fcl_ms = 0;
    std::size_t exact_pairs = 0, embree_extra = 0, embree_missed = 0, fcl_extra = 0, fcl_missed = 0;
    for (auto _ : state) {
        const std::unique_ptr<Method> ours = make_aabb_method();
        EmbreePeer embree;
        FclPeer fcl_peer;
        for (std::uint32_t f = 0; f < frames; ++f) {
            const Frame frame = scene.source->frame(f);
            Clock::time_point start = Clock::now();
            const std::vector<Eigen::AlignedBox3d> boxes = compute_object_boxes(frame);
            const std::vector<ObjectPair> object_pairs = find_object_pairs(boxes, false);
            PairSet exact;
            FrameStats stats;
            ours->detect({frame, boxes, object_pairs, false}, exact, stats);
            std::sort(exact.begin(), exact.end());
            exact.erase(std::unique(exact.begin(), exact.end()), exact.end());
            ours_ms += ms_since(start);
            start = Clock::now();
            const PairSet from_embree = embree.frame(frame, object_pairs);
            embree_ms += ms_since(start);
            start = Clock::now();
            const PairSet from_fcl = fcl_peer.frame(frame, object_pairs);
            fcl_ms += ms_since(start);
            exact_pairs += exact.size();
            const auto [e_extra, e_missed] = difference(from_embree, exact);
            const auto [f_extra, f_missed] = difference(from_fcl, exact);
            embree_extra += e_extra;
            embree_missed += e_missed;
            fcl_extra += f_extra;
            fcl_missed += f_missed;
        }
    }
    state.counters["aabb_ms"] = ours_ms / frames;
    state.counters["embree_ms"] = embree_ms / frames;
    state.counters["fcl_ms"] = fcl_ms / frames;
    state.counters["exact_pairs"] = static_cast<double>(exact_pairs);
    state.counters["embree_extra"] = static_cast<double>(embree_extra);
    state.counters["embree_missed"] = static_cast<double>(embree_missed);
    state.counters["fcl_extra"] = static_cast<double>(fcl_extra);
    state.counters["fcl_missed"] = static_cast<double>(fcl_missed);
}

// Arguments: data set, frames (the first N; each frame's peers refit from the last).
BENCHMARK(BM_peers)
    ->ArgNames({"set", "frames"})
    ->Args({0, 50})->Args({1, 50})->Args({2, 50})->Args({3, 50})->Args({4, 25})->Args({5, 50})->Args({6, 50})
    ->Args({7, 50})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
