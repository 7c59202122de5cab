// Algorithm 3 of the thesis: the adaptive number of triangles per occlusion query.

#include "gpucull/triangles_per_query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collidescope::gpucull {

TrianglesPerQuery::TrianglesPerQuery(TrianglesPerQueryConfig config)
    : m_config(config), m_p(std::clamp<std::uint32_t>(config.initial, 1, std::max<std::uint32_t>(1, config.maximum))) {}

double TrianglesPerQuery::predicted(std::uint32_t p) const {
    const auto it = m_predicted.find(p);
    return it == m_predicted.end() ? -1 : it->second;
}

double TrianglesPerQuery::fit(std::uint32_t p, double n, const QueryFrame& frame) const {
    if (p < 1 || p > m_config.maximum) return -std::numeric_limits<double>::infinity();
    const double queries_ms = frame.total * frame.query_ms / p;
    double needed = 0;  // (4.8): culled triangles P' needs to cost no more than n
    if (frame.rebuild_ms_per_triangle > 0) {
        needed = frame.total - (n - queries_ms) / frame.rebuild_ms_per_triangle;
    } else {  // culling saves nothing: only the queries' cost decides
        needed = queries_ms <= n ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    }
    const double predicted_cull = m_predicted.contains(p) ? m_predicted.at(p) : m_predicted.at(m_p);
    return predicted_cull - needed;  // (4.9), (4.10)
}

void TrianglesPerQuery::update(const QueryFrame& frame) {
    double& px = m_predicted.try_emplace(m_p, frame.culled).first->second;
    px = px / 4 + 0.75 * frame.culled;  // (4.3)
    const double n = frame.total * frame.query_ms / m_p + (frame.total - frame.culled) * frame.rebuild_ms_per_triangle;  // (4.4)
    const double up = fit(m_p + 1, n, frame);
    const double down = fit(m_p - 1, n, frame);
    if (up > down && up > 0) {
        ++m_p;
    } else if (down > up && down > 0) {
        --m_p;
    }
}

}  // namespace collidescope::gpucull
