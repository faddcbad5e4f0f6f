#include "solvers/multigrid_smoother.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/multigrid_local.hpp"
#include "solvers/multigrid_variational.hpp"

namespace eg2d {

namespace {
// Over-relaxing the line Gauss-Seidel smoother speeds up the damping of the
// errors that the explicit cross-derivative (-2 beta r_xieta) leaves behind on
// skewed cells: measured on the elliptic-grid course notes domains, the cycle's factor drops by
// about 1.5x from omega = 1 to 1.3, with no change on orthogonal grids.
constexpr double kSmootherOmega = 1.3;
// Local relaxation after the sweeps (multigrid_local.hpp): 2 point sweeps in
// a 9x9 box round each singular boundary node, on every level. Measured on
// the NACA0012 O-grid 513x129 (bench): 6 cycles at 0.12 each without, 4
// at 0.02-0.04 with (the largest residual sat at the trailing edge, node
// (0, 2), in every cycle); radius 2 is nearly as good, 8 no better.
constexpr int kLocalRadius = 4;
constexpr int kLocalSweeps = 2;
// A C-grid's trailing edge (the ends of the wake cut) gets a larger, longer
// round on top: there the Winslow grid fans out from the airfoil's fine
// spacing to the wake's (NACA0012 C-grid 1025x257: first wake cell 0.45
// chord against 0.004 on the airfoil), and the error gathers in that fan.
// Measured on bench naca0012-c 65..1025 (with the lines through the cut):
// without it 6 cycles at 0.06-0.08 up to 513, then 12 at 0.24 at 1025;
// radius 8 and 8 sweeps 5-7 cycles at 0.04-0.08; 4 sweeps 7 at 0.09 at
// 1025, radius 4 or 2 sweeps worse. Cost: two 17x17 boxes per smoothing.
constexpr int kTrailingEdgeRadius = 8;
constexpr int kTrailingEdgeSweeps = 8;
constexpr int kCoarseSweepCap = 50;
}  // namespace

// The smoother, per topology. A single block gets the alternating ILU sweeps
// (multigrid_ilu.hpp). Measured, the worst W(2,1) per-cycle residual ratio
// down to 1e-10 at 65^2..1025^2 (the monitor's residuals): swan 0.09-0.18
// with the line smoother, 0.002-0.006 with ILU; dome 0.09-0.29 with lines,
// 0.008-0.086 with ILU. An ILU sweep pair costs about twice a line sweep
// pair (WU per cycle 17-22 -> 25-36); fewer cycles make up for it (swan
// 1025^2: 5 cycles, 1.41 CPU s -> 2 cycles, 0.92 s). O- and C-grids keep the
// line smoother (a coarse C-grid level whose cut coarsened away is a single
// block and gets ILU): ILU leaves the couplings across the branch cut or the wake
// cut out of its factors, and there it was worse (257^2: annulus 0.019 ->
// 0.069, NACA0012 O-grid 0.035 -> 0.082 per cycle; the C-grid unchanged at 0.16).
static bool single_block(const Connectivity &c) { return !c.periodic_i() && c.extra_unknowns().empty(); }

void smooth(System system, MgLevel &m, int sweeps, bool reverse) {
    const double omega = kSmootherOmega;
    for (int s = 0; s < sweeps && system == System::Variational; ++s) m.refused += variational_sweeps(m.level);
    for (int s = 0; s < sweeps && system != System::Variational; ++s) {
        if (single_block(m.conn)) {
            ilu_sweep(system, m.level, false, 1.0, m.ilu);
            ilu_sweep(system, m.level, true, 1.0, m.ilu);
        } else if (!reverse) {
            sweep_xi_lines(system, m.level, omega, m.work, LineOrder::Forward);
            sweep_eta_lines(system, m.level, omega, m.work, LineOrder::Zebra);
        } else {
            sweep_eta_lines(system, m.level, omega, m.work, LineOrder::Zebra);
            sweep_xi_lines(system, m.level, omega, m.work, LineOrder::Backward);
        }
        relax_extra_unknowns(system, m.level, 1.0);
    }
    if (sweeps > 0) {
        relax_near(system, m.level, m.singular, kLocalRadius, kLocalSweeps);
        relax_near(system, m.level, m.trailing_edge, kTrailingEdgeRadius, kTrailingEdgeSweeps);
    }
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
        if (m.work.singular) {  // a ring left unsolved (line_relax.hpp): the best iterate stands
            m.work.singular = false;
            break;
        }
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
