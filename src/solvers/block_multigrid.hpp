// Linear multigrid for a symmetric nine-point matrix of 2x2 blocks on a
// structured grid (the variational system's Hessian: every term of V couples
// a node to its eight neighbours, x and y together): the preconditioner of
// the Newton minimiser's conjugate gradients (variational_newton.hpp).
//
// Coarse matrices are Galerkin products P^T A P with P bilinear
// interpolation (every other node per direction, the last kept; a direction
// of fewer than 5 nodes, or 8 periodic ones, is not coarsened), so they hold
// the fine matrix's variable coefficients (cells of any shape, the A and O
// terms' anisotropy) with no rediscretisation, and stay nine-point. One
// application is a V(1,1) cycle from zero with forward block Gauss-Seidel
// before and backward after, and an exact (Cholesky) solve on the coarsest
// level: a symmetric positive definite operator when A is, as CG needs.
#pragma once
#include <cstddef>
#include <vector>

#include "base/block_tridiagonal.hpp"

namespace eg2d {

// nc x nr nodes u = i + nc*j, periodic in i or not. Node u's nine blocks are
// a[9u + 3(dj+1) + (di+1)], the coupling to node (i+di, j+dj). A node that
// is not an unknown has the identity on the diagonal and no coupling, and
// no unknown couples to it.
struct BlockStencil {
    int nc = 0, nr = 0;
    bool periodic = false;
    std::vector<char> unknown;
    std::vector<Mat2> a;

    void resize(int columns, int rows, bool periodic_i);
    std::size_t nodes() const { return static_cast<std::size_t>(nc) * nr; }
    Mat2 &at(std::size_t u, int di, int dj) { return a[9 * u + 3 * (dj + 1) + (di + 1)]; }
    const Mat2 &at(std::size_t u, int di, int dj) const { return a[9 * u + 3 * (dj + 1) + (di + 1)]; }
    // Column i + di with the periodic wrap (the node itself off a
    // non-periodic edge: its block there is 0).
    int column(int i, int di) const {
        const int c = i + di;
        if (periodic) return c < 0 ? c + nc : c >= nc ? c - nc : c;
        return c < 0 || c >= nc ? i : c;
    }
    // y = A x.
    void multiply(const Vec2 *x, Vec2 *y) const;
};

class BlockMultigrid {
public:
    // Builds the hierarchy of A (kept by reference: it must outlive the
    // preconditioner's use). False if the coarsest matrix is not positive
    // definite (then A is not either).
    bool setup(const BlockStencil &A);
    // z = one V-cycle applied to r (zero start).
    void apply(const Vec2 *r, Vec2 *z);
    int levels() const { return static_cast<int>(levels_.size()); }

    struct Axis {  // fine node f gets w0 of coarse i0 and w1 of coarse i1 (w1 = 0: one only)
        int fine = 0, coarse = 0;
        std::vector<int> i0, i1, at;  // at: the fine index of each coarse node
        std::vector<double> w0, w1;
    };

private:
    struct LevelData {
        BlockStencil own;           // the Galerkin matrix (coarse levels; level 0 uses the caller's)
        Axis ai, aj;                // this level's nodes in the finer one
        std::vector<Vec2> b, x, r;  // right-hand side, iterate, residual
    };
    const BlockStencil &matrix(std::size_t l) const { return l == 0 ? *fine_ : levels_[l].own; }
    void cycle(std::size_t l);
    bool factor_coarsest();
    void solve_coarsest();

    const BlockStencil *fine_ = nullptr;
    std::vector<LevelData> levels_;
    std::vector<std::size_t> dense_index_;  // coarsest: unknown number per node (or -1)
    std::vector<double> chol_;              // coarsest: its dense Cholesky factor
    std::size_t dense_n_ = 0;
};

}  // namespace eg2d
