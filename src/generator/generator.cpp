#include "generator/generator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.hpp"
#include "eg2d.h"
#include "grid/initializers.hpp"
#include "base/folds.hpp"
#include "base/self_crossing.hpp"
#include "controls/controls.hpp"
#include "generator/stall_watch.hpp"
#include "base/setup_progress.hpp"

namespace eg2d {

// A new last good grid is taken when the residual is below the last one's
// and has halved since, or kGoodEvery iterations have passed: the fold count
// and the copy then cost a small part of a sweep (at every iteration point
// SOR was 25% slower, bench swan 257^2).
constexpr double kGoodStep = 0.5;
constexpr int kGoodEvery = 10;

LastGoodGrid::LastGoodGrid(const Grid &g, int iteration, double residual)
    : residual_(residual), iteration_(iteration), folded_(fold_summary(g).folded) {
    snapshot_.take(g);
}

void LastGoodGrid::offer(const Grid &g, int iteration, double residual) {
    if (!(residual < residual_)) return;
    if (!(residual <= kGoodStep * residual_) && iteration - iteration_ < kGoodEvery) return;
    if (fold_summary(g).folded > folded_) return;
    residual_ = residual;
    iteration_ = iteration;
    snapshot_.take(g);
}

int LastGoodGrid::restore(Grid &g) const {
    snapshot_.restore(g);
    return iteration_;
}

namespace {
// Below this residual growth is never taken for divergence: round-off near a
// converged grid can grow by large factors and still mean nothing.
constexpr double kDivergenceFloor = 1e-2;
// Smallest boundary extent L: below it the residual (a 3rd power of node
// spacings) underflows to 0 and a TFI grid would pass as converged (found
// by fuzz_api). The largest is bounded by kMaxCoordinate in grid.cpp.
constexpr double kMinExtent = 1e-75;
// The smallest enclosed area, as a share of the bounding box's diagonal
// squared: below it the domain is flat (1e-12 is far below any real domain,
// a NACA 0012 in a 500-chord far field is 3e-1, and far above round-off).
constexpr double kMinAreaShare = 1e-12;
// The pace of dynamic controls against a solver that converges each
// iteration (ControlPace; measured in the loop of run()).
constexpr double kCyclePaceRelaxation = 3.0;
constexpr double kCyclePaceStep = 5.0;
// Winslow cycles at most for a folded variational start (untangle_start).
constexpr int kUntangleCycles = 50;

// The residual of a grid before any iteration. Coordinates are bounded, so a
// non-finite value can only come from a control value too large for the
// metric terms (a source, source array, weight or parameter grid near
// DBL_MAX; found by fuzz_api): refuse it rather than return NaN or call the
// first iteration a divergence.
ResidualInfo finite_residual(System system, const Level &level, double extent) {
    const ResidualInfo ri = eg2d::residual(system, level, extent);
    if (!std::isfinite(ri.value))
        fail(Failure::Argument, format("the equations are not finite at node (%d, %d) of the grid as it is: a "
                                       "control value (source, source array, weight, parameter grid) is too large",
                                       ri.i, ri.j));
    return ri;
}

void check_extent(const Grid &g) {
    const double L = g.extent();
    if (!(L >= kMinExtent))
        fail(Failure::Boundary, format("the boundary's extent (bounding-box diagonal) is %g, below %g: the points "
                                       "(nearly) coincide, or the domain needs scaling", L, kMinExtent));
    const BoundaryCrossing c = find_boundary_crossing(g);
    if (c.found)
        fail(Failure::Boundary, format("the boundary crosses itself: %s segment %d-%d crosses %s segment %d-%d near "
                                       "(%.6g, %.6g)", side_name(c.side_a), c.a, c.a + 1, side_name(c.side_b), c.b,
                                       c.b + 1, c.x, c.y));
    // A boundary that encloses nothing (every point on one line, a side
    // lying on the side opposite) has no grid: refused, not "solved".
    const double area = boundary_area(g);
    if (!(area > kMinAreaShare * L * L))
        fail(Failure::Boundary, format("the boundary encloses an area of %.3g in a bounding box of diagonal %.3g: "
                                       "its points lie on one line, or a side lies on the side opposite",
                                       area, L));
}

std::string missing_sides(const Grid &g) {
    std::string s;
    for (int k = 0; k < 4; ++k) {
        const Side side = static_cast<Side>(k);
        if (g.has_side(side) && !g.side_set(side)) {
            if (!s.empty()) s += ", ";
            s += side_name(side);
        }
    }
    return s;
}
}  // namespace

Generator::Generator(int ni, int nj)
    : grid_(ni, nj), solver_info_(find_solver(EG2D_SOLVER_MULTIGRID)), solver_(solver_info_->make()) {}

void Generator::set_topology(Topology t) {
    Grid next(grid_);
    next.set_topology(t);
    grid_ = std::move(next);
    motions_.clear();
    changed_start();
    controls_.invalidate();
    shape_pending_ = true;
}

void Generator::drop_motion(Side s) {
    for (std::size_t k = 0; k < motions_.size(); ++k)
        if (motions_[k]->side() == s) {
            motions_.erase(motions_.begin() + static_cast<std::ptrdiff_t>(k));
            return;
        }
}

void Generator::changed_boundary() {
    controls_.invalidate();  // boundary-derived controls (Middlecoff-Thomas) must be recomputed
    shape_pending_ = boundary_changed_ = true;
}

void Generator::shape_start(bool fill_above, bool checked) {
    if (!checked)
        if (const Control *c = controls_.find(ControlKind::Orthogonality)) c->check(grid_);  // before any change
    shape_pending_ = boundary_changed_ = false;
    shaped_with_layer_ = settings.wall_layer;
    shaped_with_growth_ = settings.wall_growth;
    if (layer_.moved_sides) grid_.restore_boundary();  // the last shape's moves were its own
    layer_ = WallLayerShape{};
    Control *c = controls_.find(ControlKind::Orthogonality);
    // The graded layer (graded_layer.hpp) re-spaces the lines of the start it
    // is given: a folded start (the TFI start of an S-shaped duct) is first
    // solved without controls. An unfolded one is kept: the Winslow grid
    // would lose the rows' clustering of a flat plate's TFI start, which
    // the frozen Phi keeps exactly.
    std::string untangled;
    if (c && fill_above && is_wall_control(c) && c->grades(grid_, settings)) {
        const long folded = has_folds(grid_) ? fold_summary(grid_).folded : 0;
        double r = 0.0;
        const int cycles = folded > 0 ? winslow_cycles(ControlFields{}, settings, std::max(settings.tolerance, kShapeTolerance),
                                                      r, kUntangleCycles, grid_.held_rows() == 0)
                                      : 0;
        if (folded > 0)
            untangled = format("wall layer: the start grid has %ld folded cell(s); the layer is made on the Winslow "
                               "grid without controls instead (%d multigrid cycle(s), residual %.3g)", folded, cycles, r);
    }
    if (c) layer_ = c->shape_start(grid_, settings, fill_above);
    else if (grid_.held_rows() > 0) grid_.hold_rows(0);
    // A graded start not kept: one multigrid cycle on its one-dimensional
    // controls shapes the lines, which the layer then re-spaces and keeps,
    // with every solver (after one sweep of a line solver, the TMR bump kept
    // its start's skewness, 41 degrees against 14.5).
    if (c && c->shapes_after_cycle()) {
        double r = 0.0;
        winslow_cycles(controls_.update(grid_, true), settings, 0.0, r, 1, false);
        c->shape_after_cycle(grid_);
    }
    if (!untangled.empty()) layer_.note = untangled + (layer_.note.empty() ? "" : "; " + layer_.note);
    controls_.invalidate();
}

void Generator::changed_start() {
    iterations_ = 0;
    solver_->reset();
}

void Generator::set_coordinates(const double *x, const double *y) {
    grid_.set_coordinates(x, y);
    motions_.clear();  // the user's boundary is the boundary now
    changed_start();
    fresh_start_ = false;
    shape_pending_ = true;
    controls_.invalidate();
}

void Generator::take_solution(const std::vector<double> &x, const std::vector<double> &y, int iterations,
                              const RunReport &report) {
    check_coordinates("x", x.data(), grid_.size());
    check_coordinates("y", y.data(), grid_.size());
    RunReport copy = report;  // allocates before the change: strong guarantee
    report_.events.swap(copy.events);
    report_.solver = report.solver;
    report_.levels = report.levels;
    report_.levels_built = report.levels_built;
    report_.iteration = report.iteration;
    grid_.x = x;
    grid_.y = y;
    grid_.mark_initialized();
    changed_start();
    iterations_ = iterations;
    fresh_start_ = false;
}

void Generator::initialize(int method, bool shape) {
    const InitMethod *m = find_init_method(method);
    if (!m) fail(Failure::Argument, format("initialisation method %d: no such method", method));
    if (m->marches && !grid_.side_set(Side::JMin))
        fail(Failure::State, format("%s: side JMIN, the curve to march from, is not set", m->name));
    if (!m->marches && !grid_.boundary_complete())
        fail(Failure::State, format("the boundary is not complete: side %s not set", missing_sides(grid_).c_str()));
    check_extent(grid_);
    const bool lines = !grid_.interior_lines().empty();
    if (lines && m->marches)
        fail(Failure::State, format("%s writes every node: it cannot pass through the interior lines set "
                                    "(eg2d_clear_interior_lines, or a TFI method)", m->name));
    Grid next(grid_);
    next.restore_boundary();
    if (lines) {
        next.check_interior_lines();
        next.restore_interior_lines();
    }
    if (m->marches) m->fill(next, settings);
    else fill_blocks(next, settings, m->fill);
    check_coordinates("initial x", next.x.data(), next.size());
    check_coordinates("initial y", next.y.data(), next.size());
    if (const Control *c = controls_.find(ControlKind::Orthogonality)) c->check(next);  // before the commit
    if (m->marches) {
        // The march made the outer boundary: it is the boundary now, as
        // after eg2d_set_coordinates (no sliding sides survive it).
        const std::vector<double> mx(next.x), my(next.y);
        next.set_coordinates(mx.data(), my.data());
        motions_.clear();
    }
    next.mark_initialized();
    grid_ = std::move(next);
    for (const auto &mo : motions_) mo->restart();
    changed_start();
    fresh_start_ = true;
    if (shape) shape_start(true, true);
    else {
        layer_ = WallLayerShape{};
        shape_pending_ = boundary_changed_ = false;
    }
    controls_.invalidate();
}

void Generator::set_system(System s) {
    system_ = s;
    solver_->reset();
}

void Generator::set_solver(int id) {
    const SolverInfo *info = find_solver(id);
    if (!info) fail(Failure::Unsupported, format("solver %d is not built into this library", id));
    std::unique_ptr<Solver> next = info->make();
    solver_info_ = info;
    solver_ = std::move(next);
}

void Generator::changed_controls() {
    controls_.invalidate();
    solver_->reset();
    shape_pending_ = true;
}

void Generator::require_initialized(const char *what) const {
    if (!grid_.boundary_complete())
        fail(Failure::State, format("%s: the boundary is not complete: side %s not set", what,
                                    missing_sides(grid_).c_str()));
    if (!grid_.initialized())
        fail(Failure::State, format("%s: the grid has a boundary but no interior yet: call eg2d_initialize, "
                                    "eg2d_iterate or eg2d_solve first", what));
}

void Generator::ensure_ready() {
    if (!grid_.boundary_complete())
        fail(Failure::State,
             format("the boundary is not complete: side %s not set", missing_sides(grid_).c_str()));
    check_extent(grid_);
    grid_.check_interior_lines();  // a side set since may have moved a line's end
    if (!grid_.initialized()) initialize(EG2D_INIT_TFI);
}

Functional Generator::functional() const {
    if (system_ != System::Variational) return Functional{};
    const double cells = static_cast<double>(grid_.ni() - 1) * (grid_.nj() - 1);
    double mean = boundary_area(grid_) / cells;
    if (!(mean > 0.0)) mean = grid_.extent() * grid_.extent() / cells;  // a flat boundary: any scale
    const int orientation = settings.fold_check != 0.0 ? boundary_orientation(grid_) : 0;
    Functional f = make_functional(settings.variational_area, settings.variational_spacing,
                                   settings.variational_orthogonality, settings.variational_smoothness,
                                   settings.variational_orthogonality_form != 0.0, mean, orientation);
    f.sense = boundary_orientation(grid_) < 0 ? -1 : 1;
    return f;
}

ResidualInfo Generator::residual() const {
    require_initialized("residual");
    Grid &g = const_cast<Grid &>(grid_);  // the Level view is read-only here
    const ControlFields &f = controls_.update(g, false);
    Problem p{g, system_, f, settings, false, true, nullptr, functional()};
    return finite_residual(system_, p.level(), grid_.extent());
}

void Generator::control_sources(double *P, double *Q) const {
    require_initialized("controls");
    const std::size_t n = grid_.x.size();
    if (P) std::fill(P, P + n, 0.0);
    if (Q) std::fill(Q, Q + n, 0.0);
    if (system_ != System::Winslow || controls_.empty()) return;  // only Winslow has control terms
    Grid &g = const_cast<Grid &>(grid_);  // the Level view is read-only here
    const ControlFields &f = controls_.update(g, false);
    Problem p{g, system_, f, settings, false, true, nullptr, functional()};
    equivalent_sources(p.level(), P, Q);
}

// V's fold guard and its smoothness barrier keep unfolded cells unfolded;
// they cannot unfold a start that is folded already (the course notes'
// antenna: its TFI start folds, and V's minimisation from it ended with
// 141-6279 folded cells at 65^2-257^2). Winslow's equations untangle such
// starts (the antenna converges unfolded in 2 cycles), so with the fold
// guard on the variational run starts from the Winslow grid there, and says
// so (with the guard off V's minimum is sought from wherever it starts).
int Generator::winslow_cycles(const ControlFields &fields, const Settings &run_settings, double tolerance, double &r,
                              int most, bool fresh) {
    std::unique_ptr<Solver> winslow = find_solver(EG2D_SOLVER_MULTIGRID)->make();
    Problem p{grid_, System::Winslow, fields, run_settings, false, fresh, nullptr, Functional{}};
    const double extent = grid_.extent();
    r = eg2d::residual(System::Winslow, p.level(), extent).value;
    int cycles = 0;
    for (; cycles < most && std::isfinite(r) && r > tolerance; ++cycles) {
        winslow->iterate(p);
        p.fresh_start = false;
        r = eg2d::residual(System::Winslow, p.level(), extent).value;
    }
    return cycles;
}

void Generator::untangle_start(const ControlFields &fields, const Settings &run_settings) {
    const long folded = fold_summary(grid_).folded;
    if (folded == 0) return;
    double r = 0.0;
    const int cycles = winslow_cycles(fields, run_settings, settings.tolerance, r, kUntangleCycles, grid_.held_rows() == 0);
    const long left = std::isfinite(r) ? fold_summary(grid_).folded : -1;
    report_.note(format("variational: the start grid has %ld folded cell(s), which V's fold guard cannot unfold; "
                        "it starts from the Winslow grid instead (%d multigrid cycle(s), residual %.3g, %ld folded)",
                        folded, cycles, r, left));
    fresh_start_ = false;
}

// Before iteration 1 the monitor is called with the iteration count so far
// and no residual (+infinity): it may stop the run there too.
void Generator::set_up_tick() {
    if (monitor && monitor(iterations_, HUGE_VAL))
        fail(Failure::Interrupted, format("stopped by the monitor before iteration %d, during the set-up (the wall "
                                          "layer, the start grid): nothing changed", iterations_ + 1));
}

// The start grid and its wall layer, if they are to be made: with a
// monitor, called as they go (the march layer by layer: a 1793x513 C-grid's
// first call came 1.3 s into a 1.6 s run) and, when it stops the run there,
// the grid, the controls and the layer put back as they were.
void Generator::set_up() {
    // The layer's settings are read when it is shaped: a change reshapes it.
    // A new boundary (or an interior no iteration has touched) gets a new
    // start above the layer too; a grid the user set or iterated keeps its.
    auto shape_due = [this] {
        return shape_pending_ || shaped_with_layer_ != settings.wall_layer || shaped_with_growth_ != settings.wall_growth;
    };
    auto make = [&] {
        ensure_ready();
        setup_tick();  // the start grid is there: the monitor may read it
        if (shape_due()) shape_start(boundary_changed_ || fresh_start_);
    };
    if (!monitor || (grid_.initialized() && !shape_due()) || settings.monitor_set_up == 0.0) {
        // No ticks: not even an outer run's on this thread (a monitor that
        // runs another grid would have its own monitor called from there).
        const SetupProgress quiet(nullptr);
        return make();
    }
    struct Saved {
        Grid grid;
        ControlSet controls;
        WallLayerShape layer;
        bool pending, changed, fresh;
        double with_layer, with_growth;
        int iterations;
    } saved{grid_, controls_, layer_, shape_pending_, boundary_changed_, fresh_start_,
            shaped_with_layer_, shaped_with_growth_, iterations_};
    try {
        const SetupProgress progress([this] { set_up_tick(); });
        make();
    } catch (const Error &e) {
        if (e.failure() != Failure::Interrupted) throw;
        grid_ = std::move(saved.grid);
        controls_ = std::move(saved.controls);
        layer_ = std::move(saved.layer);
        shape_pending_ = saved.pending;
        boundary_changed_ = saved.changed;
        fresh_start_ = saved.fresh;
        shaped_with_layer_ = saved.with_layer;
        shaped_with_growth_ = saved.with_growth;
        iterations_ = saved.iterations;
        solver_->reset();
        throw;
    }
}

Generator::RunEnd Generator::run(long max_iterations, bool stop_at_tolerance) {
    // The control terms are coefficients of the quasi-linear (Winslow/TTM)
    // equation; Laplace has no place for them, and silently dropping the
    // user's controls would hand back a grid they did not ask for.
    if (system_ != System::Winslow && !controls_.empty())
        fail(Failure::State, format("control terms are set but the system is %s: controls need "
                                    "EG2D_SYSTEM_WINSLOW (or clear the controls)", system_name(system_)));
    if (system_ == System::Variational && !solver_info_->variational)
        fail(Failure::State, format("the %s solver does not solve the variational system (its line systems are "
                                    "Winslow's form); use one of: %s", solver_info_->name,
                                    variational_solver_names().c_str()));
    set_up();
    const ControlFields &fields = controls_.update(grid_, true);
    // The automatic relaxation factor is an over-relaxation (the elliptic-grid course notes'
    // optimum for Laplace). While a wall control is updated between sweeps
    // its strong first-order terms (rows that are not diagonally dominant
    // next to a sharp convex corner, the NACA0012 trailing edge) make
    // over-relaxation diverge: automatic means 1 then.
    Settings run_settings = settings;
    if (controls_.has_dynamic() && run_settings.relaxation == 0.0) run_settings.relaxation = 1.0;
    report_ = RunReport{};
    report_.solver = solver_info_->id;
    if (layer_.rows > 0 && layer_.hybrid)
        report_.note(format("wall layer (hybrid): %d rows of the hyperbolic march held (growth %.3g at their top); "
                            "the solver works on the %d rows above with the march's controls",
                            layer_.rows, layer_.growth, grid_.nj() - 2 - layer_.rows));
    else if (layer_.rows > 0)
        report_.note(format("wall layer: %d rows marched from the wall and held (growth %g); the solver works on "
                            "the %d rows above", layer_.rows, layer_.growth, grid_.nj() - 2 - layer_.rows));
    if (!layer_.note.empty()) report_.note(layer_.note);
    if (layer_.fold_row > 0)
        report_.note(format("wall layer: row %d would fold a cell, so the layer has %d of the %d rows asked",
                            layer_.fold_row, layer_.rows, layer_.asked));
    // A held wall layer comes with its own start above it (the layer's
    // distribution on straight lines), better than an FMG start from
    // coarse rings a few cells round (annulus 129x65 at a 1e-4 wall, far
    // field 30: the FMG start went non-finite).
    if (system_ == System::Variational && fresh_start_ && settings.fold_check != 0.0) untangle_start(fields, run_settings);
    Problem problem{grid_, system_, fields, run_settings, controls_.has_dynamic(),
                    fresh_start_ && grid_.held_rows() == 0 && !layer_.graded, &report_, functional()};
    const double extent = grid_.extent();
    double r = finite_residual(system_, problem.level(), extent).value;
    double best = r;
    LastGoodGrid good(grid_, iterations_, r);
    auto done = [&] { return stop_at_tolerance && r <= settings.tolerance && settled(extent, settings.tolerance); };
    // Only a solve stops on a stall: eg2d_iterate runs the count it is given.
    const bool watch = stop_at_tolerance && system_ != System::Variational;
    StallWatch stall(!watch ? 0
                     : settings.stall_iterations > 0.0 ? static_cast<long>(settings.stall_iterations)
                                                       : solver_->stall_window(grid_.ni(), grid_.nj()));
    stall.stalled(0, r, controls_.has_dynamic() ? StallWatch::kUnknown : 0.0);
    for (long it = 0; it < max_iterations; ++it) {
        if (done()) return RunEnd::Converged;
        if (controls_.has_dynamic() && advance_dynamic_controls(problem, extent, r) && done())
            return RunEnd::Converged;
        report_.iteration = iterations_ + 1;
        solver_->iterate(problem);
        for (const auto &m : motions_) m->apply(grid_);  // sliding sides follow the interior
        if (system_ == System::Variational && !motions_.empty())
            problem.functional = functional();  // the enclosed area moved a little
        const ResidualInfo ri = eg2d::residual(system_, problem.level(), extent);
        if (!std::isfinite(ri.value) ||
            (ri.value > settings.divergence_factor * best && ri.value > kDivergenceFloor))
            fail_diverged(ri, best, good);
        ++iterations_;
        fresh_start_ = problem.fresh_start = false;
        r = ri.value;
        solver_->observe(r, controls_.has_dynamic() ? controls_.mismatch() / extent : 0.0);
        best = std::min(best, r);
        good.offer(grid_, iterations_, r);
        if (stall.stalled(it + 1, r, controls_.has_dynamic() ? controls_.mismatch() / extent : 0.0))
            fail_stalled(stall, good);
        if (monitor && monitor(iterations_, r))
            fail(Failure::Interrupted,
                 format("stopped by the monitor at iteration %d (residual %.3g)", iterations_, r));
    }
    if (stop_at_tolerance) {
        if (done()) return RunEnd::Converged;
        fail_not_converged(max_iterations, r, extent);
    }
    return RunEnd::Done;
}

bool Generator::advance_dynamic_controls(Problem &problem, double extent, double &r) {
    // Against a solver that converges the grid for the current fields each
    // iteration, the control moves 3x (relaxation) and 5x (step) further
    // per update, and convergence is tested after the update: the residual
    // after such an iteration says nothing about the control, which would
    // stop a run whose wall spacing is still far off. Once past its ramp the
    // control accelerates its updates (Anderson, wall.cpp): with the grid
    // converged for each state they are a fixed-point iteration of the
    // control alone. (Measurements: bench/RESULTS.md, naca0012-wall.)
    const bool cycles = solver_->converges_each_iteration();
    ControlPace pace = cycles ? ControlPace{kCyclePaceRelaxation, kCyclePaceStep, true} : ControlPace{};
    pace.one_gain = solver_->marches_in_time();
    const bool moved = controls_.advance(grid_, settings, pace);
    if (!cycles) return false;
    if (moved) r = eg2d::residual(system_, problem.level(), extent).value;
    return true;
}

void Generator::fail_diverged(const ResidualInfo &ri, double best, const LastGoodGrid &good) {
    const int failed = iterations_ + 1;
    iterations_ = good.restore(grid_);
    solver_->reset();
    const std::string where =
        !std::isfinite(ri.value)
            ? format("non-finite residual at node (%d, %d)", ri.i, ri.j)
            : format("residual %.3g is more than %.3g times the run's best %.3g (largest at node (%d, %d))",
                     ri.value, settings.divergence_factor, best, ri.i, ri.j);
    fail(Failure::Diverged,
         format("%s diverged at iteration %d: %s; the grid is restored to iteration %d, the last good one "
                "(a lower residual, no more folded cells than the start)%s",
                solver_info_->name, failed, where.c_str(), iterations_, events_said().c_str()));
}

std::string Generator::events_said() const {
    std::string s;
    for (const RunEvent &e : report_.events)
        s += format("%s[iteration %d] %s", s.empty() ? "" : "; ", e.iteration, e.message.c_str());
    return s.empty() ? "" : "; the run's events: " + s;
}

void Generator::fail_stalled(const StallWatch &stall, const LastGoodGrid &good) {
    const int stopped = iterations_;
    iterations_ = good.restore(grid_);
    solver_->reset();
    fail(Failure::NotConverged,
         format("%s made no progress in %ld iterations (to iteration %d: neither the residual, best %.3g, nor the "
                "wall control's remaining change fell 10%% below its best; EG2D_PARAM_STALL_ITERATIONS); the grid "
                "is restored to iteration %d, the last good one%s",
                solver_info_->name, stall.window(), stopped, stall.best_residual(), iterations_,
                events_said().c_str()));
}

void Generator::fail_not_converged(long max_iterations, double r, double extent) const {
    if (r <= settings.tolerance)
        fail(Failure::NotConverged,
             format("%s did not converge in %ld iterations: residual %.3g is within the tolerance %.3g but "
                    "the wall control has not settled (its remaining change %.3g > tolerance)",
                    solver_info_->name, max_iterations, r, settings.tolerance, controls_.mismatch() / extent));
    fail(Failure::NotConverged,
         format("%s did not converge in %ld iterations: residual %.3g > tolerance %.3g", solver_info_->name,
                max_iterations, r, settings.tolerance));
}

void Generator::iterate(int n) { run(n, false); }

void Generator::solve() {
    run(static_cast<long>(settings.max_iterations), true);
    if (settings.fold_check != 0.0) {
        const FoldSummary fs = fold_summary(grid_);
        if (fs.folded > 0)
            fail(Failure::Folded,
                 format("the converged grid has %ld folded cell%s; the first is cell (%d, %d) "
                        "(cells are numbered by their lowest node)",
                        fs.folded, fs.folded == 1 ? "" : "s", fs.first_i, fs.first_j));
    }
}

}  // namespace eg2d
