// The controls that make a grid an exact solution of the Thomas & Middlecoff
// (1980) form of Winslow's equations, node by node: where the grid is known
// (a march's layers, a re-spaced graded layer) and should be kept while the
// solve works round it.
#pragma once

#include "base/grid.hpp"

namespace eg2d {

// Phi, Psi at node (i, j) of m, its xi-neighbours a and b (a ring's seam:
// a = ni - 2 at i = 0), such that
// alpha (r_xixi + Phi r_xi) - 2 beta r_xieta + gamma (r_etaeta + Psi r_eta) = 0
// there in NUMERICS.md's central differences: the 2x2 system
// [alpha r_xi, gamma r_eta] (Phi, Psi) = -(alpha r_xixi - 2 beta r_xieta +
// gamma r_etaeta), by Cramer's rule (determinant alpha gamma J, nonzero on
// an unfolded grid).
void invert_controls(const Grid &m, int i, int a, int b, int j, double &phi, double &psi);

}  // namespace eg2d
