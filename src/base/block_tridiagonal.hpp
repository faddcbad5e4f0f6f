// Block-tridiagonal kernels with 2x2 blocks: one grid line's (x, y) pairs
// coupled through 2x2 matrices, as the hyperbolic march's implicit layer
// solve needs (Steger & Chaussee 1980). Block Thomas elimination, and the
// periodic (O-grid) system by eliminating the last unknown (a bordered
// system), the block analogue of the cyclic solve in tridiagonal.hpp.
#pragma once
#include <cstddef>
#include <vector>

namespace eg2d {

// [[a, b], [c, d]]
struct Mat2 {
    double a = 0, b = 0, c = 0, d = 0;
};
struct Vec2 {
    double x = 0, y = 0;
};

// Solves A[k] u[k-1] + B[k] u[k] + C[k] u[k+1] = r[k], k = 0..n-1 (A[0] and
// C[n-1] unused); r gets the solution. Needs every pivot block invertible
// (block diagonal dominance); a singular pivot gives non-finite values,
// which callers check. n >= 1. scratch: n blocks, the caller's, kept
// between calls (a march solves one system per layer and sub-step).
void solve_block_tridiagonal2(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r,
                              std::vector<Mat2> &scratch);

// The periodic system: A[0] couples u[0] to u[n-1], C[n-1] couples u[n-1]
// to u[0]. n >= 3. r gets the solution.
void solve_cyclic_block_tridiagonal2(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r);

}  // namespace eg2d
