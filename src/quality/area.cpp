// Cell area (the Jacobian integrated over the cell), signed by the grid's
// orientation so that an inverted cell is negative in either handedness.
#include <algorithm>
#include <limits>

#include "base/cell.hpp"
#include "quality/quality.hpp"

namespace eg2d {

void cell_area(const Grid &g, double *out) {
    const int o = grid_orientation(g);
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) out[cell_index(g, i, j)] = Cell::at(g, i, j).area() * o;
}

}  // namespace eg2d
