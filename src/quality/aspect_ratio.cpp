// Aspect ratio: the longer over the shorter of a cell's mean widths along i
// and along j (each the mean of two opposite edges). 1 for a square or a
// rhombus; infinite for a cell with a collapsed direction.
#include <algorithm>
#include <limits>

#include "base/cell.hpp"
#include "quality/quality.hpp"

namespace eg2d {

void cell_aspect_ratio(const Grid &g, double *out) {
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) {
            const Cell c = Cell::at(g, i, j);
            const double a = c.width_i(), b = c.width_j();
            const double lo = std::min(a, b), hi = std::max(a, b);
            out[cell_index(g, i, j)] = lo > 0.0 ? hi / lo : std::numeric_limits<double>::infinity();
        }
}

}  // namespace eg2d
