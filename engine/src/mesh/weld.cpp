// weld: sort vertex ids by key, then give each run of equal keys its first vertex's new index.

#include "mesh/weld.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>
#include <numeric>

namespace collidescope {
namespace {

// A total order on doubles that agrees with == for every non-NaN value (so -0 and +0 are one
// key) and keeps NaNs apart by their bits: sorting stays well defined on any input.
std::uint64_t ordered_bits(double x) {
    if (x == 0) x = 0;  // -0 -> +0
    const auto bits = std::bit_cast<std::uint64_t>(x);
    // IEEE total order as unsigned integers: flip all bits of negatives, the sign bit of positives.
    return (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63);
}

class KeyOrder {
public:
    explicit KeyOrder(const WeldKeys& keys) : m_keys(keys) {}

    int compare(std::uint32_t a, std::uint32_t b) const {
        const std::uint32_t a_begin = m_keys.begin[a], a_end = m_keys.begin[a + 1];
        const std::uint32_t b_begin = m_keys.begin[b], b_end = m_keys.begin[b + 1];
        const std::uint32_t length = std::min(a_end - a_begin, b_end - b_begin);
        for (std::uint32_t i = 0; i < length; ++i) {
            const std::uint64_t x = ordered_bits(m_keys.values[a_begin + i]);
            const std::uint64_t y = ordered_bits(m_keys.values[b_begin + i]);
            if (x != y) return x < y ? -1 : 1;
        }
        const std::uint32_t a_length = a_end - a_begin, b_length = b_end - b_begin;
        return a_length == b_length ? 0 : (a_length < b_length ? -1 : 1);
    }

private:
    const WeldKeys& m_keys;
};

}  // namespace

Welding weld(const WeldKeys& keys) {
    const std::uint32_t count = keys.vertex_count();
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    const KeyOrder key_order(keys);
    // Stable by vertex id within equal keys, so each run starts at its first occurrence.
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const int c = key_order.compare(a, b);
        return c != 0 ? c < 0 : a < b;
    });
    std::vector<std::uint32_t> representative(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        const bool starts_run = i == 0 || key_order.compare(order[i - 1], order[i]) != 0;
        representative[order[i]] = starts_run ? order[i] : representative[order[i - 1]];
    }
    Welding welding;
    welding.remap.resize(count);
    for (std::uint32_t v = 0; v < count; ++v) {
        const std::uint32_t first = representative[v];
        if (first == v) {
            welding.remap[v] = static_cast<std::uint32_t>(welding.kept.size());
            welding.kept.push_back(v);
        } else {
            assert(first < v);
            welding.remap[v] = welding.remap[first];
        }
    }
    return welding;
}

}  // namespace collidescope
