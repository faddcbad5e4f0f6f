// Coarse-to-fine ("nested") iteration, after the main program of the
// Phoenix grid code with `interpol` and `nsub`: the equations are first
// converged on a coarse grid, the result is interpolated to the next finer
// grid, converged again, and so on up to the full grid; then plain point SOR
// sweeps continue on the full grid.
//
// One iteration is one point SOR sweep of the full grid; the first iteration
// after a new start (Problem::fresh_start) also does the whole coarse-to-fine
// phase. The coarse
// grids are the multigrid hierarchy's (multigrid_hierarchy.hpp: any size, the
// control fields sampled and rescaled to each level's index units), each
// swept with the relaxation setting (automatic: the optimal SOR factor of its
// size) until its residual is below max(tolerance, kCoarseTolerance). Each
// finer level takes the coarser one's change as a correction,
// u += P(u_c - I u), so a warm start keeps its fine detail. (Right after
// interpolation the max-norm residual is larger than a smooth start's, from
// the kinks of linear interpolation, though the error is smaller; so the
// residual cannot judge which start is better.) A start with more folded
// cells than the grid had is dropped.
#include <algorithm>
#include <cmath>
#include <vector>

#include "base/error.hpp"
#include "base/folds.hpp"
#include "base/grid_snapshot.hpp"
#include "solvers/auto_relaxation.hpp"
#include "solvers/multigrid_hierarchy.hpp"
#include "solvers/solver.hpp"

namespace eg2d {

namespace {
// A coarse level is converged to this residual at most: below it the
// interpolation error of the next level dominates anyway.
constexpr double kCoarseTolerance = 1e-7;

// Nested coarsens down to 3 nodes a direction: every coarse solve is cheap.
constexpr int kCoarsestNodes = 3;

class Nested final : public Solver {
public:
    void reset() override {
        started_ = false;
        relaxation_.reset();
    }

    void iterate(Problem &p) override {
        const Level L = p.level();
        // Not on a start that is no new start (a held wall layer, a graded
        // layer's kept lines, which the coarse levels' controls would undo:
        // a pipe 257x129 took 4720 sweeps back to its exact start), as
        // multigrid's FMG.
        if (!started_ && p.fresh_start) coarse_to_fine(p);
        started_ = true;
        guarded_sweep(p.system, L, p.settings, relaxation_);
    }

private:
    void coarse_to_fine(Problem &p) {
        const Level fine = p.level();
        std::vector<MgLevel> levels = build_hierarchy(*fine.conn, p.system, kCoarsestNodes);
        if (p.report) p.report->levels = p.report->levels_built = static_cast<int>(levels.size());
        if (levels.size() < 2) return;
        const double extent = p.grid.extent();
        GridSnapshot start;
        start.take(p.grid);
        const long folded_before = fold_summary(p.grid).folded;
        const double target = std::max(p.settings.tolerance, kCoarseTolerance);
        levels[0].level = fine;
        levels[0].level.conn = &levels[0].conn;
        attach_functional(levels, fine.functional);
        for (std::size_t l = 1; l < levels.size(); ++l) {
            MgLevel &c = levels[l];
            const MgLevel &f = levels[l - 1];
            inject(f.conn, f.level.x, c, c.x0.data());
            inject(f.conn, f.level.y, c, c.y0.data());
            c.x = c.x0;
            c.y = c.y0;
            c.level.x = c.x.data();
            c.level.y = c.y.data();
            c.level.fx = c.level.fy = nullptr;  // the plain equations on every level
            restrict_controls(f.level.controls, f.conn, c);
        }
        converge(p.system, levels.back().level, extent, target, p.settings);
        for (std::size_t l = levels.size() - 1; l > 0; --l) {
            prolong_correction(levels[l], levels[l - 1].level);
            if (l > 1) converge(p.system, levels[l - 1].level, extent, target, p.settings);
        }
        // A coarse grid can misrepresent strong control terms (an attraction
        // that decays within a few fine lines) and fold; such a start is
        // worse than none.
        const long folded = fold_summary(p.grid).folded;
        if (folded > folded_before) {
            p.note(format("nested: the coarse-to-fine start folded %ld cells (the start had %ld); it is dropped "
                          "and point SOR goes on from the start", folded, folded_before));
            start.restore(p.grid);
        }
    }

    // Point SOR sweeps on a coarse level until its residual is below target,
    // the sweeps stop helping, or a cap proportional to its size (50 sweeps
    // per node of the longer side, Petrilli's (1989) coarse levels need far fewer:
    // a safety bound, 8a304e2, not tuned).
    static void converge(System system, const Level &L, double extent, double target, const Settings &settings) {
        const int cap = 50 * std::max(L.conn->ni(), L.conn->nj()) + 100;
        AutoRelaxation relaxation;
        double best = residual(system, L, extent).value;
        for (int k = 0; k < cap && best > target; ++k) {
            guarded_sweep(system, L, settings, relaxation);
            const double r = residual(system, L, extent).value;
            // The run's own divergence test (EG2D_PARAM_DIVERGENCE_FACTOR); the fine
            // grid's run loop reports it.
            if (!std::isfinite(r) || r > settings.divergence_factor * best) return;
            best = std::min(best, r);
        }
    }

    // A point SOR sweep at the user's factor, or the automatic one with no
    // ramp: every level starts from the converged coarser one. Its target is
    // the elliptic-grid course notes' optimum but at most kLimit: the error left by the coarser
    // level is not the model's slowest mode, and more over-relaxation only
    // slows it (bench, swan/valley: 402/518 sweeps at 257^2, 503/493 at
    // 513^2 with the limit; 774/732 and 1040+/1083+ (capped) at the
    // optimum; 424/585 and 775/816 at the optimum of a grid half as fine).
    static void guarded_sweep(System system, const Level &L, const Settings &settings, AutoRelaxation &relaxation) {
        constexpr double kLimit = 1.95;
        if (settings.relaxation > 0.0) return sor_sweep(system, L, settings.relaxation);
        const double target = std::min(kLimit, optimal_sor_omega(L.conn->ni(), L.conn->nj()));
        relaxation.sweep(L, 0, [&] { sor_sweep(system, L, relaxation.omega(target)); });
    }

    bool started_ = false;
    AutoRelaxation relaxation_;
};

}  // namespace

std::unique_ptr<Solver> make_nested() { return std::make_unique<Nested>(); }

}  // namespace eg2d
