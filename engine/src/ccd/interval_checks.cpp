// The interval's input checks and its default tolerance.

#include "ccd/interval_checks.hpp"

#include "collidescope/between_frames.hpp"
#include "collidescope/error.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <string>

namespace collidescope::ccd {
namespace {

constexpr double k_largest = 1e100;  // products of three coordinate differences must not overflow

// The box of a frame's vertices, and whether every coordinate is finite and at most
// k_largest in size: one pass over the coordinates, two vertices (six doubles, three pairs)
// a step in vector registers, without a branch (the two frames' scans, separate scalar loops
// before, were a tenth of a soup's interval), in parallel over runs of vertices (one thread's
// scans were still 8% of a soup's interval at two threads).
struct Scan {
    double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[3] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()};
    bool finite = true;  ///< no coordinate NaN or infinite
    bool fine = true;    ///< finite, and the box within k_largest (set by scan only)

    void grow(const Scan& other) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], other.lo[k]);
            hi[k] = std::max(hi[k], other.hi[k]);
        }
        finite = finite && other.finite;
    }
};

using Doubles = double __attribute__((vector_size(16)));

Doubles load(const unsigned char* p) {
    Doubles v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// The box of a run of vertices, and whether they are finite.
Scan scan_run(std::span<const Vec3> vertices) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    // Lanes (x, y), (z, x), (y, z) of two vertices; plain locals, so that they stay in
    // registers. `poison` sums each coordinate times zero: NaN once one is NaN or infinite.
    Doubles lo0 = {inf, inf}, lo1 = lo0, lo2 = lo0, hi0 = -lo0, hi1 = hi0, hi2 = hi0;
    Doubles poison0 = {0, 0}, poison1 = poison0, poison2 = poison0;
    const auto take = [](Doubles v, Doubles& lo, Doubles& hi, Doubles& poison) {
        lo = v < lo ? v : lo;
        hi = v > hi ? v : hi;
        poison += v * 0.0;
    };
    static_assert(sizeof(Vec3) == 3 * sizeof(double));
    // Vec3 is three packed doubles: two vertices are 48 bytes, read as three pairs.
    const auto* bytes = reinterpret_cast<const unsigned char*>(vertices.data());
    const std::size_t pairs = vertices.size() / 2;
    for (std::size_t i = 0; i < pairs; ++i, bytes += 2 * sizeof(Vec3)) {
        take(load(bytes), lo0, hi0, poison0);
        take(load(bytes + 16), lo1, hi1, poison1);
        take(load(bytes + 32), lo2, hi2, poison2);
    }
    if (vertices.size() % 2 != 0) {  // the last vertex, in both lanes
        const Vec3& last = vertices.back();
        take(Doubles{last.x(), last.y()}, lo0, hi0, poison0);
        take(Doubles{last.z(), last.x()}, lo1, hi1, poison1);
        take(Doubles{last.y(), last.z()}, lo2, hi2, poison2);
    }
    Scan s;
    s.lo[0] = std::min(lo0[0], lo1[1]);
    s.lo[1] = std::min(lo0[1], lo2[0]);
    s.lo[2] = std::min(lo1[0], lo2[1]);
    s.hi[0] = std::max(hi0[0], hi1[1]);
    s.hi[1] = std::max(hi0[1], hi2[0]);
    s.hi[2] = std::max(hi1[0], hi2[1]);
    const Doubles poison = poison0 + poison1 + poison2;
    s.finite = poison[0] == 0 && poison[1] == 0;
    return s;
}

Scan scan(const Frame& frame) {
    constexpr std::size_t k_run = 1 << 15;  // the grain: about this many vertices (768 KiB) a task or more
    Scan s;
    for (const ObjectFrame& object : frame.objects) {
        const auto vertices = object.vertices.span();
        if (vertices.size() <= k_run) {
            s.grow(scan_run(vertices));
            continue;
        }
        s.grow(tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(0, vertices.size(), k_run), Scan{},
            [&](const tbb::blocked_range<std::size_t>& range, Scan partial) {
                partial.grow(scan_run(vertices.subspan(range.begin(), range.size())));
                return partial;
            },
            [](Scan a, const Scan& b) {  // min, max and "and": the same whatever the split
                a.grow(b);
                return a;
            }));
    }
    s.fine = s.finite;
    for (int k = 0; k < 3; ++k) s.fine = s.fine && -k_largest <= s.lo[k] && s.hi[k] <= k_largest;
    return s;
}

