#include "blocks/set_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

#include "base/error.hpp"
#include "blocks/composite.hpp"
#include "blocks/set_multigrid.hpp"
#include "blocks/set_wall_layer.hpp"
#include "grid/graded_layer.hpp"
#include "solvers/multigrid_hierarchy.hpp"
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
// guarded ramp (solvers/auto_relaxation.hpp) on the set's coordinates: a
// fixed factor near 2 blows up on a TFI start (the 49x161 step diverged).
class SetSor {
public:
    SetSor(const Settings &s, const Composite &c, bool lines) : lines_(lines), automatic_(!(s.relaxation > 0.0)) {
        if (!automatic_) target_ = LineOmega{s.relaxation, s.relaxation};
        else if (lines) target_ = c.line_omega();
        else target_ = LineOmega{point_omega(c), point_omega(c)};
        ramp_ = automatic_ ? AutoRelaxation::ramp_for(std::max(target_.xi, target_.eta)) : 0;
    }
    void iterate(System system, Composite &c) {
        if (automatic_) auto_.sweep_guarded(c, ramp_, [&] { sweep(system, c); });
        else sweep(system, c);
    }
    double factor(double target) const { return automatic_ ? auto_.omega(target) : target; }
    double factor() const { return factor(target_.xi); }

private:
    void sweep(System system, Composite &c) {
        if (lines_) c.sweep_lines(system, factor(target_.xi), factor(target_.eta));
        else c.sweep(system, factor(target_.xi));
    }
    bool lines_, automatic_;
    LineOmega target_{1.0, 1.0};
    long ramp_ = 0;
    AutoRelaxation auto_;
};

// The wall layer's second pass re-spaces and turns the lines only while
// that skews no cell by this many degrees more than the first pass's grid.
constexpr double kReshapeSkew = 10.0;

// The nested iteration's coarse levels are converged to this at most:
// below it the next level's interpolation error dominates (solvers/nested.cpp).
constexpr double kCoarseTolerance = 1e-7;
constexpr long kCoarseSweeps = 5000;

// Iterates a composite to the tolerance with block 0's solver (one pass of
// the run; the wall layer's set is solved twice: set_wall_layer.hpp).
class SetPass {
public:
    SetPass(const BlockSet &set, const std::function<bool(long, double)> &monitor, SetRun &run, RunReport &report)
        : set_(set), s_(set.block(0)->settings), solver_(set.block(0)->solver_id()), system_(set.block(0)->system()),
          monitor_(monitor), run_(run), report_(report), extent_(set.extent()) {
        window_ = static_cast<long>(s_.stall_iterations);
        if (window_ == 0) window_ = multigrid() ? 200L : sor_window(run.unknowns);
    }
    bool multigrid() const { return solver_ == EG2D_SOLVER_MULTIGRID; }
    // Line SOR from here on, its stall window its own; use_own_solver goes
    // back to the set's.
    void use_line_sor(const Composite &c) {
        own_ = {solver_, window_};
        solver_ = EG2D_SOLVER_LSOR;
        if (s_.stall_iterations == 0) window_ = sor_window(c.unknowns());
        prepare(c);
    }
    void use_own_solver(const Composite &c) {
        std::tie(solver_, window_) = own_;
        prepare(c);
    }

    // The levels of this composite (built from its controls as they are now).
    void prepare(const Composite &c) {
        mg_.clear();
        if (multigrid() || solver_ == EG2D_SOLVER_NESTED) mg_.emplace_back(c);
        sor_ = std::make_unique<SetSor>(s_, c, solver_ == EG2D_SOLVER_LSOR);
    }
    int levels() const { return mg_.empty() ? 1 : mg_[0].levels(); }
    const std::string &stopped() const {
        static const std::string none;
        return mg_.empty() ? none : mg_[0].stopped();
    }
    double omega() const { return multigrid() ? 1.0 : sor_->factor(); }
    long clipped() const { return mg_.empty() ? 0 : mg_[0].clipped(); }

