// A copy of a grid's coordinates to go back to: the run's last good grid,
// a multigrid cycle undone, a coarse-to-fine start dropped. Restored by
// copying into the grid's own arrays (never swapped): solvers keep pointers
// into them.
#pragma once
#include <algorithm>
#include <vector>

#include "base/grid.hpp"

namespace eg2d {

struct GridSnapshot {
    std::vector<double> x, y;

    void take(const Grid &g) {
        x.assign(g.x.begin(), g.x.end());
        y.assign(g.y.begin(), g.y.end());
    }
    void restore(Grid &g) const {
        std::copy(x.begin(), x.end(), g.x.begin());
        std::copy(y.begin(), y.end(), g.y.begin());
    }
};

}  // namespace eg2d