// The first vertex of `frame` that scan found unfit, named.
[[noreturn]] void report_unfit(const Frame& frame) {
    for (std::size_t i = 0; i < frame.objects.size(); ++i) {
        const auto vertices = frame.objects[i].vertices.span();
        for (std::size_t v = 0; v < vertices.size(); ++v) {
            const std::string where = "frame " + std::to_string(frame.index) + ", object " + std::to_string(i) +
                                      ": vertex " + std::to_string(v);
            if (!vertices[v].allFinite()) {
                throw InputError(where + " is not finite (between-frames detection needs finite coordinates)");
            }
            if (vertices[v].cwiseAbs().maxCoeff() > k_largest) {
                throw InputError(where + " has a coordinate above 1e100 (between-frames detection's limit)");
            }
        }
    }
    throw InputError("frame " + std::to_string(frame.index) + " has a coordinate that is not finite or above 1e100");
}

double tolerance_of(const Scan& first, const Scan& second, double requested) {
    if (requested > 0) return requested;
    double extent = 0;
    for (int k = 0; k < 3; ++k) {
        const double lo = std::min(first.lo[k], second.lo[k]), hi = std::max(first.hi[k], second.hi[k]);
        if (lo <= hi) extent = std::max(extent, hi - lo);  // no vertex: lo = inf, hi = -inf
    }
    // An infinite extent only where check_interval has not run (the peer's tolerance).
    return 1e-6 * (extent > 0 && extent < std::numeric_limits<double>::infinity() ? extent : 1.0);
}

}  // namespace

double check_interval(const Frame& from, const Frame& to, double requested_tolerance) {
    if (from.objects.size() != to.objects.size()) {
        throw InputError("frames " + std::to_string(from.index) + " and " + std::to_string(to.index) + " have " +
                         std::to_string(from.objects.size()) + " and " + std::to_string(to.objects.size()) +
                         " objects: between-frames detection needs the same objects in both");
    }
    for (std::size_t i = 0; i < from.objects.size(); ++i) {
        const Topology& a = *from.objects[i].topology;
        const Topology& b = *to.objects[i].topology;
        const bool same = &a == &b || (a.revision != 0 && a.revision == b.revision) ||
                          (a.vertex_count == b.vertex_count && a.triangles == b.triangles);
        if (!same) {
            throw InputError("object " + std::to_string(i) + " changes its mesh between frames " + std::to_string(from.index) +
                             " and " + std::to_string(to.index) + " (" + std::to_string(a.vertex_count) + " to " +
                             std::to_string(b.vertex_count) + " vertices, " + std::to_string(a.triangles.size()) + " to " +
                             std::to_string(b.triangles.size()) +
                             " triangles): between-frames detection needs the same topology at both ends");
        }
    }
    const Scan first = scan(from);
    if (!first.fine) report_unfit(from);
    const Scan second = scan(to);
    if (!second.fine) report_unfit(to);
    return tolerance_of(first, second, requested_tolerance);
}

double interval_tolerance(const Frame& from, const Frame& to, double requested) {
    return requested > 0 ? requested : tolerance_of(scan(from), scan(to), requested);
}

}  // namespace collidescope::ccd

namespace collidescope {

std::string with_object_names(const std::string& message, const std::vector<std::string>& names) {
    // A plain scan, not std::regex: GCC 12's <regex> warns (maybe-uninitialized) under the
    // sanitizers and costs the engine its compile time.
    const std::string word = "object ";
    std::string out;
    std::size_t at = 0;
    for (std::size_t found = message.find(word); found != std::string::npos; found = message.find(word, at)) {
        std::size_t end = found + word.size();
        while (end < message.size() && message[end] >= '0' && message[end] <= '9') ++end;
        out += message.substr(at, end - at);
        at = end;
        if (end == found + word.size() || end - found - word.size() > 9) continue;  // no index, or far too long for one
        const std::size_t index = std::stoul(message.substr(found + word.size(), end - found - word.size()));
        if (index < names.size()) out += " ('" + names[index] + "')";
    }
    return out + message.substr(at);
}

}  // namespace collidescope
