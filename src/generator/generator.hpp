// Generator: one grid with everything that defines its generation (system,
// controls, solver, settings) and the run loop that is the same for every
// solver: residual, divergence check and restore, monitor, stopping, folds.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "controls/control.hpp"
#include "grid/boundary_motion.hpp"
#include "base/grid_snapshot.hpp"
#include "base/settings.hpp"
#include "base/grid.hpp"
#include "operator/operator.hpp"
#include "solvers/solver.hpp"

namespace eg2d {

// A folded start under a graded wall layer is solved without controls to
// this residual only: the layer re-spaces its lines and keeps their shape,
// which a rounder residual does not change (S-shaped diffuser 177x81: 1
// cycle against 3 to 1e-10). A set of blocks' layer takes its lines'
// shape from a pass converged to it too (blocks/set_solve.cpp).
constexpr double kShapeTolerance = 1e-6;

// The run's last good grid: the latest iterate whose residual is below the
// previous good one's (the start is the first), has halved since or comes 10
// iterations after it, and that folds no more cells than the start. A
// divergence goes back
// to it: an iteration that diverges can fold the grid several iterations
// before its residual shows it (point SOR at omega 1.95 on the swan 17x17:
// the iterate before the failing one had 215 of 256 cells folded).
class StallWatch;

class LastGoodGrid {
public:
    LastGoodGrid(const Grid &g, int iteration, double residual);
    void offer(const Grid &g, int iteration, double residual);
    int restore(Grid &g) const;  // the iteration it was taken at

private:
    GridSnapshot snapshot_;
    double residual_;
    int iteration_;
    long folded_;
};

class Generator {
public:
    Generator(int ni, int nj);

    const Grid &grid() const { return grid_; }
    Settings settings;
    // Called after each iteration with (iteration count, residual); true stops the run.
    std::function<bool(int, double)> monitor;

    // Each of these has the strong guarantee: on a throw nothing changed.
    void set_topology(Topology t);
    // Setting a side's points ends any sliding of that side.
    void set_side(Side s, const double *x, const double *y) {
        grid_.set_side(s, x, y);
        drop_motion(s);
        changed_boundary();
    }
    void set_boundary(const double *x, const double *y) {
        grid_.set_boundary(x, y);
        motions_.clear();
        changed_boundary();
    }
    // A side whose nodes slide (applied after every iteration); replaces any
    // motion of the same side. Call after setting the side's points.
    void set_motion(std::shared_ptr<const BoundaryMotion> m) {
        drop_motion(m->side());
        motions_.push_back(std::move(m));
    }
    void set_coordinates(const double *x, const double *y);
    // A set of blocks solved together (blocks/): every node from x, y (ni*nj
    // each), the boundary as the user set it kept (a joined side's nodes
    // moved with the set), `iterations` and `report` the set's run.
    void take_solution(const std::vector<double> &x, const std::vector<double> &y, int iterations,
                       const RunReport &report);
    // Interior lines (Grid::set_interior_line): the solvers' unknowns
    // change, so any cached hierarchy is dropped; an initialised grid gets
    // the line's points at once.
    void set_interior_line(bool xi, int index, const double *x, const double *y) {
        grid_.set_interior_line(xi, index, x, y);
        changed_lines();
    }
    void clear_interior_lines() {
        grid_.clear_interior_lines();
        changed_lines();
    }
    // The boundary patches only name and type the boundary for the writers:
    // no effect on the generation.
    void set_patches(std::vector<Patch> patches) { grid_.patches = std::move(patches); }
    void set_wall_node_spacing(Side s, std::vector<double> h) { grid_.wall_node_spacing[static_cast<std::size_t>(s)] = std::move(h); }
    // `shape`: the controls shape the start (a wall layer's, shape_start);
    // a set of blocks shapes its blocks' starts together instead
    // (blocks/set_wall_layer.hpp).
    void initialize(int method, bool shape = true);
    void set_system(System s);
    System system() const { return system_; }
    void set_solver(int id);
    int solver_id() const { return solver_info_->id; }
    const char *solver_name() const { return solver_info_->name; }

