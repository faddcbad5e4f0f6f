// The variational system's corner terms that are not polynomials
// (variational.hpp): the smoothness term W, and O's cotangent form below.
// W is Brackbill & Saltzman's (1982) smoothness integral,
// int (|x_xi|^2 + |x_eta|^2)/J, which is Winslow's functional, discretised
// at the cells' corners as Charakhch'yan & Ivanenko (1997) do: at a corner
// with edges u = r_next - r_m, v = r_prev - r_m,
//     (|u|^2 + |v|^2) / (u x v),
// 2 at a square corner, growing without bound as the corner turns flat or
// the cell shrinks against its neighbours, infinite on a folded corner: a
// barrier that keeps the minimum unfolded (Charakhch'yan & Ivanenko).
//
// W's Hessian is indefinite in places. The convex one: the term is
// 2 + |e|^2/(u x v), e = u - R v (R v = (v_y, -v_x), so u.Rv = u x v),
// and |e|^2/X is convex in (e, X) for X > 0; with e linear in the
// coordinates and X's own second derivative dropped, its Hessian is
// (2/X) sum_k c_k c_k^T, c_k = grad e_k - (e_k/X) grad X: positive
// semidefinite, and exact where e = 0 (a square corner).
#pragma once

#include "operator/variational_cell.hpp"

namespace eg2d {

// Adds w times the sum over the cell's four corners (the cell's corners
// (x[m], y[m]) in its own order) to t: value (infinite on a corner with
// u x v <= 0, whose gradient is left out), gradient, and with `hessians`
// the exact and the convex Hessians.
void add_smoothness_terms(double w, const double x[4], const double y[4], bool hessians, CellTerms &t);

// The same for O's scale-invariant form (variational.hpp): the squared
// cotangent (u.v)^2/(u x v)^2 at each corner; the convex Hessian is its
// Gauss-Newton part 2 grad q grad q^T, q = u.v/(u x v), exact at right angles.
void add_cotangent_terms(double w, const double x[4], const double y[4], bool hessians, CellTerms &t);

// Both terms of F (F.smoothness, F.cotangent) added to t, on a grid whose
// cells turn with F.sense (a clockwise grid is mirrored, x -> -x, so that
// its unfolded corners have u x v > 0).
inline bool has_corner_terms(const Functional &F) { return F.smoothness != 0.0 || F.cotangent != 0.0; }
void add_corner_terms(const Functional &F, const double x[4], const double y[4], bool hessians, CellTerms &t);

// add_corner_terms's value alone (what the line search needs), without the
// gradient or the cell's 8 x 8 arrays.
double corner_terms_value(const Functional &F, const double x[4], const double y[4]);

// What add_corner_terms adds at the cell's corner 0 alone, to the same
// round-off: its gradient and its 2 x 2 blocks of the convex Hessian and,
// with `exact`, of the exact one (h stays 0 without). A node's equation reads
// no more (variational.cpp: the residual the convex block only, the point
// Newton step both), and the three corners that move with the node cost far
// less than the cell's 8 x 8 scatter.
struct NodeTerms {
    double g[2] = {};
    double h[2][2] = {};
    double hc[2][2] = {};
};
NodeTerms corner_node_terms(const Functional &F, const double x[4], const double y[4], bool exact);

}  // namespace eg2d
