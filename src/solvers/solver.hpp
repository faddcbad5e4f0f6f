// A solver does one iteration (a sweep, or a cycle of a multilevel method) on
// a Problem. It never computes the stopping residual or checks divergence:
// the Generator does that, the same way for every solver.
#pragma once
#include <algorithm>
#include <memory>
#include <string>

#include "operator/control_fields.hpp"
#include "base/settings.hpp"
#include "base/grid.hpp"
#include "base/table.hpp"
#include "operator/operator.hpp"
#include "operator/system.hpp"
#include "solvers/run_report.hpp"

namespace eg2d {

struct Problem {
    Grid &grid;
    System system;
    const ControlFields &controls;  // the fine grid's control fields
    const Settings &settings;
    // True while a control term is recomputed from the grid between
    // iterations (wall orthogonality): its update assumes each iteration
    // moves the grid a little, which a multilevel cycle does not.
    bool dynamic_controls = false;
    // True while the interior is an initial-grid method's (TFI) and no
    // iteration has run: a multilevel solver may then build its own start
    // from the coarsest grid (FMG). A grid the user set, or one already
    // iterated, is a better start than that, and is kept.
    bool fresh_start = true;
    // Where the solver says what it did (levels, fallbacks); may be null.
    RunReport *report = nullptr;
    // The variational system's functional on the fine grid (its weights over
    // this grid's mean cell area, and the fold guard).
    Functional functional;

    void note(std::string message) const {
        if (report) report->note(std::move(message));
    }

    // The fine grid as an operator Level.
    Level level() const {
        Level L;
        L.conn = &grid.connectivity();
        L.x = grid.x.data();
        L.y = grid.y.data();
        L.controls = controls.empty() ? nullptr : &controls;
        L.functional = &functional;
        return L;
    }
};

class Solver {
public:
    virtual ~Solver() = default;
    // One iteration. May leave NaN in the grid: the caller checks and restores.
    virtual void iterate(Problem &problem) = 0;
    // Called when the problem changed shape (topology, size, a new start):
    // drop any cached hierarchy or time-step cycle.
    virtual void reset() {}
    // The residual of the grid after each iteration, for solvers that adapt a
    // setting to the convergence they see; control_gap is the dynamic
    // controls' remaining change (Control::mismatch / L, 0 without), which
    // must reach the tolerance too.
    virtual void observe(double /*residual*/, double /*control_gap*/) {}
    // True if the next iteration brings the grid close to the solution for
    // the current control fields (a multigrid cycle), false for a sweep.
    // With a dynamic control the run then paces its updates for that
    // (ControlPace) and tests convergence after each update.
    virtual bool converges_each_iteration() const { return false; }
    // True for AF (pseudo-time marching): the wall control then keeps one
    // relaxation gain per node (ControlPace::one_gain). A measured choice for
    // AF alone, not a rule for slow solvers (wall.cpp, damped_update): a new
    // solver should be measured both ways.
    virtual bool marches_in_time() const { return false; }
    // Iterations without progress (generator/stall_watch.hpp) after which
    // eg2d_solve gives up, when EG2D_PARAM_STALL_ITERATIONS is automatic.
    // Sweeps: 500, or twice the longer side's nodes (a sweep's gain per
    // iteration falls as the grid grows). The largest gap between 10% gains
    // over the test suite's converged runs: PSOR 280 sweeps (250 wide),
    // line SOR 199, AF 102 (bench/RESULTS.md).
    virtual long stall_window(int ni, int nj) const { return std::max(500L, 2L * std::max(ni, nj)); }
};

struct SolverInfo {
    int id;             // EG2D_SOLVER_*
    const char *name;   // short name: "psor"
    std::unique_ptr<Solver> (*make)();
    // Solves the variational system: point and multilevel solvers; the line
    // solvers' systems are Winslow's form, which the variational one lacks.
    bool variational;
};

Table<SolverInfo> solver_table();  // in increasing id order
// nullptr if this library has no solver with that id.
const SolverInfo *find_solver(int id);
// The names of the solvers that solve the variational system, for messages.
std::string variational_solver_names();

// One lexicographic point SOR sweep over the unknowns of a level (psor.cpp);
// the point solver and the coarse-to-fine solver share it.
void sor_sweep(System system, const Level &L, double omega);

// The elliptic-grid course notes' optimal SOR factor for Laplace on an N1 x N2 grid.
double optimal_sor_omega(int n1, int n2);

}  // namespace eg2d
