// What the FAS multigrid does differently for the variational system
// (operator/variational.hpp) on a C-grid's wake cut (single blocks and
// O-grids get the Newton minimiser, variational_newton.hpp, which is far
// faster: bench/RESULTS.md): the smoother is the point Newton step, and on
// the fine grid, under the fold guard, no smoothing step and no coarse
// correction may fold a cell; a cycle that stops making progress because of
// that ends the run (FoldStall).
//
// Smoother, chosen by measurement (bench --variational): symmetric point
// Gauss-Seidel with the 2x2 Newton step per node (one sweep forward, one
// backward). Every term of V couples a node only to its eight neighbours, and
// the node's block is the exact second derivative there, so this is the
// nonlinear Gauss-Seidel of the Euler-Lagrange equations; line relaxation
// would need the Hessian's off-diagonal blocks, which change with the grid.
#pragma once
#include <string>

#include "solvers/multigrid_hierarchy.hpp"

namespace eg2d {

// One forward and one backward point sweep of the variational step over the
// level's unknowns (extra unknowns after each); returns the node steps the
// fold guard shortened.
long variational_sweeps(const Level &L);

// u_f += P(u_c - I u_f) as prolong_correction, but with a fold guard on the
// fine level (functional orientation != 0) a correction that adds folded
// cells is halved, up to three times, and then dropped. `save` is scratch.
// Returns the fraction of the correction kept (1, 1/2, 1/4, 1/8 or 0).
double prolong_guarded(const MgLevel &coarse, const Level &fine, std::vector<double> &save);

// Cells of a level that fold against `orientation` (folds.hpp's test).
long folded_cells(const Level &L, int orientation);

// The run's end when the fold guard stops the minimisation: the gradient
// norm not down by kProgress in kCycles cycles while the guard shortened
// steps (a node pressing on a flat corner comes half the way closer per
// step and never arrives).
class FoldStall {
public:
    static constexpr int kCycles = 10;
    static constexpr double kProgress = 0.8;
    // After each cycle: the residual, the steps shortened in it. Throws
    // NotConverged (the grid as it is kept: unfolded) on a stall.
    void observe(double residual, long refused);
    void reset() { *this = FoldStall{}; }

private:
    double best_ = -1.0;
    int since_ = 0;
    long refused_ = 0;  // steps shortened since the best
};

}  // namespace eg2d
