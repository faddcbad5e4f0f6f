#include "blocks/set_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "base/error.hpp"
#include "blocks/composite.hpp"
#include "blocks/set_multigrid.hpp"
#include "eg2d.h"
#include "generator/generator.hpp"
#include "generator/stall_watch.hpp"
#include "solvers/run_report.hpp"
#include "solvers/auto_relaxation.hpp"

namespace eg2d {

namespace {

// Point SOR's factor for the model problem on the set (Young 1971): 2/(1 +
// sin(pi h)) with h one over the longest chain of nodes across the set,
// bounded by the nodes' count (a chain of blocks is as long as their sum).
double point_omega(const Composite &c) {
    const double n = std::max(static_cast<double>(c.longest()), std::sqrt(static_cast<double>(c.nodes())));
    return 2.0 / (1.0 + std::sin(M_PI / n));
}

void write_back(const BlockSet &set, const Composite &c, long iterations, RunReport &report) {
    std::vector<std::vector<double>> xs(static_cast<std::size_t>(set.size())), ys(xs.size());
    for (int b = 0; b < set.size(); ++b) c.extract(b, xs[static_cast<std::size_t>(b)], ys[static_cast<std::size_t>(b)]);
    report.iteration = static_cast<int>(std::min<long>(iterations, 2147483647L));
    for (int b = 0; b < set.size(); ++b)
        set.block(b)->take_solution(xs[static_cast<std::size_t>(b)], ys[static_cast<std::size_t>(b)], report.iteration,
                                    report);
}

// Point or line SOR over the set. Automatic factor: the point solvers'
// guarded ramp (solvers/auto_relaxation.hpp) from Gauss-Seidel to the
// target over its ramp, a sweep that moves the grid more than kJump times
// the last one undone and redone with half the over-relaxation: a fixed
// factor near 2 blows up on a TFI start (the 49x161 step diverged).
class SetSor {
public:
    SetSor(const Settings &s, const Composite &c, bool lines) : lines_(lines), automatic_(!(s.relaxation > 0.0)) {
        if (!automatic_) target_ = LineOmega{s.relaxation, s.relaxation};
        else if (lines) target_ = c.line_omega();
        else target_ = LineOmega{point_omega(c), point_omega(c)};
        ramp_ = automatic_ ? AutoRelaxation::ramp_for(std::max(target_.xi, target_.eta)) : 0;
    }
    void iterate(System system, Composite &c) {
        c.save();
        sweep(system, c);
        double m = c.move();
        if (automatic_ && !(m <= kJump * last_move_) && sweeps_ > 0) {
            c.restore();
            share_ *= 0.5;
            sweep(system, c);
            m = c.move();
        }
        last_move_ = m;
        ++sweeps_;
    }
    double factor(double target) const {
        if (!automatic_) return target;
        const double r = ramp_ > 0 ? std::min(1.0, static_cast<double>(sweeps_ + 1) / static_cast<double>(ramp_)) : 1.0;
        return 1.0 + share_ * r * (target - 1.0);
    }
    double factor() const { return factor(target_.xi); }

private:
    void sweep(System system, Composite &c) {
        if (lines_) c.sweep_lines(system, factor(target_.xi), factor(target_.eta));
        else c.sweep(system, factor(target_.xi));
    }
    static constexpr double kJump = 3.0;
    bool lines_, automatic_;
    LineOmega target_{1.0, 1.0};
    long ramp_ = 0, sweeps_ = 0;
    double share_ = 1.0, last_move_ = std::numeric_limits<double>::infinity();
};

// The nested iteration's coarse levels are converged to this at most:
// below it the next level's interpolation error dominates (solvers/nested.cpp).
constexpr double kCoarseTolerance = 1e-7;
constexpr long kCoarseSweeps = 5000;

}  // namespace

void solve_set(BlockSet &set, const std::function<bool(long, double)> &monitor, SetRun &run) {
    set.check();
    const Settings &s = set.block(0)->settings;
    const int solver = set.block(0)->solver_id();
    if (solver != EG2D_SOLVER_MULTIGRID && solver != EG2D_SOLVER_PSOR && solver != EG2D_SOLVER_LSOR &&
        solver != EG2D_SOLVER_NESTED)
        fail(Failure::Unsupported, format("block 0's solver is \"%s\": a set of blocks is solved by multigrid, point SOR, "
                                          "line SOR or the nested iteration (EG2D_SOLVER_MULTIGRID, _PSOR, _LSOR, "
                                          "_NESTED) in this version", set.block(0)->solver_name()));
    for (int b = 0; b < set.size(); ++b)
        if (!set.block(b)->grid().initialized()) set.block(b)->initialize(EG2D_INIT_TFI);
    const System system = set.block(0)->system();
    Composite c = Composite::of(set);
    run = SetRun{};
    run.unknowns = c.unknowns();
    const bool multigrid = solver == EG2D_SOLVER_MULTIGRID, nested = solver == EG2D_SOLVER_NESTED;
    SetSor sor(s, c, solver == EG2D_SOLVER_LSOR);
    std::vector<SetMultigrid> mg;  // the levels: multigrid's and the nested iteration's
    if (multigrid || nested) mg.emplace_back(c);
    run.omega = multigrid ? 1.0 : sor.factor();
    // What the set's run is, on every block's eg2d_get_run_info and _event.
    RunReport report;
    report.solver = solver;
    report.levels = report.levels_built = mg.empty() ? 1 : mg[0].levels();
    report.iteration = 1;
    report.note(format("set of %d blocks solved as one grid: %ld unknowns, %d inner vertex(es) at their neighbours' "
                       "mean, %d vertex(es) on the boundary held; %s on %d level(s)", set.size(), run.unknowns,
                       c.free_vertices(), c.held_vertices(), set.block(0)->solver_name(), report.levels));
    if (!mg.empty() && !mg[0].stopped().empty())
        report.note(format("%s: no coarser level below %d: %s%s", set.block(0)->solver_name(), report.levels,
                           mg[0].stopped().c_str(),
                           report.levels == 1 ? "; the smoother alone converges slowly" : ""));
    const double extent = set.extent();
    const long limit = static_cast<long>(s.max_iterations);
    long window = static_cast<long>(s.stall_iterations);
    if (window == 0) {  // the single-block solvers' windows (Solver::stall_window)
        int longest = 0;
        for (int b = 0; b < set.size(); ++b)
            longest = std::max({longest, set.block(b)->grid().ni(), set.block(b)->grid().nj()});
        window = multigrid ? 200L
                           : std::max(500L, 2L * static_cast<long>(std::sqrt(static_cast<double>(run.unknowns)) + longest));
    }
    StallWatch watch(window);
    run.residual = c.residual(system, extent);
    double best = run.residual;
    while (run.residual > s.tolerance) {
        if (run.iterations >= limit) {
            write_back(set, c, run.iterations, report);
            fail(Failure::NotConverged, format("the set reached the iteration limit (%ld) at residual %.3g (tolerance %.3g)",
                                               limit, run.residual, s.tolerance));
        }
        if (multigrid && run.iterations == 0 && s.mg_fmg != 0.0)
            mg[0].fmg(system, c, static_cast<int>(s.mg_cycle), static_cast<int>(s.mg_pre_smooth),
                      static_cast<int>(s.mg_post_smooth));
        else if (multigrid)
            mg[0].cycle(system, c, static_cast<int>(s.mg_cycle), static_cast<int>(s.mg_pre_smooth),
                        static_cast<int>(s.mg_post_smooth));
        else {
            if (nested && run.iterations == 0)
                mg[0].coarse_to_fine(c, [&](Composite &level) {
                    SetSor level_sor(s, level, false);
                    StallWatch level_watch(window);
                    const double goal = std::max(s.tolerance, kCoarseTolerance);
                    double r = level.residual(system, extent);
                    for (long k = 0; k < kCoarseSweeps && r > goal && !level_watch.stalled(k, r, 0.0); ++k) {
                        level_sor.iterate(system, level);
                        r = level.residual(system, extent);
                        if (!std::isfinite(r)) break;
                    }
                });
            sor.iterate(system, c);
        }
        ++run.iterations;
        run.residual = c.residual(system, extent);
        if (!std::isfinite(run.residual) || !c.finite() ||
            (run.residual > s.divergence_factor * best && run.residual > 1e-2))  // the generator's floor
            fail(Failure::Diverged, format("the set diverged at iteration %ld (residual %.3g, best %.3g; %s): the "
                                           "blocks are unchanged", run.iterations, run.residual, best,
                                           multigrid ? "multigrid" : format("SOR factor %.4g", sor.factor()).c_str()));
        best = std::min(best, run.residual);
        if (watch.stalled(run.iterations, run.residual, 0.0)) {
            write_back(set, c, run.iterations, report);
            fail(Failure::NotConverged, format("the set made no progress in %ld iterations (residual %.3g, best %.3g, "
                                               "tolerance %.3g)", watch.window(), run.residual,
                                               watch.best_residual(), s.tolerance));
        }
        if (monitor && monitor(run.iterations, run.residual)) {
            write_back(set, c, run.iterations, report);
            fail(Failure::Interrupted, format("the monitor stopped the set's run at iteration %ld", run.iterations));
        }
    }
    write_back(set, c, run.iterations, report);
    run.levels = mg.empty() ? 1 : mg[0].levels();
    run.note = format("set of %d blocks: %ld unknowns, %s on %d level(s), %ld iteration(s), residual %.3g", set.size(),
                      run.unknowns, set.block(0)->solver_name(), run.levels, run.iterations, run.residual);
}

}  // namespace eg2d
