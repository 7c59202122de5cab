#include "support/rational_reference.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <optional>
#include <set>
#include <vector>

namespace collidescope::testing {
namespace {

using Q = mpq_class;
using Point = std::array<Q, 3>;

Point to_rational(const Vec3& p) { return {Q(p.x()), Q(p.y()), Q(p.z())}; }

Q dot(const Point& f, const Point& x) { return f[0] * x[0] + f[1] * x[1] + f[2] * x[2]; }

Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Dense simplex tableau for  A x = b, x >= 0  with one artificial variable per row.
/// Columns: n structural, then m artificial, then the right-hand side.
class Tableau {
public:
    Tableau(const std::vector<std::vector<Q>>& a, const std::vector<Q>& b)
        : m_rows(a.size()), m_structural(a[0].size()) {
        const std::size_t width = m_structural + m_rows + 1;
        m_cells.assign(m_rows + 1, std::vector<Q>(width, Q(0)));
        for (std::size_t i = 0; i < m_rows; ++i) {
            const int flip = b[i] < 0 ? -1 : 1;  // make the right-hand side non-negative
            for (std::size_t j = 0; j < m_structural; ++j) m_cells[i][j] = flip * a[i][j];
            m_cells[i][m_structural + i] = 1;
            m_cells[i][width - 1] = flip * b[i];
            m_basis.push_back(m_structural + i);
        }
    }

    /// Phase 1: true when A x = b, x >= 0 is feasible. Leaves a feasible basis behind.
    bool make_feasible() {
        std::vector<Q> cost(m_structural + m_rows, Q(0));
        for (std::size_t i = 0; i < m_rows; ++i) cost[m_structural + i] = -1;  // max -sum(art)
        set_objective(cost);
        optimise(m_structural + m_rows);
        if (objective_value() != 0) return false;
        for (std::size_t i = 0; i < m_rows; ++i) {  // pivot zero-level artificials out
            if (m_basis[i] < m_structural) continue;
            for (std::size_t j = 0; j < m_structural; ++j)
                if (m_cells[i][j] != 0) {
                    pivot(i, j);
                    break;
                }
            // A row left with only artificials is redundant; it never limits a pivot.
        }
        return true;
    }

    /// Phase 2: the maximum of cost . x over the feasible set (bounded by assumption).
    Q maximise(const std::vector<Q>& structural_cost) {
        std::vector<Q> cost(structural_cost);
        cost.resize(m_structural + m_rows, Q(0));
        set_objective(cost);
        optimise(m_structural);
        return objective_value();
    }

private:
    std::size_t rhs() const { return m_structural + m_rows; }
    Q objective_value() const { return m_cells[m_rows][rhs()]; }

    /// Objective row: reduced costs z_j - c_j for  max cost . x  in the current basis.
    void set_objective(const std::vector<Q>& cost) {
        m_cost = cost;
        auto& z = m_cells[m_rows];
        for (std::size_t j = 0; j <= rhs(); ++j) {
            Q sum = 0;
            for (std::size_t i = 0; i < m_rows; ++i) sum += m_cost[m_basis[i]] * m_cells[i][j];
            z[j] = j < rhs() ? sum - m_cost[j] : sum;
        }
    }

    /// Bland's rule over columns [0, allowed): smallest improving column, smallest basic
    /// variable among tied ratios. Terminates without cycling.
    void optimise(std::size_t allowed) {
        for (;;) {
            std::optional<std::size_t> enter;
            for (std::size_t j = 0; j < allowed && !enter; ++j)
                if (m_cells[m_rows][j] < 0) enter = j;
            if (!enter) return;
            std::optional<std::size_t> leave;
            Q best_ratio;
            for (std::size_t i = 0; i < m_rows; ++i) {
                if (m_cells[i][*enter] <= 0) continue;
                const Q ratio = m_cells[i][rhs()] / m_cells[i][*enter];
                if (!leave || ratio < best_ratio ||
                    (ratio == best_ratio && m_basis[i] < m_basis[*leave])) {
                    leave = i;
                    best_ratio = ratio;
                }
            }
            if (!leave) return;  // unbounded: cannot happen on a polytope
            pivot(*leave, *enter);
        }
    }

