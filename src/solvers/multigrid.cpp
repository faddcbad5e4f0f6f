// FAS multigrid (Brandt's full approximation scheme) for the nonlinear grid
// equations: V or W cycles, an optional full-multigrid (FMG) start, alternating
// nine-point ILU smoothing on single-block grids and alternating line
// Gauss-Seidel smoothing on O- and C-grids (multigrid_smoother.cpp). One
// iterate() is one cycle; the first after a reset is the FMG start (it ends
// with the cycle on the fine grid).
//
// Coarse level c of fine level f (multigrid_hierarchy.hpp):
//   u_c = I u_f                         injection (boundary included)
//   f_c = L_c(I u_f) - s * W R_f        W full weighting, R_f = L_f(u_f) - f_f,
//                                       s = operator_scale (index units)
//   solve L_c(u_c) = f_c  (recursively), then u_f += P (u_c - I u_f), bilinear.
//
// Defaults, W(2,1) with FMG (settings.hpp), chosen by measurement on the
// elliptic-grid course notes' domains and the annulus (bench/eg2d_bench). With the ILU smoother the
// per-cycle factor on the swan is 0.002-0.006 and on the dome 0.01-0.09 at
// 65^2..1025^2 (the dome's worst, 0.086 at 1025^2, sits at the top middle,
// where alpha/gamma is about 3600; W(2,2) makes it 0.03 for 40% more work,
// V(2,1) keeps these factors for about 60% of the cost). With the
// over-relaxed zebra/line smoother (O- and C-grids) V(2,1) was about 30%
// faster at 1025^2 for a somewhat worse factor (swan 0.14 vs 0.11, dome 0.22
// vs 0.18); V(1,1) and W(1,1) converge more slowly on the dome.
// Every smoothing also relaxes the nodes next to the boundary's singular
// points (multigrid_local.hpp): an airfoil's trailing edge otherwise sets
// the cycle's factor. The swan's obtuse corners gain nothing from it
// (measured; left as they are). On a C-grid the eta-lines run through the
// wake cut and the trailing edge gets a longer local round
// (line_relax.cpp, multigrid_smoother.cpp): bench naca0012-c went from
// 9-12 cycles at 0.13-0.24 (growing with the grid) to 5-7 at 0.04-0.08.
#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "base/folds.hpp"
#include "base/grid_snapshot.hpp"
#include "solvers/multigrid_hierarchy.hpp"
#include "solvers/multigrid_local.hpp"
#include "solvers/multigrid_smoother.hpp"
#include "solvers/multigrid_variational.hpp"
#include "solvers/solver.hpp"
#include "solvers/variational_newton.hpp"