    // To `goal` (block 0's tolerance when 0).
    void converge(Composite &c, double goal = 0.0) {
        if (!(goal > s_.tolerance)) goal = s_.tolerance;
        const bool nested = solver_ == EG2D_SOLVER_NESTED;
        const long limit = static_cast<long>(s_.max_iterations);
        StallWatch watch(window_);
        const long first = run_.iterations;
        run_.residual = c.residual(system_, extent_);
        double best = run_.residual;
        while (run_.residual > goal) {
            if (run_.iterations >= limit) {
                write_back(set_, c, run_.iterations, report_);
                fail(Failure::NotConverged, format("the set reached the iteration limit (%ld) at residual %.3g "
                                                   "(tolerance %.3g)", limit, run_.residual, s_.tolerance));
            }
            if (multigrid() && run_.iterations == 0 && s_.mg_fmg != 0.0)  // a cold start only
                full_multigrid(c);
            else if (multigrid())
                mg_[0].cycle(system_, c, static_cast<int>(s_.mg_cycle), static_cast<int>(s_.mg_pre_smooth),
                             static_cast<int>(s_.mg_post_smooth));
            else {
                if (nested && run_.iterations == first)
                    mg_[0].coarse_to_fine(c, [&](Composite &level) {
                        SetSor level_sor(s_, level, false);
                        StallWatch level_watch(window_);
                        const double level_goal = std::max(s_.tolerance, kCoarseTolerance);
                        double r = level.residual(system_, extent_);
                        for (long k = 0; k < kCoarseSweeps && r > level_goal && !level_watch.stalled(k, r, 0.0); ++k) {
                            level_sor.iterate(system_, level);
                            r = level.residual(system_, extent_);
                            if (!std::isfinite(r)) break;
                        }
                    });
                sor_->iterate(system_, c);
            }
            ++run_.iterations;
            report_.iteration = static_cast<int>(std::min<long>(run_.iterations, 2147483647L));  // the notes' stamp
            run_.residual = c.residual(system_, extent_);
            if (!std::isfinite(run_.residual) || !c.finite() ||
                (run_.residual > s_.divergence_factor * best && run_.residual > 1e-2))  // the generator's floor
                fail(Failure::Diverged, format("the set diverged at iteration %ld (residual %.3g, best %.3g; %s): the "
                                               "blocks are unchanged", run_.iterations, run_.residual, best,
                                               multigrid() ? "multigrid" : format("SOR factor %.4g", sor_->factor()).c_str()));
            best = std::min(best, run_.residual);
            if (watch.stalled(run_.iterations - first, run_.residual, 0.0)) {
                write_back(set_, c, run_.iterations, report_);
                fail(Failure::NotConverged, format("the set made no progress in %ld iterations (residual %.3g, best "
                                                   "%.3g, tolerance %.3g)", watch.window(), run_.residual,
                                                   watch.best_residual(), s_.tolerance));
            }
            if (monitor_ && monitor_(run_.iterations, run_.residual)) {
                write_back(set_, c, run_.iterations, report_);
                fail(Failure::Interrupted, format("the monitor stopped the set's run at iteration %ld", run_.iterations));
            }
        }
    }

private:
    // The single-block SOR solvers' stall window (Solver::stall_window).
    long sor_window(long unknowns) const {
        int longest = 0;
        for (int b = 0; b < set_.size(); ++b)
            longest = std::max({longest, set_.block(b)->grid().ni(), set_.block(b)->grid().nj()});
        return std::max(500L, 2L * static_cast<long>(std::sqrt(static_cast<double>(unknowns)) + longest));
    }

    // FMG, unless it leaves a start near its solution worse: a tensor set
    // re-spaced for walls of 1e-5 (its start off the solution by 1e-6) came
    // back from the coarse levels at residual 0.2, and the run stopped as
    // diverged. Then a V-cycle from the start instead, said.
    void full_multigrid(Composite &c) {
        const int cycle = static_cast<int>(s_.mg_cycle), pre = static_cast<int>(s_.mg_pre_smooth),
                  post = static_cast<int>(s_.mg_post_smooth);
        const Composite::Snapshot start = c.snapshot();
        mg_[0].fmg(system_, c, cycle, pre, post);
        const double after = c.residual(system_, extent_);
        if (after <= run_.residual) return;
        c.restore(start);
        report_.note(format("multigrid: its full multigrid start would raise the set's residual from %.3g to %.3g "
                            "(a start near its solution); V-cycles from the start instead", run_.residual, after));
        mg_[0].cycle(system_, c, cycle, pre, post);
    }

