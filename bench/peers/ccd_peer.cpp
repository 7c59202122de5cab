// The CCD peer: Embree swept-box refit and rtcCollide, then the root-finding narrow phase
// (ccd_peer.hpp says what and why).

#include "peers/ccd_peer.hpp"

#include "peers/ccd_root_finding.hpp"

#include "ccd/interval_checks.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace collidescope::peers {
namespace {

bool bounds_overlap(const RTCBounds& a, const RTCBounds& b) {
    return a.lower_x <= b.upper_x && b.lower_x <= a.upper_x && a.lower_y <= b.upper_y && b.lower_y <= a.upper_y &&
           a.lower_z <= b.upper_z && b.lower_z <= a.upper_z;
}

CcdMotion motion(const Frame& from, const Frame& to, const TrianglePair& pair) {
    CcdMotion m;
    const ObjectFrame& a0 = from.objects[pair.obj_a];
    const ObjectFrame& a1 = to.objects[pair.obj_a];
    const ObjectFrame& b0 = from.objects[pair.obj_b];
    const ObjectFrame& b1 = to.objects[pair.obj_b];
    m.ia = a0.topology->triangles[pair.tri_a];
    m.ib = b0.topology->triangles[pair.tri_b];
    for (int i = 0; i < 3; ++i) {
        m.a[i] = {a0.vertices[m.ia[i]], a1.vertices[m.ia[i]]};
        m.b[i] = {b0.vertices[m.ib[i]], b1.vertices[m.ib[i]]};
    }
    m.self = pair.obj_a == pair.obj_b;
    return m;
}

}  // namespace

CcdPeer::CcdPeer(bool self_collision, int threads, bool rebuild)
    : m_self(self_collision),
      m_rebuild(rebuild),
      m_device(rtcNewDevice(threads > 0 ? ("threads=" + std::to_string(threads)).c_str() : nullptr)) {}

CcdPeer::~CcdPeer() {
    release();
    rtcReleaseDevice(m_device);
}

// The swept box of one triangle, in floats rounded outward so that it holds the double box.
void CcdPeer::swept_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* object = static_cast<const SweptObject*>(args->geometryUserPtr);
    const std::array<Vec3, 3> c0 = object->from->corners(args->primID);
    const std::array<Vec3, 3> c1 = object->to->corners(args->primID);
    Vec3 lo = c0[0], hi = c0[0];
    for (const std::array<Vec3, 3>* corners : {&c0, &c1}) {
        for (const Vec3& p : *corners) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
    }
    const auto down = [](double x) { return std::nextafter(static_cast<float>(x), -INFINITY); };
    const auto up = [](double x) { return std::nextafter(static_cast<float>(x), INFINITY); };
    RTCBounds* b = args->bounds_o;
    b->lower_x = down(lo.x()); b->lower_y = down(lo.y()); b->lower_z = down(lo.z());
    b->upper_x = up(hi.x()); b->upper_y = up(hi.y()); b->upper_z = up(hi.z());
}

std::vector<IntervalContact> CcdPeer::detect(const Frame& from, const Frame& to, CcdPeerStats& stats) {
    const Clock::time_point start = Clock::now();
    update(from, to);
    stats.refit_ms = ms_since(start);
    const PairSet found = candidates();
    stats.collide_ms = ms_since(start) - stats.refit_ms;
    stats.candidates = found.size();
    std::vector<IntervalContact> contacts = narrow_phase(from, to, found);
    stats.narrow_ms = ms_since(start) - stats.refit_ms - stats.collide_ms;
    return contacts;
}

void CcdPeer::update(const Frame& from, const Frame& to) {
    if (m_objects.empty() || revisions(from) != m_revisions) {
        release();
        create(from);
        m_revisions = revisions(from);
    }
    for (std::size_t o = 0; o < m_objects.size(); ++o) {
        m_objects[o].from = &from.objects[o];
        m_objects[o].to = &to.objects[o];
        rtcCommitGeometry(m_objects[o].geometry);
        rtcCommitScene(m_objects[o].scene);
    }
}