    ControlSet &controls() { return controls_; }
    const ControlSet &controls() const { return controls_; }
    // Call after changing controls().
    void changed_controls();

    // Exactly n iterations (n >= 0). Throws Diverged (grid restored to before
    // the failing iteration) or Interrupted (iterations kept).
    void iterate(int n);
    // Iterates to the tolerance; throws NotConverged, Diverged, Interrupted,
    // and Folded when the converged grid has folded cells and settings ask.
    void solve();

    // NUMERICS.md's residual of the grid as it is. Needs an initialised grid.
    ResidualInfo residual() const;
    // The control terms in force as Thompson's P, Q per node (operator's
    // equivalent_sources; 0 at the nodes not solved for). Needs an
    // initialised grid; P, Q (either may be null) hold ni*nj values.
    void control_sources(double *P, double *Q) const;
    int iterations() const { return iterations_; }
    // What the last eg2d_iterate/eg2d_solve ran (solvers/run_report.hpp).
    const RunReport &report() const { return report_; }
    // The wall layer the last shape made (none: rows 0, no note).
    const WallLayerShape &layer() const { return layer_; }

    // Throws State unless the boundary is complete and the grid initialised.
    void require_initialized(const char *what) const;

private:
    void changed_boundary();
    void changed_lines() {
        changed_start();
        controls_.invalidate();
        shape_pending_ = true;
    }
    // Lets the controls build what they fix before the solve (a wall layer).
    // checked: the orthogonality control's check already passed on this grid.
    void shape_start(bool fill_above, bool checked = false);
    void drop_motion(Side s);
    // The variational system's functional for the grid as it is (its mean
    // cell area, the fold guard as settings ask); the default for the others.
    Functional functional() const;
    void changed_start();
    void ensure_ready();
    enum class RunEnd { Done, Converged, Limit };
    RunEnd run(long max_iterations, bool stop_at_tolerance);
    // A folded start of the variational system solved with Winslow's first.
    void untangle_start(const ControlFields &fields, const Settings &run_settings);
    // Uncontrolled-or-given Winslow multigrid cycles on the grid until the
    // tolerance, at most `most` of them (from an FMG start if `fresh`); r:
    // the residual at the end.
    int winslow_cycles(const ControlFields &fields, const Settings &run_settings, double tolerance, double &r,
                       int most, bool fresh);
    // One update of the dynamic controls before an iteration; true (and r
    // the residual after it) when the solver converges each iteration.
    bool advance_dynamic_controls(Problem &problem, double extent, double &r);
    [[noreturn]] void fail_diverged(const ResidualInfo &ri, double best, const LastGoodGrid &good);
    [[noreturn]] void fail_not_converged(long max_iterations, double r, double extent) const;
    [[noreturn]] void fail_stalled(const StallWatch &stall, const LastGoodGrid &good);
    void set_up_tick();
    void set_up();
    // "; the run's events: ..." (empty without any): a failure's causes.
    std::string events_said() const;
    // Dynamic controls have been updated since they last changed and are
    // within the tolerance of their target (ControlSet::mismatch() / L).
    bool settled(double extent, double tolerance) const {
        return !controls_.dynamic_pending() && controls_.settled() && controls_.mismatch() / extent <= tolerance;
    }

    Grid grid_;
    System system_ = System::Winslow;
    mutable ControlSet controls_;
    const SolverInfo *solver_info_;
    std::unique_ptr<Solver> solver_;
    int iterations_ = 0;
    bool fresh_start_ = false;
    RunReport report_;
    WallLayerShape layer_;        // the wall layer the controls made, if any
    bool shape_pending_ = false;  // grid, boundary or controls changed since shape_start
    bool boundary_changed_ = false;  // the boundary changed since shape_start
    double shaped_with_layer_ = 0.0, shaped_with_growth_ = 0.0;  // the settings shape_start used  // the interior is an initializer's and no iteration ran (Problem::fresh_start)
    std::vector<std::shared_ptr<const BoundaryMotion>> motions_;
};

}  // namespace eg2d
