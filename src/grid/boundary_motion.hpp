// A boundary whose nodes move during the run (a sliding side). The Generator
// applies every motion after each solver iteration, so all solvers get it.
#pragma once
#include "base/grid.hpp"

namespace eg2d {

class BoundaryMotion {
public:
    virtual ~BoundaryMotion() = default;
    virtual Side side() const = 0;
    // Moves the side's nodes (never the corners) from the grid as it is.
    virtual void apply(Grid &grid) const = 0;
    // Back to the state the side was set with, for a new start grid
    // (eg2d_initialize restores the side's points too).
    virtual void restart() const {}
};

}  // namespace eg2d
