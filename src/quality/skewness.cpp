// Skewness: the largest deviation of a cell's four corner angles from 90
// degrees. Angles are signed by the grid's orientation (cell.hpp), so a
// folded corner has a negative angle and the cell's skewness exceeds 90.
#include <algorithm>
#include <cmath>
#include <limits>

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

// The largest of cell_skewness without an atan2 per corner (the report of a
// 7169x2049 grid spent 4 s in them): an unfolded corner's deviation from 90
// degrees is asin |cos|, which grows with cos^2, so a first pass finds the
// largest cos^2 and a second measures, as cell_skewness does, only the
// corners within rounding of it; folded corners (cross product against the
// orientation) and degenerate ones are measured as they come. The result is
// cell_skewness's largest value to the last bit.
double largest_skewness(const Grid &g) {
    const int o = grid_orientation(g);
    // cos^2 of corner m of c, or -1 for a corner measured at once into
    // `exact`: a folded one, and one whose edge lengths' product is zero or
    // below the normal range (cos^2 would be 0/0 or inexact there).
    auto cos2 = [o](const Cell &c, int m, double *exact) {
        const Cell::Corner k = c.corner(m, o);
        if (k.cross < 0.0 || !(k.lengths2 >= std::numeric_limits<double>::min())) {
            if (exact) *exact = std::max(*exact, std::fabs(c.corner_angle(m, o) - 90.0));
            return -1.0;
        }
        return k.dot * k.dot / k.lengths2;
    };
    double most = -1.0, exact = 0.0;
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) {
            const Cell c = Cell::at(g, i, j);
            for (int m = 0; m < 4; ++m) most = std::max(most, cos2(c, m, &exact));
        }
    double out = exact;
    if (most < 0.0) return out;
    const double near = most * (1.0 - 1e-9);
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) {
            const Cell c = Cell::at(g, i, j);
            for (int m = 0; m < 4; ++m)
                if (cos2(c, m, nullptr) >= near) out = std::max(out, std::fabs(c.corner_angle(m, o) - 90.0));
        }
    return out;
}

}  // namespace eg2d
