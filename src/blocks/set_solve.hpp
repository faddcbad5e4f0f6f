// Solving a set of blocks as one grid (composite.hpp) with block 0's
// solver (multigrid over the set, set_multigrid.hpp; point or line SOR;
// the nested iteration's coarse-to-fine start, then point SOR) and
// settings (tolerance, iteration limit, stall window, relaxation, the
// multigrid cycle), each block's grid receiving its part.
#pragma once
#include <functional>
#include <string>

#include "blocks/block_set.hpp"
#include "blocks/set_wall_layer.hpp"

namespace eg2d {

struct SetRun {
    long iterations = 0;
    double residual = 0.0;
    long unknowns = 0;
    double omega = 0.0;  // point SOR's factor at the start (multigrid: 1)
    int levels = 1;      // multigrid's levels over the set
    std::string note;  // how the run ended, for the API's events
    SetLayerFigures layer;  // the graded wall layer (lines 0: none)
};

// Checks the set (BlockSet::check), starts each block not yet initialised
// from its TFI grid, and iterates to block 0's tolerance. Throws
// NotConverged (limit or stall; the blocks keep the last iterate),
// Diverged (the blocks unchanged) or Interrupted (the monitor, called with
// the iteration count and residual, returned true; iterations kept).
// `run` follows the run as it goes, so it says how far a failed one got.
void solve_set(BlockSet &set, const std::function<bool(long, double)> &monitor, SetRun &run);

}  // namespace eg2d
