// The multigrid smoother and coarsest-level solver: alternating line
// Gauss-Seidel (line_relax.hpp). Lines make it robust to stretched cells:
// a point smoother cannot damp errors that are smooth along the strong
// direction, a line solve in that direction removes them.
#pragma once
#include "operator/system.hpp"
#include "solvers/multigrid_hierarchy.hpp"

namespace eg2d {

// `sweeps` alternating sweeps: xi-lines then eta-lines (eta then xi, in
// reverse order, when `reverse`: post-smoothing mirrors pre-smoothing).
void smooth(System system, MgLevel &m, int sweeps, bool reverse);

// m.rx, m.ry = R = L(r) - f at the unknowns (0 elsewhere).
void compute_residual(System system, MgLevel &m);

// The coarsest level: smoothing sweeps until the largest |R|/diag fell by
// 1e-3 or below `floor` (round-off), or a cap of sweeps that grows with the
// level's size; the best iterate is kept.
void coarse_solve(System system, MgLevel &m, double floor);

}  // namespace eg2d
