// Local relaxation near the boundary's singular points (Brandt's remedy for
// re-entrant corners and sharp trailing edges): the error of a cycle
// concentrates where the solution is singular, and those few nodes set the
// max-norm residual of NUMERICS.md. Extra point Gauss-Seidel sweeps in a
// small box around each such node, on every level, remove it for a cost
// independent of the grid size.
#pragma once
#include <vector>

#include "base/connectivity.hpp"
#include "operator/operator.hpp"

namespace eg2d {

// Boundary nodes of the fine grid where the solution is singular: the corners
// of a single block, a C-grid's cut ends (cut_ends) and every boundary node where the boundary turns by more
// than kSingularTurn (an O-grid airfoil's trailing edge, a kink of a side).
std::vector<Connectivity::Node> singular_nodes(const Connectivity &conn, const double *x, const double *y);

// A C-grid's trailing edge, where each side of the cut turns only a little:
// the two ends of the level's own wake cut (none without a cut). On top of
// the round every singular node gets, they get a longer one of their own
// (multigrid_smoother.cpp): with either round alone C-grids took more cycles
// (odd wakes: 10 and 12 instead of 9 and 11 at 65x17 and 129x33).
std::vector<Connectivity::Node> cut_ends(const Connectivity &conn);


// `sweeps` symmetric point Gauss-Seidel sweeps over the unknowns within
// `radius` index steps of each node.
void relax_near(System system, const Level &L, const std::vector<Connectivity::Node> &nodes, int radius,
                int sweeps);

}  // namespace eg2d
