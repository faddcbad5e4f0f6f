// Folded cells and signed areas. A cell's corners in counter-clockwise order
// (i,j), (i+1,j), (i+1,j+1), (i,j+1) each turn by the cross product of the
// two edges leaving it; a folded cell has a corner whose turn has the sign
// opposite to the grid's orientation (the sign of the total area).
#include <algorithm>
#include <limits>

#include "quality/cell.hpp"
#include "quality/quality.hpp"

namespace eg2d {

namespace {
bool is_folded(const Cell &c, int orientation) {
    for (int m = 0; m < 4; ++m) {
        const int n = (m + 1) % 4, p = (m + 3) % 4;
        const double turn = (c.x[n] - c.x[m]) * (c.y[p] - c.y[m]) - (c.y[n] - c.y[m]) * (c.x[p] - c.x[m]);
        if (turn * orientation < 0.0) return true;
    }
    return false;
}
}  // namespace

int grid_orientation(const Grid &g) {
    double total = 0.0;
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) total += Cell::at(g, i, j).area();
    return total < 0.0 ? -1 : 1;
}

FoldSummary fold_summary(const Grid &g) {
    FoldSummary s;
    s.orientation = grid_orientation(g);
    s.min_area = std::numeric_limits<double>::infinity();
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) {
            const Cell c = Cell::at(g, i, j);
            s.min_area = std::min(s.min_area, c.area() * s.orientation);
            if (is_folded(c, s.orientation)) {
                if (s.folded == 0) {
                    s.first_i = i;
                    s.first_j = j;
                }
                ++s.folded;
            }
        }
    return s;
}

void cell_folded(const Grid &g, double *out) {
    const int o = grid_orientation(g);
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) out[cell_index(g, i, j)] = is_folded(Cell::at(g, i, j), o) ? 1.0 : 0.0;
}

}  // namespace eg2d
