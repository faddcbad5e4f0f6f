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
#include "solvers/auto_relaxation.hpp"

namespace eg2d {

namespace {

// SOR's factor for the model problem on the set (Young 1971): 2/(1 + sin(pi h))
// with h one over the longest chain of nodes across the set, bounded by the
// nodes' count (a chain of blocks is as long as their sum).
double automatic_omega(const BlockSet &set) {
    double nodes = 0.0, longest = 0.0;
    for (int b = 0; b < set.size(); ++b) {
        const Grid &g = set.block(b)->grid();
        nodes += static_cast<double>(g.ni()) * g.nj();
        longest = std::max(longest, static_cast<double>(std::max(g.ni(), g.nj())));
    }
    const double n = std::max(longest, std::sqrt(nodes));
    return 2.0 / (1.0 + std::sin(M_PI / n));
}

void write_back(const BlockSet &set, const Composite &c, long iterations) {
    std::vector<std::vector<double>> xs(static_cast<std::size_t>(set.size())), ys(xs.size());
    for (int b = 0; b < set.size(); ++b) c.extract(b, xs[static_cast<std::size_t>(b)], ys[static_cast<std::size_t>(b)]);
    for (int b = 0; b < set.size(); ++b)
        set.block(b)->take_solution(xs[static_cast<std::size_t>(b)], ys[static_cast<std::size_t>(b)],
                                    static_cast<int>(std::min<long>(iterations, 2147483647L)));
}

// Point SOR over the set. Automatic factor: the point solvers' guarded ramp
// (solvers/auto_relaxation.hpp) from Gauss-Seidel to the target over its
// ramp, a sweep that moves the grid more than kJump times the last one
// undone and redone with half the over-relaxation: a fixed factor near 2
// blows up on a TFI start (the 49x161 step diverged).
class SetSor {
public:
    SetSor(const Settings &s, const BlockSet &set)
        : automatic_(!(s.relaxation > 0.0)), target_(automatic_ ? automatic_omega(set) : s.relaxation),
          ramp_(automatic_ ? AutoRelaxation::ramp_for(target_) : 0) {}
    void iterate(System system, Composite &c) {
        c.save();
        c.sweep(system, factor());
        double m = c.move();
        if (automatic_ && !(m <= kJump * last_move_) && sweeps_ > 0) {
            c.restore();
            share_ *= 0.5;
            c.sweep(system, factor());
            m = c.move();
        }
        last_move_ = m;
        ++sweeps_;
    }
    double factor() const {
        if (!automatic_) return target_;
        const double r = ramp_ > 0 ? std::min(1.0, static_cast<double>(sweeps_ + 1) / static_cast<double>(ramp_)) : 1.0;
        return 1.0 + share_ * r * (target_ - 1.0);
    }

private:
    static constexpr double kJump = 3.0;
    bool automatic_;
    double target_;
    long ramp_, sweeps_ = 0;
    double share_ = 1.0, last_move_ = std::numeric_limits<double>::infinity();
};

}  // namespace

void solve_set(BlockSet &set, const std::function<bool(long, double)> &monitor, SetRun &run) {
    set.check();
    const Settings &s = set.block(0)->settings;
    const int solver = set.block(0)->solver_id();
    if (solver != EG2D_SOLVER_MULTIGRID && solver != EG2D_SOLVER_PSOR)
        fail(Failure::Unsupported, format("block 0's solver is %s: a set of blocks is solved by multigrid or point SOR "
                                          "(EG2D_SOLVER_MULTIGRID, EG2D_SOLVER_PSOR) in this version",
                                          set.block(0)->solver_name()));
    for (int b = 0; b < set.size(); ++b)
        if (!set.block(b)->grid().initialized()) set.block(b)->initialize(EG2D_INIT_TFI);
    const System system = set.block(0)->system();
    Composite c = Composite::of(set);
    run = SetRun{};
    run.unknowns = c.unknowns();
    const bool multigrid = solver == EG2D_SOLVER_MULTIGRID;
    SetSor sor(s, set);
    std::vector<SetMultigrid> mg;  // built only for multigrid
    if (multigrid) mg.emplace_back(c);
    run.omega = multigrid ? 1.0 : sor.factor();
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
            write_back(set, c, run.iterations);
            fail(Failure::NotConverged, format("the set reached the iteration limit (%ld) at residual %.3g (tolerance %.3g)",
                                               limit, run.residual, s.tolerance));
        }
        if (multigrid && run.iterations == 0 && s.mg_fmg != 0.0)
            mg[0].fmg(system, c, static_cast<int>(s.mg_cycle), static_cast<int>(s.mg_pre_smooth),
                      static_cast<int>(s.mg_post_smooth));
        else if (multigrid)
            mg[0].cycle(system, c, static_cast<int>(s.mg_cycle), static_cast<int>(s.mg_pre_smooth),
                        static_cast<int>(s.mg_post_smooth));
        else
            sor.iterate(system, c);
        ++run.iterations;
        run.residual = c.residual(system, extent);
        if (!std::isfinite(run.residual) || !c.finite() ||
            (run.residual > s.divergence_factor * best && run.residual > 1e-2))  // the generator's floor
            fail(Failure::Diverged, format("the set diverged at iteration %ld (residual %.3g, best %.3g; %s): the "
                                           "blocks are unchanged", run.iterations, run.residual, best,
                                           multigrid ? "multigrid" : format("SOR factor %.4g", sor.factor()).c_str()));
        best = std::min(best, run.residual);
        if (watch.stalled(run.iterations, run.residual, 0.0)) {
            write_back(set, c, run.iterations);
            fail(Failure::NotConverged, format("the set made no progress in %ld iterations (residual %.3g, best %.3g, "
                                               "tolerance %.3g)", watch.window(), run.residual,
                                               watch.best_residual(), s.tolerance));
        }
        if (monitor && monitor(run.iterations, run.residual)) {
            write_back(set, c, run.iterations);
            fail(Failure::Interrupted, format("the monitor stopped the set's run at iteration %ld", run.iterations));
        }
    }
    write_back(set, c, run.iterations);
    run.levels = multigrid ? mg[0].levels() : 1;
    run.note = multigrid ? format("set of %d blocks: %ld unknowns, multigrid on %d level(s), %ld cycle(s), residual %.3g",
                                  set.size(), run.unknowns, run.levels, run.iterations, run.residual)
                         : format("set of %d blocks: %ld unknowns, point SOR (factor %.4g), %ld iterations, residual %.3g",
                                  set.size(), run.unknowns, sor.factor(), run.iterations, run.residual);
}

}  // namespace eg2d
