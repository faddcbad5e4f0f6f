// Folded cells and the grid's orientation (folds.hpp).
#include "base/folds.hpp"

#include <algorithm>
#include <limits>

namespace eg2d {

bool is_folded(const Cell &c, int orientation) {
    for (int m = 0; m < 4; ++m) {
        const int n = (m + 1) % 4, p = (m + 3) % 4;
        const double turn = (c.x[n] - c.x[m]) * (c.y[p] - c.y[m]) - (c.y[n] - c.y[m]) * (c.x[p] - c.x[m]);
        if (turn * orientation < 0.0) return true;
    }
    return false;
}
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

}  // namespace eg2d