namespace eg2d {

namespace {

constexpr int kStallCycles = 20;

// How many coarsenings a direction with this |Phi| or |Psi| allows (capped).
int stretch_doublings(double stretch) {
    int k = 0;
    while (k < 40 && stretch * 2.0 <= kMaxCoarseStretching) {
        stretch *= 2.0;
        ++k;
    }
    return stretch == 0.0 ? 40 : k;
}

class Multigrid final : public Solver {
public:
    void iterate(Problem &p) override {
        const Settings &st = p.settings;
        if (st.mg_pre_smooth + st.mg_post_smooth < 1.0)
            fail(Failure::State, "multigrid: the pre- and post-smoothing counts are both 0; set "
                                 "EG2D_PARAM_MG_PRE_SMOOTH or EG2D_PARAM_MG_POST_SMOOTH to at least 1");
        // The variational system: Newton with this multigrid on its Hessian
        // (variational_newton.hpp), where the grid's unknowns allow it and
        // V is not S alone. S alone is Laplace (linear): the FAS point cycles
        // solve it in 2-3 cycles, 3-4x faster than the Newton minimiser at
        // 257^2 (bench --variational).
        const bool spacing_only = p.functional.area == 0.0 && p.functional.orthogonality == 0.0 &&
                                  p.functional.smoothness == 0.0 && p.functional.cotangent == 0.0;
        if (p.system == System::Variational && !spacing_only && VariationalNewton::handles(p.grid.connectivity())) {
            newton_used_ = true;
            newton_.iterate(p);
            return;
        }
        newton_used_ = false;
        prepare(p);
        if (p.system == System::Variational && !spacing_only && !noted_point_cycles_) {
            noted_point_cycles_ = true;
            note("multigrid: the variational system on a C-grid's wake cut (nodes coupled across it) is minimised "
                 "by FAS cycles of point Newton steps, not the global Newton minimiser; expect many cycles");
        }
        if (p.dynamic_controls && sweeps_only_) {
            sweep();
            return;
        }
        // With a control recomputed from the grid between iterations (the
        // wall control) each cycle follows one update of it (the run paces
        // the updates for cycles: converges_each_iteration). That coupled
        // iteration is not safe on every grid (NACA0012 257x65 at a wall
        // spacing of 1e-5 chord: some paces fold the trailing-edge cells and
        // stall), so a cycle that adds folded cells or non-finite values is
        // undone, and the run goes on with sweeps.
        const bool guard = p.dynamic_controls;
        if (guard) {
            saved_.take(p.grid);
            if (folded_ < 0) folded_ = fold_summary(p.grid).folded;
        }
        // FMG builds a start from the coarsest grid: better than TFI, worse
        // than a grid the user set or one already solved (a restart, a
        // boundary moved a little), which the cycles take as it is.
        if (!started_ && st.mg_fmg != 0.0 && p.fresh_start) full_multigrid();
        else cycle(0);
        started_ = true;
        if (guard) {
            const bool finite = std::all_of(p.grid.x.begin(), p.grid.x.end(), [](double v) { return std::isfinite(v); }) &&
                                std::all_of(p.grid.y.begin(), p.grid.y.end(), [](double v) { return std::isfinite(v); });
            const long folded = finite ? fold_summary(p.grid).folded : folded_ + 1;
            if (folded > folded_) {
                note(finite ? format("multigrid: a cycle under the wall control added folded cells (%ld, from %ld); "
                                     "it is undone and the run goes on with line sweeps", folded, folded_)
                            : std::string("multigrid: a cycle under the wall control went non-finite; it is undone "
                                          "and the run goes on with line sweeps"));
                saved_.restore(p.grid);
                sweeps_only_ = true;
                sweep();
            }
        }
    }
    void reset() override {
        levels_.clear();
        started_ = false;
        sweeps_only_ = false;
        folded_ = -1;
        stall_best_ = std::numeric_limits<double>::infinity();
        stall_count_ = 0;
        fold_stall_.reset();
        newton_.reset();
        newton_used_ = noted_point_cycles_ = false;
    }
    bool converges_each_iteration() const override { return !sweeps_only_; }
    // 200 iterations, cycles or the line sweeps it hands over to: the test
    // suite's converged runs go at most 53 without a 10% gain, and NACA 0012's
    // C-grid 385x97 with a first cell at y+ 100 (its layer refused, every
    // cycle folding) gives up after 2.4 s at 300.
    long stall_window(int, int) const override { return 200; }
    // Guarded cycles that stop making progress (the best residual not halved
    // in kStallCycles cycles: Petrilli's (1989) channel 2 with its sources stalled
    // at 9e-4) also hand over to sweeps. Progress is the larger of residual
    // and control gap going down: while the wall control ramps, the residual
    // alone stalls, and counting it handed the annulus (1e-4 wall) to sweeps
    // just as the control's acceleration began (65x33: 150 iterations, 30
    // when the gap counts).
    void observe(double residual, double control_gap) override {
        if (newton_used_) {
            newton_.observe(residual);
            return;
        }
        if (system_ == System::Variational && !levels_.empty()) {
            const long refused = levels_[0].refused;
            levels_[0].refused = 0;
            fold_stall_.observe(residual, refused);
        }
        if (sweeps_only_ || folded_ < 0) return;
        const double progress = std::max(residual, control_gap);
        if (progress < 0.5 * stall_best_) {
            stall_best_ = progress;
            stall_count_ = 0;
        } else if (++stall_count_ >= kStallCycles) {
            sweeps_only_ = true;
            note(format("multigrid: under the wall control no progress in %d cycles (best %.3g); the run goes on "
                        "with line sweeps", kStallCycles, stall_best_));
        }
    }

private:
    // One line Gauss-Seidel sweep in each direction (EG2D_SOLVER_LSOR at
    // omega = 1): the fallback while a dynamic control is paced for sweeps.
    void sweep() {
        MgLevel &m = levels_[0];
        sweep_xi_lines(system_, m.level, 1.0, m.work);
        sweep_eta_lines(system_, m.level, 1.0, m.work);
        relax_extra_unknowns(system_, m.level, 1.0);
    }

