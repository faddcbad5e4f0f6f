// Incomplete-LU smoothing of the FAS multigrid on single-block grids: the
// frozen-coefficient (Picard) nine-point operator of the line systems
// (line_relax.hpp) with the cross-derivative -2 beta r_xieta included,
// factorised incompletely on its own nine-point pattern (ILU(0)), and the grid
// moved by the solution d of L U d = -R. One sweep in each of two orderings
// (i ascending, then i descending, both j ascending) makes the couplings along
// either diagonal implicit (Wesseling, "An introduction to multigrid methods",
// 1992, ch. 7: alternating nine-point ILU is the robust smoother for the
// rotated anisotropic operator).
//
// Why (measured with build/bench/eg2d_bench and the per-cycle residuals): on
// strongly skewed cells (beta^2/(alpha gamma) near 1: the swan's 153-degree
// corner, the dome's top corners, 0.9-0.95 over a region a fixed fraction of
// the grid wide) the error a cycle with the line smoother leaves is made of
// "characteristic" components, smooth along the skewed direction and
// oscillating across it. The line smoother does not damp them (the
// cross-derivative couples only neighbouring lines, explicitly) and the
// rediscretised coarse grid corrects them by a factor of about 2 (dome 513^2
// with 8 pre-smoothing sweeps: the coarse-grid correction raised the largest
// residual from 1.5e-9 to 3.3e-9), so the per-cycle factor grew with the grid
// (swan 0.09 at 129^2 to 0.19 at 1025^2, dome 0.17 to 0.29). The ILU sweeps
// damp them; see multigrid_smoother.cpp for the numbers.
#pragma once
#include <vector>

#include "operator/operator.hpp"
#include "operator/system.hpp"

namespace eg2d {

// The upper factor U (the reciprocal of its diagonal, uc, and the four upper
// couplings) and the forward-substitution result z, per node; sized on first use.
struct IluWork {
    std::vector<double> uc, ue, unw, un, une, zx, zy;
};

// One ILU correction of the unknowns [i_begin, i_end) x [j_begin, j_end) of a
// single-block level (no periodic wrap, no cut: multigrid_smoother.cpp uses
// it only there). mirror = false: i ascending within j ascending; true: i
// descending.
void ilu_sweep(System system, const Level &L, bool mirror, double omega, IluWork &w);

}  // namespace eg2d
