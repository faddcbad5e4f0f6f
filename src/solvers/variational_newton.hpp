// The variational system's minimiser (what EG2D_SOLVER_MULTIGRID runs for
// EG2D_SYSTEM_VARIATIONAL on single blocks and O-grids): Newton's method on
// V = a A/Abar + b S + c O/Abar (operator/variational.hpp) over all the
// unknown nodes at once, with
//   - the exact Hessian and a convex one, assembled cell by cell
//     (operator/variational_cell.hpp), nine-point matrices of 2x2 blocks;
//   - the Newton system solved inexactly (Eisenstat-Walker forcing) by
//     conjugate gradients on the exact Hessian, preconditioned with one
//     Galerkin multigrid V-cycle (block_multigrid.hpp) on the convex one,
//     or after a full step on the exact one where that hierarchy is
//     positive definite at its coarsest level and the direction descends,
//     inside a trust region once a step needed shortening (Steihaug 1983:
//     stopped on its edge, or at a direction of negative curvature followed
//     to it; without a region, truncated Newton: the iterate so far);
//   - a line search on V (Armijo) whose first trial is, under the fold guard
//     (EG2D_PARAM_FOLD_CHECK), at most kToFold of the way to the first
//     corner of any cell turning flat, so no step folds a cell;
//   - the trust region's radius from the steps the line search took and the
//     ratio of V's actual to predicted decrease (update_radius());
//   - nonlinear elimination after each step: Newton steps on the patch of
//     nodes where the direction was largest, the rest held (eliminate(),
//     variational_patch.hpp);
//   - a Levenberg shift mu D (D: the convex Hessian's diagonal) on both
//     matrices after a step that found no descent, shrinking again after
//     full steps; the run notes the first one.
// A fresh start (TFI) is improved first by grid sequencing (sequence()):
// V's minimum on the grids with every 2nd, 4th, ... node, interpolated up,
// so the fine grid needs a few Newton steps where the minimum is benign
// (swan 257^2, a = 3, b = 1: 4 steps). Starting from Winslow's grid instead
// was measured and dropped: on the dome (a = 10, b = 1, 33^2) it ran into
// the fold guard where the TFI start converges in 3 steps, and on the
// course notes' domains at 129^2 it saved no steps.
//
// Why not the FAS point smoother it replaces (bench/RESULTS.md): A and O
// have near-null directions (moves that keep every cell's area or corner),
// which point Gauss-Seidel barely damps; Newton removes them in the linear
// solve, where the Galerkin hierarchy carries them to the coarse levels.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "operator/variational_cell.hpp"
#include "solvers/block_multigrid.hpp"
#include "solvers/newton_progress.hpp"
#include "solvers/solver.hpp"
#include "solvers/variational_patch.hpp"

namespace eg2d {

class VariationalNewton {
public:
    // Grids this minimiser takes: every unknown inside the index rectangle
    // (not a C-grid's wake cut, whose nodes couple across it).
    static bool handles(const Connectivity &c) { return c.extra_unknowns().empty(); }
    // One Newton step (the first after a reset of a fresh start: grid sequencing first).
    void iterate(Problem &p);
    // After the run computed the residual of the step: the fold guard's stall
    // test (throws NotConverged when V's minimum lies beyond a fold; not with
    // a barrier in V, whose minimum is unfolded) and the no-progress tests
    // (neither the residual nor V falling).
    void observe(double residual);
    void reset();

private:
    // One Newton step on (x, y), a grid of conn's shape (p: where to note, or null).
    void step(const Connectivity &conn, double *x, double *y, const Functional &F, Problem *p);
    void restart();  // a new minimisation: forcing, shift and stall test afresh
    void sequence(Problem &p);
    // V's minimum on a grid sequencing level: empty, or why it was given up.
    std::string solve_level(const Connectivity &conn, double *x, double *y, const Functional &F, double extent);
    void layout(const Connectivity &conn);
    double assemble(const double *x, const double *y, const Functional &F);
    double energy(const double *x, const double *y, const Functional &F, double alpha) const;
    double fold_limit(const double *x, const double *y, int orientation) const;
    int solve(const BlockStencil &K, double forcing, bool &negative);
    void eliminate(const Connectivity &conn, double *x, double *y, const Functional &F);
    void update_radius(double alpha, int halvings, bool limited, double rho, double dnorm);

    int ni_ = 0, nc_ = 0, nr_ = 0;
    bool periodic_ = false;
    BlockStencil H_, C_;          // the exact Hessian, the convex one (+ the shift)
    BlockMultigrid mg_;
    PatchNewton patch_;           // nonlinear elimination's local Newton
    std::vector<Vec2> g_, d_, r_, z_, p_, q_;
    std::vector<double> diag_;    // |H|'s diagonal scale per node, for the shift
    double shift_ = 0.0;
    double mean_ = 0.0;           // the mean cell area (variational_cell.hpp)
    double last_gradient_ = -1.0, forcing_ = 0.5;
    bool started_ = false, noted_shift_ = false;
    Functional functional_;    // what the state below was built minimising
    NewtonProgress progress_;  // the stop tests
    bool last_limited_ = false;
    bool last_full_ = false;   // the last step a full one along a direction of positive curvature
    double v_last_ = 0.0;      // V where the last step began
    double radius_ = 0.0;      // the trust region's radius in the norm ||d||_D (infinite: none yet)
    bool boundary_ = false;    // the last direction ended on the trust region's edge
    bool barrier_ = false;  // V has W or O's cotangents: infinite on a flat corner, its minimum unfolded
};

}  // namespace eg2d
