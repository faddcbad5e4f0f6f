// The controls that make a grid an exact solution of the Thomas & Middlecoff
// (1980) form of Winslow's equations, node by node: where the grid is known
// (a march's layers, a re-spaced graded layer) and should be kept while the
// solve works round it.
#pragma once

#include <vector>

#include "base/grid.hpp"

namespace eg2d {

// Phi, Psi at every interior node of rows j0..nj-2 (an O-grid's seam
// included, its last column a copy of its first), such that
// alpha (r_xixi + Phi r_xi) - 2 beta r_xieta + gamma (r_etaeta + Psi r_eta) = 0
// there in NUMERICS.md's central differences: the 2x2 system
// [alpha r_xi, gamma r_eta] (Phi, Psi) = -(alpha r_xixi - 2 beta r_xieta +
// gamma r_etaeta), by Cramer's rule (determinant alpha gamma J, nonzero on
// an unfolded grid). phi and psi hold g.size() values; no other is written.
void invert_grid_controls(const Grid &g, int j0, std::vector<double> &phi, std::vector<double> &psi);

}  // namespace eg2d
