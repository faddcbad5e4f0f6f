// V = a A/Abar + b S + c O/Abar (variational.hpp) as a sum over cells: one
// cell's share, its gradient and its exact Hessian in the cell's eight
// coordinates, for the global Newton minimiser (solvers/variational_newton).
//
// A cell (corners 0..3 in its own order (i,j), (i+1,j), (i+1,j+1), (i,j+1))
// holds its area^2, its four corner dot products^2 and half of each of its
// four edges' |dr|^2 (an interior edge lies in two cells; an edge in one cell
// only joins two boundary nodes, which do not move). Summed over the cells
// this is V exactly as variational.cpp's node equations have it.
//
// The area term is taken as w (area - mean)^2 with `mean` the mean cell
// area: the sum of the areas is fixed by the boundary, so this differs from
// w area^2 summed by a constant only (same gradient, same Hessian), and its
// f is small where the areas are even (less round-off in V, and the
// Hessian's second part below is small).
//
// The other terms are w f^2 with f quadratic in the coordinates (the area
// (r2 - r0) x (r3 - r1)/2, a corner's u.v, u = r_next - r_m, v = r_prev -
// r_m), so their Hessian is 2 w (grad f grad f^T + f K), with K = hess f
// constant and indefinite: eigenvalues +-1/2 on (d1, d2) = (r2 - r0, r3 -
// r1) for the area, +-1 on (u, v) for a corner. Convex: f K is replaced by
// its positive part, f K/2 + |f| I/4 (area) or f K/2 + |f| I/2 (corner), I
// the identity on (d1, d2) or (u, v): the nearest positive semidefinite
// term, equal to the exact one where f = 0 (even areas, right angles).
// The smoothness term W and O's cotangent form are not quadratic in the
// coordinates: their terms are worked out apart (smoothness_cell.hpp).
#pragma once

#include "operator/variational.hpp"

namespace eg2d {

struct CellTerms {
    double value = 0.0;
    double g[8] = {};      // dV/d(x0, y0, x1, y1, x2, y2, x3, y3)
    double h[8][8] = {};   // the exact second derivatives, same order
    double hc[8][8] = {};  // the convex ones
};

// The cell's share of V (its area term about `mean`) at corners (x[m], y[m]);
// with `hessians` false only value and g are filled.
void cell_terms(const Functional &F, double mean, const double x[4], const double y[4], bool hessians,
                CellTerms &out);

// The cell's share of V alone (the line search's energy), the same way.
double cell_value(const Functional &F, double mean, const double x[4], const double y[4]);

// The smallest alpha > 0 at which a corner of the cell with corners
// (x + alpha dx, y + alpha dy) turns flat against `orientation` (+1, -1), or
// infinity: each corner's turn is quadratic in alpha; a corner already flat
// or folded sets no limit (the Newton steps' fold guard).
double cell_fold_limit(const double x[4], const double y[4], const double dx[4], const double dy[4], int orientation);

}  // namespace eg2d
