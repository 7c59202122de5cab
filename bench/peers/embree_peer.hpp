#pragma once
// The Embree 3 broad phase of the peers (bench/peers): one scene per object, a user geometry
// whose primitives are the triangles (rtcCollide supports only user geometries), build
// quality RTC_BUILD_QUALITY_REFIT on a RTC_SCENE_FLAG_DYNAMIC scene (both are needed for a
// real refit, DESIGN.md), refit every frame, built again when the topology changes.
// rtcCollide of two scenes gives the object pairs' candidates; of a scene with itself, the
// self-collision candidates. Embree runs its collide and refit on its own (TBB) threads.

#include "peers/peer_common.hpp"

#include "collidescope/frame_context.hpp"

#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string>
#include <vector>

namespace collidescope::peers {

struct EmbreeObject {
    const ObjectFrame* mesh = nullptr;  // the current frame's object (bounds callback reads it)
    RTCScene scene = nullptr;
    RTCGeometry geometry = nullptr;
};

inline void embree_bounds(const RTCBoundsFunctionArguments* args) {
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
    tbb::enumerable_thread_specific<PairSet>* pairs = nullptr;  // one list per calling thread
};

// Called from Embree's threads, with small batches: each thread appends to its own list (a
// lock per batch cost the peer more than its narrow phase on the cloth scenes). Within one
// object, rtcCollide of a scene with itself reports a triangle with itself and every other
// pair in both orders (measured: 6,403,846 reports for 3,201,923 pairs on cloth-crumple:large),
// so keeping primID0 < primID1 gives each pair once without a sort (sorting cost about a
// second per frame there); bench_embree_cgal_peers checks, untimed, that no pair repeats.
inline void embree_collide(void* user, RTCCollision* collisions, unsigned int count) {
    auto* collect = static_cast<EmbreeCollect*>(user);
    PairSet& pairs = collect->pairs->local();
    for (unsigned int i = 0; i < count; ++i) {
        const std::uint32_t p0 = collisions[i].primID0, p1 = collisions[i].primID1;
        if (collect->a != collect->b) {
            pairs.push_back({collect->a, p0, collect->b, p1});
        } else if (p0 < p1) {
            pairs.push_back({collect->a, p0, collect->b, p1});
        }
    }
}

class EmbreePeer {
public:
    /// `quality`: RTC_BUILD_QUALITY_REFIT (the default: refit every frame) or a build quality
    /// (RTC_BUILD_QUALITY_LOW, MEDIUM: the tree is built again every frame). `threads` > 0:
    /// Embree's builds run on that many threads (its `threads` device setting), as the engine's
    /// do under --threads; 0: all hardware threads.
    explicit EmbreePeer(RTCBuildQuality quality = RTC_BUILD_QUALITY_REFIT, int threads = 0)
        : m_device(rtcNewDevice(threads > 0 ? ("threads=" + std::to_string(threads)).c_str() : nullptr)),
          m_quality(quality) {}
    ~EmbreePeer() {
        release();
        rtcReleaseDevice(m_device);
    }
    EmbreePeer(const EmbreePeer&) = delete;
    EmbreePeer& operator=(const EmbreePeer&) = delete;

    /// Refit (or first build, or rebuild after a topology change) for the frame.
    void update(const Frame& frame) {
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
    }

    /// The candidate pairs (box overlaps) of every object pair, (a, a) meaning self-collision,
    /// in canonical order within a pair, in no order between pairs. update() first.
    PairSet candidates(std::span<const ObjectPair> object_pairs) {
        for (PairSet& part : m_local) part.clear();
        for (const ObjectPair& pair : object_pairs) {
            EmbreeCollect collect;
            collect.a = pair.a;
            collect.b = pair.b;
            collect.pairs = &m_local;
            rtcCollide(m_objects[pair.a].scene, m_objects[pair.b].scene, &embree_collide, &collect);
        }
        PairSet pairs;
        for (const PairSet& part : m_local) pairs.insert(pairs.end(), part.begin(), part.end());
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
            rtcSetGeometryBuildQuality(object.geometry, m_quality);
            if (m_quality != RTC_BUILD_QUALITY_REFIT) rtcSetSceneBuildQuality(object.scene, m_quality);
            rtcAttachGeometry(object.scene, object.geometry);
            rtcReleaseGeometry(object.geometry);
        }
    }

    RTCDevice m_device;
    RTCBuildQuality m_quality;
    std::vector<EmbreeObject> m_objects;
    std::vector<std::uint64_t> m_revisions;
    /// The threads' candidate lists, kept between frames as the engine keeps its own
    /// (TraversalBuffers): made afresh each frame, their growth touched new memory every
    /// frame, and the peer's collide time on data set C moved between 2.3 and 7 ms with what
    /// else the process had allocated before (records/2026-11-26-large-blocks.md).
    tbb::enumerable_thread_specific<PairSet> m_local;
};

}  // namespace collidescope::peers
