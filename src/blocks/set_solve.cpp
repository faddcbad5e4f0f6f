#include "blocks/set_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "base/error.hpp"
#include "eg2d.h"
#include "blocks/composite.hpp"
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

}  // namespace

void solve_set(BlockSet &set, const std::function<bool(long, double)> &monitor, SetRun &run) {
    set.check();
    for (int b = 0; b < set.size(); ++b)
        if (!set.block(b)->grid().initialized()) set.block(b)->initialize(EG2D_INIT_TFI);
    const Settings &s = set.block(0)->settings;
    const System system = set.block(0)->system();
    Composite c(set);
    run = SetRun{};
    run.unknowns = c.unknowns();
    run.omega = s.relaxation > 0.0 ? s.relaxation : automatic_omega(set);
    const double extent = set.extent();
    const long limit = static_cast<long>(s.max_iterations);
    long window = static_cast<long>(s.stall_iterations);
    if (window == 0) {
        int longest = 0;
        for (int b = 0; b < set.size(); ++b)
            longest = std::max({longest, set.block(b)->grid().ni(), set.block(b)->grid().nj()});
        window = std::max(500L, 2L * static_cast<long>(std::sqrt(static_cast<double>(run.unknowns)) + longest));
    }
    StallWatch watch(window);
    // Automatic: the point solvers' guarded ramp (solvers/auto_relaxation.hpp)
    // from Gauss-Seidel to the target over its ramp, a sweep that moves the
    // grid more than kJump times the last one undone and redone with half
    // the over-relaxation: a fixed factor near 2 blows up on a TFI start.
    const bool automatic = !(s.relaxation > 0.0);
    const long ramp = automatic ? AutoRelaxation::ramp_for(run.omega) : 0;
    double share = 1.0, last_move = std::numeric_limits<double>::infinity();
    constexpr double kJump = 3.0;
    run.residual = c.residual(system, extent);
    double best = run.residual;
    while (run.residual > s.tolerance) {
        if (run.iterations >= limit) {
            write_back(set, c, run.iterations);
            fail(Failure::NotConverged, format("the set reached the iteration limit (%ld) at residual %.3g (tolerance %.3g)",
                                               limit, run.residual, s.tolerance));
        }
        auto factor = [&] {
            if (!automatic) return run.omega;
            const double r = ramp > 0 ? std::min(1.0, static_cast<double>(run.iterations + 1) / static_cast<double>(ramp)) : 1.0;
            return 1.0 + share * r * (run.omega - 1.0);
        };
        c.save();
        c.sweep(system, factor());
        double m = c.move();
        if (automatic && !(m <= kJump * last_move) && run.iterations > 0) {
            c.restore();
            share *= 0.5;
            c.sweep(system, factor());
            m = c.move();
        }
        last_move = m;
        ++run.iterations;
        run.residual = c.residual(system, extent);
        if (!std::isfinite(run.residual) || !c.finite() ||
            (run.residual > s.divergence_factor * best && run.residual > 1e-2))  // the generator's floor
            fail(Failure::Diverged, format("the set diverged at iteration %ld (residual %.3g, best %.3g; SOR factor "
                                           "%.4g): the blocks are unchanged; a smaller EG2D_PARAM_RELAXATION on "
                                           "block 0 may converge", run.iterations, run.residual, best, factor()));
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
    run.note = format("set of %d blocks: %ld unknowns, point SOR (factor %.4g), %ld iterations, residual %.3g",
                      set.size(), run.unknowns, run.omega, run.iterations, run.residual);
}

}  // namespace eg2d
