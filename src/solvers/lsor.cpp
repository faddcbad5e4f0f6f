// Line SOR: a sweep of xi-lines then a sweep of eta-lines (line_relax.hpp),
// each over-relaxed; nodes off the line rectangle (a C-grid cut) get a point
// update. Seed 004 compares it with point SOR and AF (its Table 2).
//
// Automatic relaxation (settings.relaxation = 0): each direction gets the
// optimal line-SOR factor of the Laplace model problem on the grid's size,
// reached from omega = 1 over the first max(ni, nj) sweeps after a new start
// (automatic_line_sor_omega says why). Omega = 1 throughout costs 4-13x more
// sweeps on the seed 003 domains at 33^2..129^2.
#include "solvers/line_relax.hpp"
#include "solvers/solver.hpp"

namespace eg2d {

namespace {

class LineSor final : public Solver {
public:
    void iterate(Problem &p) override {
        const Level L = p.level();
        LineOmega omega{p.settings.relaxation, p.settings.relaxation};
        if (!(p.settings.relaxation > 0.0)) omega = automatic_line_sor_omega(*L.conn, sweeps_);
        ++sweeps_;
        sweep_xi_lines(p.system, L, omega.xi, work_);
        sweep_eta_lines(p.system, L, omega.eta, work_);
        relax_extra_unknowns(p.system, L, 0.5 * (omega.xi + omega.eta));
    }
    void reset() override {
        work_ = LineWork{};
        sweeps_ = 0;
    }

private:
    LineWork work_;
    long sweeps_ = 0;  // since the last reset: drives the automatic factor's ramp
};

}  // namespace

std::unique_ptr<Solver> make_lsor() { return std::make_unique<LineSor>(); }

}  // namespace eg2d
