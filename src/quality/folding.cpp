// Folded cells and signed areas. A cell's corners in counter-clockwise order
// (i,j), (i+1,j), (i+1,j+1), (i,j+1) each turn by the cross product of the
// two edges leaving it; a folded cell has a corner whose turn has the sign
// opposite to the grid's orientation (the sign of the total area).
#include <algorithm>
#include <limits>

#include "quality/quality.hpp"

namespace eg2d {

FoldSummary fold_summary(const Grid &g) {
    const int ni = g.ni(), nj = g.nj();
    const double *x = g.x.data(), *y = g.y.data();
    auto k = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
    double total = 0.0;
    for (int j = 0; j < nj - 1; ++j)
        for (int i = 0; i < ni - 1; ++i) {
            const std::size_t a = k(i, j), b = k(i + 1, j), c = k(i + 1, j + 1), d = k(i, j + 1);
            total += 0.5 * ((x[c] - x[a]) * (y[d] - y[b]) - (y[c] - y[a]) * (x[d] - x[b]));
        }
    FoldSummary s;
    s.orientation = total < 0.0 ? -1 : 1;
    s.min_area = std::numeric_limits<double>::infinity();
    for (int j = 0; j < nj - 1; ++j)
        for (int i = 0; i < ni - 1; ++i) {
            const std::size_t v[4] = {k(i, j), k(i + 1, j), k(i + 1, j + 1), k(i, j + 1)};
            bool folded = false;
            for (int m = 0; m < 4; ++m) {
                const std::size_t p = v[m], nx = v[(m + 1) % 4], pv = v[(m + 3) % 4];
                const double turn = (x[nx] - x[p]) * (y[pv] - y[p]) - (y[nx] - y[p]) * (x[pv] - x[p]);
                if (turn * s.orientation < 0.0) folded = true;
            }
            const double area =
                0.5 * ((x[v[2]] - x[v[0]]) * (y[v[3]] - y[v[1]]) - (y[v[2]] - y[v[0]]) * (x[v[3]] - x[v[1]]));
            s.min_area = std::min(s.min_area, area * s.orientation);
            if (folded) {
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
