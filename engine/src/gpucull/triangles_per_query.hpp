#pragma once
// The adaptive number of triangles per occlusion query (engine/src/gpucull, private; thesis
// 4.2.3, Algorithm 3, Equations 4.3-4.10, Table 4.1). It keeps a predicted cull PX[P] for
// every P it has tried and moves P up or down by one when the cost model says the neighbour
// would pay.
//
// Our reading of the garbled equations (the prose fixes their meaning):
//   (4.3) PX[P] = PX[P] / 4 + 3/4 * X               X = triangles culled this frame with P
//   (4.4) N = T O / P + U R                         the frame's cost: "the time per occlusion
//                                                   query multiplied by the number of queries"
//                                                   (T / P of them) "plus the time to rebuild
//                                                   the hierarchy as a function of un-culled
//                                                   triangles"; O = time per query, R =
//                                                   rebuild time per triangle, U = T - X
//   (4.8) X(P') = T - (N - T O / P') / R            what P' must cull to cost no more than N
//   (4.9, 4.10) fit(P') = PX[P'] - X(P')            predicted surplus of culling at P'
//   move to P + 1 when fit(P + 1) > fit(P - 1) and fit(P + 1) > 0; to P - 1 in the mirror
//   case. An untried P' is predicted to cull what P culls (an optimistic start, so it gets
//   explored). The extracted (4.8) reads "X = N RT O P R", i.e. (N - R T) / (O / P - R), which
//   is what N = X O / P + U R gives: queries charged for culled triangles only. With that
//   model, for any O / P > R, a larger P always needs more culling than P culls, so P only
//   ever falls to 1 (checked while writing this); the prose's T O / P reading is the one that
//   trades culling against queries as the thesis describes.

#include <cstdint>
#include <map>

namespace collidescope::gpucull {

/// Options of the mechanism.
struct TrianglesPerQueryConfig {
    std::uint32_t initial = 1;    ///< P of the first frame
    std::uint32_t maximum = 64;   ///< P never exceeds this
};

/// One frame's measurements.
struct QueryFrame {
    double culled = 0;            ///< X: triangles culled at the triangle level
    double total = 0;             ///< T: triangles that entered the triangle level
    double query_ms = 0;          ///< O: measured milliseconds per occlusion query
    double rebuild_ms_per_triangle = 0;  ///< R: measured final-step time per surviving triangle
};

/// P and its predictions. Not thread-safe.
class TrianglesPerQuery {
public:
    explicit TrianglesPerQuery(TrianglesPerQueryConfig config = {});
    std::uint32_t current() const { return m_p; }
    /// Algorithm 3 after a frame culled with current(): updates PX and maybe moves P.
    void update(const QueryFrame& frame);
    /// PX[P], or -1 when P was never tried.
    double predicted(std::uint32_t p) const;

private:
    double fit(std::uint32_t p, double n, const QueryFrame& frame) const;

    TrianglesPerQueryConfig m_config;
    std::uint32_t m_p;
    std::map<std::uint32_t, double> m_predicted;
};

}  // namespace collidescope::gpucull
