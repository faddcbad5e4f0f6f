// The variational system (EG2D_SYSTEM_VARIATIONAL; the grid-generation lecture
// notes, "Variational methods"): the grid minimises over its unknown nodes
//
//   V = a A/Abar + b S + c O/Abar
//   S = sum over the grid's edges pq of |r_q - r_p|^2
//   A = sum over the cells of area^2,  area = (r2 - r0) x (r3 - r1) / 2
//   O = sum over the cells, over each cell's four corners m, of
//       ((r_next - r_m) . (r_prev - r_m))^2
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
    // The fold guard: the grid's orientation (+1 or -1, as folds.hpp's), or 0
    // for none. With a guard, a node step that would turn a corner of a cell
    // round the node against it (or make it flat) is halved up to three
    // times and then refused (operator.hpp's relax_variational).
    int orientation = 0;
};

// The functional with weights a, b, c on a grid whose mean cell area is
// mean_cell_area (> 0).
inline Functional make_functional(double a, double b, double c, double mean_cell_area, int orientation) {
    Functional f;
    f.area = a / mean_cell_area;
    f.spacing = b;
    f.orthogonality = c / mean_cell_area;
    f.orientation = orientation;
    return f;
}

// The same functional on a level of the same domain with `cell_ratio` times
// the cells (a coarse level: < 1): its mean cell area is 1/cell_ratio times
// larger. Coarse levels get no fold guard (their folds are the coarse
// representation's; the corrections they send up are guarded on the grid).
inline Functional coarsened(Functional f, double cell_ratio) {
    f.area *= cell_ratio;
    f.orthogonality *= cell_ratio;
    f.orientation = 0;
    return f;
}

}  // namespace eg2d