    // (Re)builds the hierarchy when the problem's shape changed and attaches
    // the fine grid and the controls, which may have changed since last time.
    void prepare(const Problem &p) {
        const Connectivity &conn = p.grid.connectivity();
        const int coarsest = static_cast<int>(p.settings.mg_coarsest);
        // A dynamic control's fields change every iteration: its stretching
        // would rebuild the levels each time, and its coarse levels are
        // guarded otherwise (iterate()).
        double stretch_i, stretch_j;
        coarse_stretch(p.controls.empty() || p.dynamic_controls ? nullptr : &p.controls, stretch_i, stretch_j);
        // Rebuilt when the shape changes, and when the controls' stretching
        // allows other coarsenings (build_hierarchy).
        const int allowed = stretch_doublings(stretch_i) * 64 + stretch_doublings(stretch_j);
        if (levels_.empty() || levels_[0].conn.ni() != conn.ni() || levels_[0].conn.nj() != conn.nj() ||
            levels_[0].conn.topology() != conn.topology() || levels_[0].conn.held_rows() != conn.held_rows() ||
            system_ != p.system || coarsest_ != coarsest || allowed_ != allowed) {
            levels_ = build_hierarchy(conn, p.system, coarsest, stretch_i, stretch_j);
            allowed_ = allowed;
            system_ = p.system;
            coarsest_ = coarsest;
            started_ = false;
            clip_noted_ = false;
        }
        const Level fine = p.level();
        levels_[0].level = fine;
        levels_[0].level.conn = &levels_[0].conn;
        attach_functional(levels_, fine.functional);
        long clipped = 0;
        for (std::size_t l = 1; l < levels_.size(); ++l) {
            restrict_controls(levels_[l - 1].level.controls, levels_[l - 1].conn, levels_[l]);
            clipped += clip_coarse_stretching(levels_[l]);
        }
        levels_[0].singular = singular_nodes(conn, fine.x, fine.y);
        for (std::size_t l = 1; l < levels_.size(); ++l) levels_[l].singular = coarse_nodes(levels_[l - 1].singular, levels_[l]);
        for (MgLevel &m : levels_) m.trailing_edge = cut_ends(m.conn);
        for (MgLevel &m : levels_) m.work.limit_ring_steps = !p.dynamic_controls;
        report_ = p.report;
        if (report_) {
            report_->levels = static_cast<int>(levels_.size());
            report_->levels_built = std::max(report_->levels_built, static_cast<int>(levels_.size()));
            if (levels_.size() == 1 && report_->events.empty())
                note(format("multigrid: the %dx%d grid has no coarse level (a direction of %d nodes or fewer "
                            "stays); a cycle is its smoothing sweeps", conn.ni(), conn.nj(), coarsest));
        }
        // Said once per hierarchy: a dynamic control is restricted again
        // every iteration.
        if (clipped > 0 && !clip_noted_) {
            clip_noted_ = true;
            note(format("multigrid: the coarse levels' |Phi|, |Psi| clipped to %g at %ld node(s), where coarsening "
                        "doubled them past it (the coarse corrections are less accurate there; the fine grid's "
                        "equations are unchanged)", kMaxCoarseStretching, clipped));
        }
        pre_ = static_cast<int>(p.settings.mg_pre_smooth);
        post_ = static_cast<int>(p.settings.mg_post_smooth);
        gamma_ = static_cast<int>(p.settings.mg_cycle);
        floor_ = 1e-14 * p.grid.extent();
    }

    void cycle(std::size_t l) {
        MgLevel &m = levels_[l];
        if (levels_.size() == 1) {
            // Nothing coarsens (ni-1 and nj-1 odd, or too small): the cycle
            // is its smoothing. Solving the fine grid as a coarsest level
            // would make one iteration up to 50 sweeps and 50 residuals
            // (fuzz_api found a 300-iteration run on an 18x24 grid that
            // took 12 s under the sanitizers).
            smooth(system_, m, std::max(1, pre_ + post_), false);
            return;
        }
        if (l + 1 == levels_.size()) {
            coarse_solve(system_, m, floor_);
            return;
        }
        MgLevel &c = levels_[l + 1];
        smooth(system_, m, pre_, false);
        compute_residual(system_, m);
        inject(m.conn, m.level.x, c, c.x0.data());
        inject(m.conn, m.level.y, c, c.y0.data());
        std::copy(c.x0.begin(), c.x0.end(), c.x.begin());
        std::copy(c.y0.begin(), c.y0.end(), c.y.begin());
        // f_c = L_c(I u) - s W R: first W R into f_c, then add L_c(I u) node by node.
        restrict_residual(system_, m, c, c.fx.data(), c.fy.data());
        Level plain = c.level;
        plain.fx = plain.fy = nullptr;
        auto add_plain = [&](int I, int J) {
            const Stencil s = c.conn.stencil(I, J);
            const NodeEquation eq = node_equation(system_, plain, s);
            c.fx[s.c] = eq.rx - c.fx[s.c];
            c.fy[s.c] = eq.ry - c.fy[s.c];
        };
        for (int J = c.conn.j_begin(); J < c.conn.j_end(); ++J)
            for (int I = c.conn.i_begin(); I < c.conn.i_end(); ++I) add_plain(I, J);
        for (const Connectivity::Node &n : c.conn.extra_unknowns()) add_plain(n.i, n.j);
        for (int g = 0; g < gamma_ && l + 1 < levels_.size(); ++g) {
            cycle(l + 1);
            if (l + 2 >= levels_.size()) break;  // the coarsest level is solved once
        }
        if (keep_coarse(l)) correct(l);
        smooth(system_, m, post_, true);
    }