    void pivot(std::size_t row, std::size_t column) {
        const Q p = m_cells[row][column];
        for (auto& cell : m_cells[row]) cell /= p;
        for (std::size_t i = 0; i <= m_rows; ++i) {
            if (i == row || m_cells[i][column] == 0) continue;
            const Q factor = m_cells[i][column];
            for (std::size_t j = 0; j <= rhs(); ++j) m_cells[i][j] -= factor * m_cells[row][j];
        }
        m_basis[row] = column;
    }

    std::size_t m_rows;
    std::size_t m_structural;
    std::vector<std::vector<Q>> m_cells;
    std::vector<std::size_t> m_basis;
    std::vector<Q> m_cost;
};

/// The LP of T1 ∩ T2 over x = (l0, l1, l2, m0, m1, m2).
Tableau intersection_program(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
    std::vector<std::vector<Q>> rows(5, std::vector<Q>(6, Q(0)));
    std::vector<Q> rhs(5, Q(0));
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) {
            rows[k][i] = a[i][k];
            rows[k][3 + i] = -b[i][k];
        }
    for (int i = 0; i < 3; ++i) {
        rows[3][i] = 1;
        rows[4][3 + i] = 1;
    }
    rhs[3] = rhs[4] = 1;
    return Tableau(rows, rhs);
}

}  // namespace

bool reference_triangles_intersect(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
    const std::array<Point, 3> qa = {to_rational(a[0]), to_rational(a[1]), to_rational(a[2])};
    const std::array<Point, 3> qb = {to_rational(b[0]), to_rational(b[1]), to_rational(b[2])};
    return intersection_program(qa, qb).make_feasible();
}

bool reference_self_collide(const TriIndices& ia, const std::array<Vec3, 3>& pa,
                            const TriIndices& ib, const std::array<Vec3, 3>& pb) {
    const std::set<std::uint32_t> sa(ia.begin(), ia.end()), sb(ib.begin(), ib.end());
    std::vector<std::uint32_t> shared;
    std::set_intersection(sa.begin(), sa.end(), sb.begin(), sb.end(), std::back_inserter(shared));
    // A triangle whose corners are all shared *is* inside H, and so is its intersection.
    if (shared.size() == sa.size() || shared.size() == sb.size()) return false;
    const std::array<Point, 3> qa = {to_rational(pa[0]), to_rational(pa[1]), to_rational(pa[2])};
    const std::array<Point, 3> qb = {to_rational(pb[0]), to_rational(pb[1]), to_rational(pb[2])};
    Tableau program = intersection_program(qa, qb);
    if (!program.make_feasible()) return false;
    if (shared.empty()) return true;

    // H's points, and functionals f with H = ∩ {f <= max_H f}.
    std::vector<Point> hull;
    for (std::uint32_t index : shared)
        for (int k = 0; k < 3; ++k)
            if (ia[k] == index) {
                hull.push_back(qa[k]);
                break;
            }
    std::vector<Point> functionals;
    const Point d = {hull.back()[0] - hull[0][0], hull.back()[1] - hull[0][1],
                     hull.back()[2] - hull[0][2]};
    if (d == Point{0, 0, 0}) {  // H is a point: the six axis directions
        for (int k = 0; k < 3; ++k) {
            Point e = {0, 0, 0};
            e[k] = 1;
            functionals.push_back(e);
        }
    } else {  // H is a segment: its direction, and normals spanning d's orthogonal complement
        functionals.push_back(d);
        for (int k = 0; k < 3; ++k) {
            Point e = {0, 0, 0};
            e[k] = 1;
            const Point n = cross(d, e);
            if (n != Point{0, 0, 0}) functionals.push_back(n);
        }
    }
    for (const Point& f : functionals)
        for (int sign : {1, -1}) {
            const Point g = {sign * f[0], sign * f[1], sign * f[2]};
            Q hull_max = dot(g, hull[0]);
            for (const Point& h : hull) hull_max = std::max(hull_max, dot(g, h));
            Tableau copy = program;
            const Q best = copy.maximise({dot(g, qa[0]), dot(g, qa[1]), dot(g, qa[2]), 0, 0, 0});
            if (best > hull_max) return true;
        }
    return false;
}

}  // namespace collidescope::testing
