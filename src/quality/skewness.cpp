// Skewness: the largest deviation of a cell's four corner angles from 90
// degrees. Angles are signed by the grid's orientation (cell.hpp), so a
// folded corner has a negative angle and the cell's skewness exceeds 90.
#include <algorithm>
#include <cmath>

#include "base/cell.hpp"
#include "quality/quality.hpp"

namespace eg2d {

void cell_skewness(const Grid &g, double *out) {
    const int o = grid_orientation(g);
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) {
            const Cell c = Cell::at(g, i, j);
            double s = 0.0;
            for (int m = 0; m < 4; ++m) s = std::max(s, std::fabs(c.corner_angle(m, o) - 90.0));
            out[cell_index(g, i, j)] = s;
        }
}

}  // namespace eg2d
