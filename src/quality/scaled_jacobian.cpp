// Scaled Jacobian: the smallest over a cell's four corners of the cross
// product of the corner's two edges over the product of their lengths, the
// sine of the corner angle: the quadrilateral scaled Jacobian of the Verdict
// library (Stimpson et al. 2007), which VTK's vtkMeshQuality computes. 1 for
// a rectangle, 0 for a corner with a zero-length edge; signed by the grid's
// orientation (cell.hpp), so it is negative in a folded cell, where Verdict,
// which orients each cell by itself, can read a convex cell turned over as
// unfolded.
#include <algorithm>
#include <cmath>
#include <limits>

#include "base/cell.hpp"
#include "base/folds.hpp"
#include "base/grid.hpp"

namespace eg2d {

void cell_scaled_jacobian(const Grid &g, double *out) {
    const int o = grid_orientation(g);
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) {
            const Cell c = Cell::at(g, i, j);
            double least = 1.0;
            for (int m = 0; m < 4; ++m) {
                const Cell::Corner k = c.corner(m, o);
                // lengths2 below the normal range: an edge of (nearly) no length
                least = std::min(least, k.lengths2 >= std::numeric_limits<double>::min() ? k.cross / std::sqrt(k.lengths2) : 0.0);
            }
            out[cell_index(g, i, j)] = least;
        }
}

}  // namespace eg2d