    // A coarse level whose grid went non-finite or whose ring systems went
    // singular (a coarse grid too crude for the geometry: an airfoil's
    // trailing edge on a handful of points) is
    // dropped with all coarser ones, for this correction and every later
    // cycle; the cycle goes on with the levels that work.
    bool keep_coarse(std::size_t l) {
        if (l + 1 >= levels_.size()) return false;
        const MgLevel &c = levels_[l + 1];
        for (std::size_t k = 0; k < c.size(); ++k)
            if (c.work.singular || !std::isfinite(c.x[k]) || !std::isfinite(c.y[k])) {
                const std::size_t below = levels_.size() - l - 2;
                std::string why = format("multigrid: the %dx%d level went non-finite (too coarse for the geometry); "
                                         "it is dropped%s, and the cycles go on with %zu level%s",
                                         c.conn.ni(), c.conn.nj(),
                                         below ? format(" with the %zu coarser", below).c_str() : "", l + 1,
                                         l ? "s" : "");
                levels_.erase(levels_.begin() + static_cast<std::ptrdiff_t>(l) + 1, levels_.end());
                note(std::move(why));
                return false;
            }
        return true;
    }

    // Solve the plain problem (f = 0) on the coarsest level from the injected
    // start, then on each finer level start from its own grid plus the
    // interpolated change of the coarser solution and do one cycle.
    void full_multigrid() {
        const std::size_t last = levels_.size() - 1;
        if (last == 0) {
            cycle(0);
            return;
        }
        for (std::size_t l = 1; l <= last; ++l) {
            MgLevel &c = levels_[l];
            inject(levels_[l - 1].conn, levels_[l - 1].level.x, c, c.x.data());
            inject(levels_[l - 1].conn, levels_[l - 1].level.y, c, c.y.data());
            std::fill(c.fx.begin(), c.fx.end(), 0.0);
            std::fill(c.fy.begin(), c.fy.end(), 0.0);
        }
        coarse_solve(system_, levels_[last], floor_);
        for (std::size_t l = last; l-- > 0;) {
            MgLevel &m = levels_[l];
            if (keep_coarse(l)) {
                MgLevel &c = levels_[l + 1];
                inject(m.conn, m.level.x, c, c.x0.data());
                inject(m.conn, m.level.y, c, c.y0.data());
                correct(l);
            }
            if (l > 0) {
                std::fill(m.fx.begin(), m.fx.end(), 0.0);
                std::fill(m.fy.begin(), m.fy.end(), 0.0);
            }
            cycle(l);
        }
    }

    // Level l += the correction of level l + 1; the variational system's
    // fold guard may damp or drop it (multigrid_variational.hpp).
    void correct(std::size_t l) {
        if (system_ == System::Variational) prolong_guarded(levels_[l + 1], levels_[l].level, save_);
        else prolong_correction(levels_[l + 1], levels_[l].level);
    }

    void note(std::string message) {
        if (report_) {
            report_->note(std::move(message));
            report_->levels = static_cast<int>(levels_.size());
        }
    }

    std::vector<MgLevel> levels_;
    RunReport *report_ = nullptr;  // the run's, set by prepare()
    System system_ = System::Winslow;
    int coarsest_ = 0, pre_ = 1, post_ = 1, gamma_ = 1;
    double floor_ = 0.0;
    bool started_ = false;
    int allowed_ = -1;  // the coarsenings the controls' stretching allowed (prepare)
    bool clip_noted_ = false;  // the coarse controls' clipping was reported for this hierarchy
    bool sweeps_only_ = false;          // a guarded cycle failed: sweeps until reset()
    long folded_ = -1;                  // folded cells of the grid the guarded cycles started from
    double stall_best_ = std::numeric_limits<double>::infinity();
    int stall_count_ = 0;
    GridSnapshot saved_;  // the grid before a guarded cycle
    std::vector<double> save_;  // scratch of the variational fold guard
    FoldStall fold_stall_;
    VariationalNewton newton_;
    bool newton_used_ = false, noted_point_cycles_ = false;
};

}  // namespace

std::unique_ptr<Solver> make_multigrid() { return std::make_unique<Multigrid>(); }

}  // namespace eg2d
