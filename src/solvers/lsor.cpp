// Line SOR: a sweep of xi-lines then a sweep of eta-lines (line_relax.hpp),
// each over-relaxed; nodes off the line rectangle (a C-grid cut) get a point
// update. Ly & Norrison (2007) compares it with point SOR and AF (its Table 2).
//
// Automatic relaxation (settings.relaxation = 0): each direction's target is
// the optimal line-SOR factor of the Laplace model problem on the grid's size
// (optimal_line_sor_omega), reached by auto_relaxation.hpp's ramp and backed
// off by its guards where the grid's own equations do not bear it. The model
// optimum is exact for Laplace but not for Winslow on skewed or stretched
// cells: at fixed omega the NACA0012 O-grid (257x65) diverges from 1.8 up and
// converges at 1.7; with the ramp and the guards it backs off once (sweep
// 186) and converges in 1046 sweeps (866 at fixed 1.7). Omega = 1 throughout
// costs 4-13x more sweeps on the elliptic-grid course notes domains at 33^2..129^2.
#include <algorithm>

#include "solvers/auto_relaxation.hpp"
#include "solvers/line_relax.hpp"
#include "solvers/solver.hpp"

namespace eg2d {

namespace {

class LineSor final : public Solver {
public:
    void iterate(Problem &p) override {
        const Level L = p.level();
        work_.limit_ring_steps = !p.dynamic_controls;
        const double given = p.settings.relaxation;
        if (given > 0.0) return sweep(p.system, L, LineOmega{given, given});
        const LineOmega target = optimal_line_sor_omega(*L.conn);
        const long ramp = AutoRelaxation::ramp_for(std::max(target.xi, target.eta));
        relaxation_.sweep(L, ramp, [&] {
            sweep(p.system, L, LineOmega{relaxation_.omega(target.xi), relaxation_.omega(target.eta)});
        });
    }
    void reset() override {
        work_ = LineWork{};
        relaxation_.reset();
    }

private:
    void sweep(System system, const Level &L, LineOmega omega) {
        sweep_xi_lines(system, L, omega.xi, work_);
        sweep_eta_lines(system, L, omega.eta, work_);
        relax_extra_unknowns(system, L, 0.5 * (omega.xi + omega.eta));
    }

    LineWork work_;
    AutoRelaxation relaxation_;
};

}  // namespace

std::unique_ptr<Solver> make_lsor() { return std::make_unique<LineSor>(); }

}  // namespace eg2d