// rtcCollide of every object pair whose scene bounds meet, and of each object with itself
// under self-collision (embree_collide keeps each self pair once, in canonical order).
PairSet CcdPeer::candidates() {
    for (PairSet& part : m_local) part.clear();
    std::vector<RTCBounds> bounds(m_objects.size());
    for (std::size_t o = 0; o < m_objects.size(); ++o) rtcGetSceneBounds(m_objects[o].scene, &bounds[o]);
    const auto n = static_cast<std::uint32_t>(m_objects.size());
    for (std::uint32_t x = 0; x < n; ++x) {
        if (m_objects[x].from->triangle_count() == 0) continue;
        for (std::uint32_t y = m_self ? x : x + 1; y < n; ++y) {
            if (m_objects[y].from->triangle_count() == 0 || !bounds_overlap(bounds[x], bounds[y])) continue;
            EmbreeCollect collect;
            collect.a = x;
            collect.b = y;
            collect.pairs = &m_local;
            rtcCollide(m_objects[x].scene, m_objects[y].scene, &embree_collide, &collect);
        }
    }
    PairSet pairs;
    for (const PairSet& part : m_local) pairs.insert(pairs.end(), part.begin(), part.end());
    return pairs;
}

// Each candidate through the root-finding test, in parallel; the contacts sorted by pair and
// kept once (rtcCollide is not known to repeat a pair, but nothing promises it).
std::vector<IntervalContact> CcdPeer::narrow_phase(const Frame& from, const Frame& to, const PairSet& candidates) {
    const double delta = ccd::interval_tolerance(from, to, 0);
    for (std::vector<IntervalContact>& part : m_found) part.clear();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 256), [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<IntervalContact>& out = m_found.local();
        for (std::size_t k = range.begin(); k < range.end(); ++k) {
            const CcdOutcome outcome = root_finding_test_pair(motion(from, to, candidates[k]), delta);
            if (outcome.contact) out.push_back({candidates[k], outcome.toi, outcome.pass_through, true});
        }
    });
    std::vector<IntervalContact> contacts;
    for (const std::vector<IntervalContact>& part : m_found) contacts.insert(contacts.end(), part.begin(), part.end());
    std::sort(contacts.begin(), contacts.end(), [](const IntervalContact& a, const IntervalContact& b) { return a.pair < b.pair; });
    const auto same = [](const IntervalContact& a, const IntervalContact& b) { return a.pair == b.pair; };
    contacts.erase(std::unique(contacts.begin(), contacts.end(), same), contacts.end());
    return contacts;
}

void CcdPeer::create(const Frame& frame) {
    m_objects.resize(frame.objects.size());
    for (std::size_t o = 0; o < frame.objects.size(); ++o) {
        SweptObject& object = m_objects[o];
        object.scene = rtcNewScene(m_device);
        if (m_rebuild) rtcSetSceneBuildQuality(object.scene, RTC_BUILD_QUALITY_LOW);
        else rtcSetSceneFlags(object.scene, RTC_SCENE_FLAG_DYNAMIC);  // needed for a real refit
        object.geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(object.geometry, static_cast<unsigned>(frame.objects[o].triangle_count()));
        rtcSetGeometryUserData(object.geometry, &object);
        rtcSetGeometryBoundsFunction(object.geometry, &CcdPeer::swept_bounds, nullptr);
        rtcSetGeometryBuildQuality(object.geometry, m_rebuild ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_REFIT);
        rtcAttachGeometry(object.scene, object.geometry);
        rtcReleaseGeometry(object.geometry);
    }
}

void CcdPeer::release() {
    for (SweptObject& o : m_objects) rtcReleaseScene(o.scene);
    m_objects.clear();
}

}  // namespace collidescope::peers
