#include "solvers/multigrid_smoother.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/multigrid_local.hpp"

namespace eg2d {

namespace {
// Over-relaxing the line Gauss-Seidel smoother speeds up the damping of the
// errors that the explicit cross-derivative (-2 beta r_xieta) leaves behind on
// skewed cells: measured on the seed 003 domains, the cycle's factor drops by
// about 1.5x from omega = 1 to 1.3, with no change on orthogonal grids.
constexpr double kSmootherOmega = 1.3;
// Local relaxation after the sweeps (multigrid_local.hpp): 2 point sweeps in
// a 9x9 box round each singular boundary node, on every level. Measured on
// the NACA0012 O-grid 513x129 (bench): 6 cycles at 0.12 each without, 4
// at 0.02-0.04 with (the largest residual sat at the trailing edge, node
// (0, 2), in every cycle); radius 2 is nearly as good, 8 no better.
constexpr int kLocalRadius = 4;
constexpr int kLocalSweeps = 2;
constexpr int kCoarseSweepCap = 50;
}  // namespace

void smooth(System system, MgLevel &m, int sweeps, bool reverse) {
    const double omega = kSmootherOmega;
    for (int s = 0; s < sweeps; ++s) {
        if (!reverse) {
            sweep_xi_lines(system, m.level, omega, m.work, LineOrder::Forward);
            sweep_eta_lines(system, m.level, omega, m.work, LineOrder::Zebra);
        } else {
            sweep_eta_lines(system, m.level, omega, m.work, LineOrder::Zebra);
            sweep_xi_lines(system, m.level, omega, m.work, LineOrder::Backward);
        }
        relax_extra_unknowns(system, m.level, 1.0);
    }
    if (sweeps > 0) relax_near(system, m.level, m.singular, kLocalRadius, kLocalSweeps);
}

void compute_residual(System system, MgLevel &m) {
    const Connectivity &c = m.conn;
    for (int j = c.j_begin(); j < c.j_end(); ++j)
        for (int i = c.i_begin(); i < c.i_end(); ++i) {
            const Stencil s = c.stencil(i, j);
            const NodeEquation eq = node_equation(system, m.level, s);
            m.rx[s.c] = eq.rx;
            m.ry[s.c] = eq.ry;
        }
    for (const Connectivity::Node &p : c.extra_unknowns()) {
        const Stencil s = c.stencil(p.i, p.j);
        const NodeEquation eq = node_equation(system, m.level, s);
        m.rx[s.c] = eq.rx;
        m.ry[s.c] = eq.ry;
    }
}

void coarse_solve(System system, MgLevel &m, double floor) {
    // The smoother's own sweeps, not over-relaxed line SOR: on coarse airfoil
    // O-grids (NACA0012, 65x33 and 5x5 levels of a 129x33 grid) line SOR at
    // its model optimum made the coarse residual grow, which stalled or broke
    // the cycle. The best iterate is kept, so the coarse solve never returns
    // a worse grid than it was given.
    const std::size_t n = m.size();
    m.best_x.resize(n);  // once per level (a level becomes the coarsest when coarser ones fail)
    m.best_y.resize(n);
    double best = residual(system, m.level, 0.0).value;
    const double target = 1e-3 * best;
    std::copy(m.level.x, m.level.x + n, m.best_x.begin());
    std::copy(m.level.y, m.level.y + n, m.best_y.begin());
    // At most kCoarseSweepCap sweeps: a coarsest level is large only when the
    // coarser ones were dropped (multigrid.cpp keep_coarse), and then an
    // accurate solve there costs more than it brings (NACA0012 257x65 with
    // the wall control, levels below 129x33 dropped: 268 sweeps per cycle,
    // 2.1 s; capped at 50, 0.6 s for the same cycle count).
    const int cap = std::min(kCoarseSweepCap, 10 + 2 * std::max(m.conn.ni(), m.conn.nj()));
    for (int s = 0; s < cap && best > target && best > floor; ++s) {
        smooth(system, m, 1, (s & 1) != 0);
        const double r = residual(system, m.level, 0.0).value;
        if (!std::isfinite(r)) break;
        if (r < best) {
            best = r;
            std::copy(m.level.x, m.level.x + n, m.best_x.begin());
            std::copy(m.level.y, m.level.y + n, m.best_y.begin());
        }
    }
    std::copy(m.best_x.begin(), m.best_x.end(), m.level.x);
    std::copy(m.best_y.begin(), m.best_y.end(), m.level.y);
}

}  // namespace eg2d
