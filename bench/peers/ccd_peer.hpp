#pragma once
// The CCD peer (bench/peers, issue 39 point 4): continuous detection built the way the
// literature's CPU codes are. Broad phase: per object an Embree 3 scene of user geometry whose
// primitive bounds are each triangle's swept box (the box of its three corners at both ends,
// which holds the triangle throughout the linear motion), built anew every interval at
// RTC_BUILD_QUALITY_LOW (by default: on A it takes 1.1 s over the run where a refit of a
// dynamic scene, RTC_BUILD_QUALITY_REFIT as the per-frame peer embree_peer.hpp, takes 3.4 s;
// `rebuild = false` keeps the refit); rtcCollide of every object pair whose scene bounds meet,
// and of each object with itself under self-collision. Narrow phase: ccd_root_finding.hpp on
// every candidate, on TBB's threads. The threads: Embree's device gets `threads=T` (as the
// per-frame peer); the narrow phase runs under the caller's tbb::global_control.

#include "peers/embree_peer.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/scene.hpp"

#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <vector>

namespace collidescope::peers {

/// What one interval took (ms) and tested.
struct CcdPeerStats {
    double refit_ms = 0, collide_ms = 0, narrow_ms = 0;
    std::uint64_t candidates = 0;
};

class CcdPeer {
public:
    /// `threads` > 0: Embree's device runs on that many threads; 0: all hardware threads.
    /// `rebuild`: each interval's trees built anew at RTC_BUILD_QUALITY_LOW (the faster on
    /// the built-in scenes); else a dynamic scene refit (RTC_BUILD_QUALITY_REFIT).
    CcdPeer(bool self_collision, int threads, bool rebuild = true);
    ~CcdPeer();
    CcdPeer(const CcdPeer&) = delete;
    CcdPeer& operator=(const CcdPeer&) = delete;

    /// The pairs touching during the interval from `from` to `to`, sorted by pair, each once
    /// (IntervalContact as ours reports it; `resolved` always true). δ (the distance at a root
    /// that counts as contact) is ours' default: 1e-6 times the interval's largest extent.
    std::vector<IntervalContact> detect(const Frame& from, const Frame& to, CcdPeerStats& stats);

private:
    struct SweptObject {
        const ObjectFrame* from = nullptr;  // the interval's ends (the bounds callback reads them)
        const ObjectFrame* to = nullptr;
        RTCScene scene = nullptr;
        RTCGeometry geometry = nullptr;
    };
    static void swept_bounds(const RTCBoundsFunctionArguments* args);

    void update(const Frame& from, const Frame& to);
    PairSet candidates();
    std::vector<IntervalContact> narrow_phase(const Frame& from, const Frame& to, const PairSet& candidates);
    void create(const Frame& frame);
    void release();

    bool m_self;
    bool m_rebuild;
    RTCDevice m_device;
    std::vector<SweptObject> m_objects;  // sized once per topology: Embree holds pointers into it
    std::vector<std::uint64_t> m_revisions;
    tbb::enumerable_thread_specific<PairSet> m_local;  // the threads' candidates, kept between intervals
    tbb::enumerable_thread_specific<std::vector<IntervalContact>> m_found;
};

}  // namespace collidescope::peers
