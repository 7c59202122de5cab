// Top-down binned SAH build (Wald, "On fast construction of SAH-based bounding volume
// hierarchies", 2007): per node, triangle centroids binned along each axis, the split plane
// of least cost count_left * area_left + count_right * area_right, then partition in place.
// Children build in parallel above the grain; large nodes also bin in parallel.

#include "bvh/build_internal.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>

namespace collidescope::bvh::detail {
namespace {

constexpr std::uint32_t k_max_bins = 64;
constexpr std::uint32_t k_max_sah_depth = 64;

struct Bins {
    std::array<std::array<Aabb, k_max_bins>, 3> boxes{};
    std::array<std::array<std::uint32_t, k_max_bins>, 3> counts{};

    void merge(const Bins& other, std::uint32_t bins) {
        for (int axis = 0; axis < 3; ++axis) {
            for (std::uint32_t b = 0; b < bins; ++b) {
                boxes[axis][b].grow(other.boxes[axis][b]);
                counts[axis][b] += other.counts[axis][b];
            }
        }
    }
};

struct Split {
    int axis = -1;              ///< -1: no useful plane (centroids coincide): split the range in half
    std::uint32_t bin = 0;      ///< triangles in bins < bin go left
    double cost = 0;
};

class SahBuilder {
public:
    SahBuilder(const BuildInput& input, const BuildConfig& config, RawTree& raw)
        : m_input(input), m_config(config), m_raw(raw),
          m_bins(std::clamp(config.sah_bins, 2u, k_max_bins)) {}

    // Below k_max_sah_depth levels every split halves the range, which bounds the depth (and
    // the recursion) for any input.
    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, std::uint32_t depth = 0) {
        const std::uint32_t count = end - begin;
        if (count <= std::max(m_config.max_leaf_size, 1u)) {
            m_raw.nodes[node] = {begin, count};
            return;
        }
        std::uint32_t middle = begin + count / 2;
        if (depth < k_max_sah_depth) {
            const Aabb bounds = centroid_bounds(begin, end);
            const Split split = find_split(bounds, begin, end);
            if (split.axis >= 0) middle = partition(bounds, split, begin, end);
        }
        const std::uint32_t left = m_raw.allocate_pair();
        m_raw.nodes[node] = {left, 0};
        if (count >= m_config.parallel_grain) {
            tbb::parallel_invoke([&] { build(left, begin, middle, depth + 1); },
                                 [&] { build(left + 1, middle, end, depth + 1); });
        } else {
            build(left, begin, middle, depth + 1);
            build(left + 1, middle, end, depth + 1);
        }
    }

private:
    template <class Body, class Value, class Join>
    Value reduce(std::uint32_t begin, std::uint32_t end, Value init, Body body, Join join) const {
        if (end - begin < m_config.parallel_grain) return body(tbb::blocked_range<std::uint32_t>(begin, end), init);
        return tbb::parallel_reduce(tbb::blocked_range<std::uint32_t>(begin, end, 2048), init, body, join);
    }

    Aabb centroid_bounds(std::uint32_t begin, std::uint32_t end) const {
        return reduce(begin, end, Aabb{},
            [&](const tbb::blocked_range<std::uint32_t>& range, Aabb bounds) {
                for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
                    const auto& c = m_input.centroids[m_raw.ids[i]];
                    bounds.grow(Vec3(c[0], c[1], c[2]));
                }
                return bounds;
            },
            [](Aabb a, const Aabb& b) { a.grow(b); return a; });
    }

    double scale(const Aabb& bounds, int axis) const {
        return static_cast<double>(m_bins) / (bounds.hi[axis] - bounds.lo[axis]);
    }

    std::uint32_t bin_of(const Aabb& bounds, int axis, std::uint32_t id) const {
        return cell_of(m_input.centroids[id][axis], bounds.lo[axis], scale(bounds, axis), m_bins);
    }

    Bins fill_bins(const Aabb& bounds, std::uint32_t begin, std::uint32_t end) const {
        return reduce(begin, end, Bins{},
            [&](const tbb::blocked_range<std::uint32_t>& range, Bins bins) {
                for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
                    const std::uint32_t id = m_raw.ids[i];
                    for (int axis = 0; axis < 3; ++axis) {
                        const std::uint32_t b = bin_of(bounds, axis, id);
                        bins.boxes[axis][b].grow(m_input.boxes[id]);
                        ++bins.counts[axis][b];
                    }
                }
                return bins;
            },
            [&](Bins a, const Bins& b) { a.merge(b, m_bins); return a; });
    }

    Split find_split(const Aabb& bounds, std::uint32_t begin, std::uint32_t end) const {
        const Bins bins = fill_bins(bounds, begin, end);
        Split best;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(bounds.hi[axis] > bounds.lo[axis])) continue;
            // Sweep from the right: right_cost[b] is the cost of bins >= b.
            std::array<double, k_max_bins> right_cost{};
            Aabb box;
            std::uint32_t count = 0;
            for (std::uint32_t b = m_bins - 1; b > 0; --b) {
                box.grow(bins.boxes[axis][b]);
                count += bins.counts[axis][b];
                right_cost[b] = count == 0 ? 0 : box.half_area() * count;
            }
            box = Aabb{};
            count = 0;
            for (std::uint32_t b = 1; b < m_bins; ++b) {
                box.grow(bins.boxes[axis][b - 1]);
                count += bins.counts[axis][b - 1];
                const std::uint32_t right = (end - begin) - count;
                if (count == 0 || right == 0) continue;
                const double cost = box.half_area() * count + right_cost[b];
                if (best.axis < 0 || cost < best.cost) best = {axis, b, cost};
            }
        }
        return best;
    }

    std::uint32_t partition(const Aabb& bounds, const Split& split, std::uint32_t begin, std::uint32_t end) {
        const auto first = m_raw.ids.begin();
        const auto middle = std::partition(first + begin, first + end, [&](std::uint32_t id) {
            return bin_of(bounds, split.axis, id) < split.bin;
        });
        return static_cast<std::uint32_t>(middle - first);
    }

    const BuildInput& m_input;
    const BuildConfig& m_config;
    RawTree& m_raw;
    std::uint32_t m_bins;
};

}  // namespace

void build_sah(const BuildInput& input, const BuildConfig& config, RawTree& raw) {
    SahBuilder builder(input, config, raw);
    builder.build(0, 0, static_cast<std::uint32_t>(raw.ids.size()));
}

}  // namespace collidescope::bvh::detail
