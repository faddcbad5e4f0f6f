// The variational system (EG2D_SYSTEM_VARIATIONAL; the grid-generation lecture
// notes, "Variational methods"): the grid minimises over its unknown nodes
//
//   V = a A/Abar + b S + c O/Abar
//   S = sum over the grid's edges pq of |r_q - r_p|^2
//   A = sum over the cells of area^2,  area = (r2 - r0) x (r3 - r1) / 2
//   O = sum over the cells, over each cell's four corners m, of
//       ((r_next - r_m) . (r_prev - r_m))^2
//
// plus d Abar/4 W, W Brackbill & Saltzman's (1982) smoothness integral (Winslow's
// functional) summed over the cells' corners, (|u|^2 + |v|^2)/(u x v) at a
// corner with edges u, v (Charakhch'yan & Ivanenko 1997; smoothness_cell.hpp):
// a barrier against folded and collapsed cells, which A and O alone do not
// have (O's dot products fall as a cell shrinks, so O's minimum on the swan
// and the dome collapses the cells at their non-right corners;
// bench/RESULTS.md). With EG2D_PARAM_VARIATIONAL_ORTHOGONALITY_FORM 1, c O/Abar
// is replaced by c Abar O', O' = the sum of the corners' squared cotangents
// (u.v)^2/(u x v)^2 (g12^2/g), scale-invariant like the orthogonality
// functional g12^2/(g11 g22) (Knupp & Steinberg 1993; Farrashkhalvat & Miles
// 2003): every corner weighs alike, where the dot products weigh it by its
// edges' lengths^4 and so leave small cells' angles nearly free.
//
// with every physical edge and cell counted once (an O-grid's cut column and
// a C-grid's wake are one set of points: Connectivity::stencil). Abar is the
// mean cell area (enclosed area / number of cells): it makes each term a
// length squared, so a, b, c are dimensionless and their balance is the same
// at any resolution and on every multigrid level.
//
// The equations at an unknown node (operator.hpp's node_equation) are the
// Euler-Lagrange equations: L(r) = -(dV/dr)/2 and diag = trace(H)/4, with H
// the node's 2x2 block of V's Hessian (its Gauss-Newton part). With a = c = 0
// and b = 1 that is the five-point Laplace operator, L = (sum of the four
// neighbours) - 4 r and diag = 4: S's minimiser is the Amsden-Hirt grid.
#pragma once

namespace eg2d {

struct Functional {
    double area = 0.0;           // a / Abar
    double spacing = 1.0;        // b
    double orthogonality = 0.0;  // c / Abar
    double smoothness = 0.0;     // d Abar / 4 (on a grid of squares, d W = d S)
    double cotangent = 0.0;      // c Abar: O's scale-invariant form (then orthogonality is 0)
    int sense = 1;               // the boundary's orientation (+1, -1), for the corner terms
    // The fold guard: the grid's orientation (+1 or -1, as folds.hpp's), or 0
    // for none. With a guard, a node step that would turn a corner of a cell
    // round the node against it (or make it flat) is halved up to three
    // times and then refused (operator.hpp's relax_variational).
    int orientation = 0;
};

// The functional with weights a, b, c on a grid whose mean cell area is
// mean_cell_area (> 0) and d the smoothness term's.
inline Functional make_functional(double a, double b, double c, double d, bool cotangents, double mean_cell_area,
                                  int orientation) {
    Functional f;
    f.area = a / mean_cell_area;
    f.spacing = b;
    (cotangents ? f.cotangent : f.orthogonality) = cotangents ? c * mean_cell_area : c / mean_cell_area;
    f.smoothness = 0.25 * d * mean_cell_area;
    f.orientation = orientation;
    return f;
}

// The same functional's weights on a level with `cell_ratio` times the
// cells (its mean cell area 1/cell_ratio times this one's).
inline void scale_weights(Functional &f, double cell_ratio) {
    f.area *= cell_ratio;
    f.orthogonality *= cell_ratio;
    f.smoothness /= cell_ratio;
    f.cotangent /= cell_ratio;
}

// The same functional on a level of the same domain with `cell_ratio` times
// the cells (a coarse level: < 1): its mean cell area is 1/cell_ratio times
// larger. Coarse levels get no fold guard (their folds are the coarse
// representation's; the corrections they send up are guarded on the grid).
inline Functional coarsened(Functional f, double cell_ratio) {
    scale_weights(f, cell_ratio);
    f.orientation = 0;
    return f;
}

}  // namespace eg2d