    const BlockSet &set_;
    const Settings &s_;
    int solver_;
    System system_;
    const std::function<bool(long, double)> &monitor_;
    SetRun &run_;
    RunReport &report_;
    double extent_;
    long window_ = 0;
    std::pair<int, long> own_{0, 0};
    std::vector<SetMultigrid> mg_;  // the levels: multigrid's and the nested iteration's
    std::unique_ptr<SetSor> sor_;
};

}  // namespace

void solve_set(BlockSet &set, const std::function<bool(long, double)> &monitor, SetRun &run) {
    set.check();
    const int solver = set.block(0)->solver_id();
    if (solver != EG2D_SOLVER_MULTIGRID && solver != EG2D_SOLVER_PSOR && solver != EG2D_SOLVER_LSOR &&
        solver != EG2D_SOLVER_NESTED)
        fail(Failure::Unsupported, format("block 0's solver is \"%s\": a set of blocks is solved by multigrid, point SOR, "
                                          "line SOR or the nested iteration (EG2D_SOLVER_MULTIGRID, _PSOR, _LSOR, "
                                          "_NESTED) in this version", set.block(0)->solver_name()));
    // A block's own wall layer (its start re-spaced and its sides moved on
    // their own) is not the set's: with walls, the blocks start from TFI.
    // A block started again alone has its joined nodes back on its sides
    // while its neighbours keep theirs where the last solve put them: the
    // whole set starts from TFI then.
    const bool walls = SetWallLayer::asks_walls(set);
    bool fresh = !set.grids_agree();
    for (int b = 0; b < set.size(); ++b) fresh = fresh || !set.block(b)->grid().initialized();
    for (int b = 0; b < set.size(); ++b) {
        Generator &g = *set.block(b);
        const WallLayerShape &own = g.layer();
        if (fresh || (walls && (own.graded || own.hybrid || own.rows > 0 || own.moved_sides)))
            g.initialize(EG2D_INIT_TFI, !walls);
    }
    const System system = set.block(0)->system();
    Composite c = Composite::of(set);
    const SetWallLayer layer(set, c);
    bool made = !layer.empty();  // the layer's passes ran (made false by a fallback)
    run = SetRun{};
    run.unknowns = c.unknowns();
    // What the set's run is, on every block's eg2d_get_run_info and _event.
    RunReport report;
    report.solver = solver;
    report.iteration = 1;
    SetPass pass(set, monitor, run, report);
    pass.prepare(c);
    run.omega = pass.omega();
    report.levels = report.levels_built = pass.levels();
    report.note(format("set of %d blocks solved as one grid: %ld unknowns, %d inner vertex(es) at their neighbours' "
                       "mean, %d vertex(es) on the boundary held; %s on %d level(s)", set.size(), run.unknowns,
                       c.free_vertices(), c.held_vertices(), set.block(0)->solver_name(), report.levels));
    if (!pass.stopped().empty())
        report.note(format("%s: no coarser level below %d: %s%s", set.block(0)->solver_name(), report.levels,
                           pass.stopped().c_str(), report.levels == 1 ? "; the smoother alone converges slowly" : ""));
    if (!layer.empty()) {
        // A folded start (TFI over a bump) is solved as it is first: its
        // lines cannot be re-spaced (the single block's untangling,
        // Generator::shape_start).
        const long folded = c.folded_cells();
        if (folded > 0) {
            pass.converge(c, kShapeTolerance);
            report.note(format("wall layer (graded, set of blocks): the blocks' start has %ld folded cell(s); the "
                               "layer is made on the set's grid without its controls (%ld iteration(s))", folded,
                               run.iterations));
        }
        const std::string sides = layer.kept_sides(c);
        if (!sides.empty()) report.note(sides);
        const Composite::Snapshot start = c.snapshot();
        const long before = run.iterations;
        layer.respace(c, true);
        c.hold_spacing(system, false);
        pass.prepare(c);
        // Only the shape of the lines is taken from this pass (to the
        // single block's kShapeTolerance): the second holds the grid it
        // leaves exactly. Where it diverges (boundary sides far from the
        // walls' heights shear the lines beside them) the set is solved
        // without the layer, said.
        bool by_lines = false;  // line SOR after multigrid diverged
        try {
            try {
                pass.converge(c, kShapeTolerance);
            } catch (const Error &e) {
                // Multigrid's coarse levels cannot always carry the lines'
                // controls (the two-element airfoil's, its wakes and slot
                // held: diverged in 3 cycles); line SOR then, said.
                if (e.failure() != Failure::Diverged || !pass.multigrid()) throw;
                const double residual = run.residual;
                c.restore(start);
                pass.use_line_sor(c);
                by_lines = true;
                report.note(format("wall layer (graded, set of blocks): on its lines' controls multigrid diverged in "
                                   "%ld iteration(s) (residual %.3g); the layer is made by line SOR instead",
                                   run.iterations - before, residual));
                pass.converge(c, kShapeTolerance);
            }
        } catch (const Error &e) {
            const bool diverged = e.failure() == Failure::Diverged;
            if (!diverged && !(by_lines && e.failure() == Failure::NotConverged)) throw;
            c.restore(start);
            c.drop_layer_controls();
            if (by_lines) pass.use_own_solver(c);
            pass.prepare(c);
            report.note(format("wall layer (graded, set of blocks): not made: on its lines' controls the set "
                               "%s in %ld iteration(s) (residual %.3g); the grid has no wall layer (space the "
                               "sides that meet the walls for their heights)", diverged ? "diverged" : "stalled",
                               run.iterations - before, run.residual));
            made = false;
        }
    }
    if (!made) {
        pass.converge(c);  // no layer, or its fallback
    } else {
        // The second pass: the first cells back to their heights where the
        // solve made them drift, the grid then held exactly. Where that
        // diverges (the exact controls of a grid turned near a corner are
        // too large for the smoother) the first pass's grid stays, said.
        const Composite::Snapshot first = c.snapshot();
        const long before = run.iterations;
        const double skew = c.largest_skew();
        layer.respace(c, false);
        layer.turn_to_normals(c);
        // Re-spaced and turned where the lines the solve shaped differ
        // sharply from one to the next (pitzDaily's rows off the step's
        // face: 10.6 -> 80 degrees), the first pass's grid is held instead.
        const double reshaped = c.largest_skew();
        if (!(reshaped <= skew + kReshapeSkew)) {
            c.restore(first);
            report.note(format("wall layer (graded, set of blocks): its lines not re-spaced to the walls' heights "
                               "after the first pass (that would skew a cell by %.3g degrees, the first pass's grid "
                               "by %.3g): the first pass's grid is held, its first cells as the figures below give "
                               "them", reshaped, skew));
        }
        c.hold_spacing(system, true);
        c.hold_vertices(true);
        pass.prepare(c);
        if (pass.clipped() > 0)
            report.note(format("%s: %ld control value(s) of its coarse levels clipped to %g (the wall layer's "
                               "stretching doubles with each level)", set.block(0)->solver_name(), pass.clipped(),
                               kMaxCoarseStretching));
        try {
            pass.converge(c);
        } catch (const Error &e) {
            if (e.failure() != Failure::Diverged) throw;
            c.restore(first);
            c.hold_spacing(system, false);
            c.hold_vertices(false);
            pass.prepare(c);
            report.note(format("wall layer (graded, set of blocks): held exactly, the set diverged in %ld "
                               "iteration(s) (residual %.3g); the grid is the one on the lines' one-dimensional "
                               "controls instead, its first cells as the figures below give them",
                               run.iterations - before, run.residual));
            pass.converge(c);
        }
        run.layer = layer.measure(c);
        report.note(format("wall layer (graded, set of blocks): %d line(s) graded from the walls across the blocks, "
                           "first cells within %.2g%% of their heights, growth at most %.4g within %d cells of a wall%s",
                           run.layer.lines, 100.0 * run.layer.first_off, run.layer.growth, kGradedRows,
                           run.layer.growth > kGradedGrowth
                               ? format(" (more than %g: give the blocks more nodes across the walls, or larger "
                                        "first cells)", kGradedGrowth).c_str()
                               : ""));
    }
    write_back(set, c, run.iterations, report);
    run.levels = pass.levels();
    run.note = format("set of %d blocks: %ld unknowns, %s on %d level(s), %ld iteration(s), residual %.3g", set.size(),
                      run.unknowns, set.block(0)->solver_name(), run.levels, run.iterations, run.residual);
}

}  // namespace eg2d
