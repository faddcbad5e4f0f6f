// Local Newton on a patch (the variational minimiser's nonlinear
// elimination, variational_newton.hpp): V minimised over the unknowns of a
// few nodes with the rest of the grid held, by Newton steps whose system,
// V's exact Hessian restricted to the patch, is solved by conjugate
// gradients preconditioned with symmetric block Gauss-Seidel (on the exact
// Hessian, or the convex one of variational_cell.hpp where the exact one's
// diagonal blocks are not positive definite), each step fold-guarded and
// cut back until V falls (Armijo). Nonlinear elimination in the sense of
// Lanzkron, Rose & Wilkes (1996) and Cai & Li (2011): the few unknowns
// where V is strongly nonlinear are solved for ("eliminated") between the
// global steps, so the global quadratic model is not limited by them.
// Coupled, where point sweeps relax one node at a time: on the swan with a
// large the patch is a strip along the lower side whose nodes move together.
#pragma once
#include <cstddef>
#include <vector>

#include "operator/variational.hpp"
#include "solvers/block_multigrid.hpp"

namespace eg2d {

class Connectivity;

class PatchNewton {
public:
    // Minimises V over the nodes `set` (indices u = i + nc j of `layout`'s
    // grid, unknowns only) of (x, y) on conn's grid, the rest held; at most
    // `steps` Newton steps, stopping once the patch's gradient is below
    // `reduction` times its first. mean: the mean cell area
    // (variational_cell.hpp). Returns the steps taken.
    int solve(const Connectivity &conn, const BlockStencil &layout, const std::vector<std::size_t> &set, double *x,
              double *y, const Functional &F, double mean, int steps, double reduction);

private:
    void build(const Connectivity &conn, const BlockStencil &layout, const std::vector<std::size_t> &set);
    double assemble(const double *x, const double *y, const Functional &F, double mean);
    double energy(const double *x, const double *y, const Functional &F, double mean, double alpha) const;
    double fold_limit(const double *x, const double *y, int orientation) const;
    void multiply(const std::vector<Mat2> &A, const std::vector<Vec2> &v, std::vector<Vec2> &out) const;
    void precondition(const std::vector<Vec2> &r, std::vector<Vec2> &z) const;
    bool direction();  // CG on H d = -g; false if it found no descent

    struct Cell {
        std::size_t k[4];  // the corners' indices in x, y
        int l[4];          // their patch indices, -1 where held
    };
    int ni_ = 0;
    std::vector<std::size_t> nodes_;  // the patch's u
    std::vector<int> near_;           // 9 per patch node: the patch index of each neighbour, -1 if held
    std::vector<Cell> cells_;         // the cells with a corner in the patch
    std::vector<Mat2> H_, C_;         // exact and convex Hessians, 9 blocks per patch node
    std::vector<Mat2> inv_;           // the preconditioner's diagonal blocks inverted
    bool exact_ = false;
    std::vector<Vec2> g_, d_, r_, z_, p_, q_;
};

}  // namespace eg2d
