// Folded cells and the grid's orientation (folds.hpp).
#include "base/folds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "base/plane.hpp"

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

int boundary_orientation(const Grid &g) {
    // An O-grid's JMIN curve turning counter-clockwise has the domain on its
    // right: with eta outward, J = r_xi x r_eta < 0.
    if (g.topology() == Topology::O) return row_signed_area(g, 0) >= 0.0 ? -1 : 1;
    return ring_signed_area(g) >= 0.0 ? 1 : -1;
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

bool has_folds(const Grid &g) {
    // Every corner turning one way leaves the total area that way: none is
    // folded whichever the orientation; corners turning both ways fold a
    // cell against either. Zero turns fold nothing, as in is_folded.
    bool plus = false, minus = false;
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) {
            const Cell c = Cell::at(g, i, j);
            for (int m = 0; m < 4; ++m) {
                const double turn = c.corner(m, 1).cross;
                plus = plus || turn > 0.0;
                minus = minus || turn < 0.0;
            }
            if (plus && minus) return true;
        }
    return false;
}

double row_signed_area(const Grid &g, int j) {
    // Row j of an O-grid ends on a copy of its first node: the closing edge adds nothing.
    const std::size_t row = static_cast<std::size_t>(g.ni()) * j;
    return 0.5 * shoelace(g.x.data() + row, g.y.data() + row, static_cast<std::size_t>(g.ni()));
}

double ring_signed_area(const Grid &g) {
    const int ni = g.ni(), nj = g.nj();
    auto at = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
    double a = 0.0;
    auto edge = [&](std::size_t p, std::size_t q) { a += g.x[p] * g.y[q] - g.x[q] * g.y[p]; };
    for (int i = 0; i + 1 < ni; ++i) edge(at(i, 0), at(i + 1, 0));
    for (int j = 0; j + 1 < nj; ++j) edge(at(ni - 1, j), at(ni - 1, j + 1));
    for (int i = ni - 1; i > 0; --i) edge(at(i, nj - 1), at(i - 1, nj - 1));
    for (int j = nj - 1; j > 0; --j) edge(at(0, j), at(0, j - 1));
    return 0.5 * a;
}

double boundary_area(const Grid &g) {
    if (g.topology() == Topology::O)
        return std::fabs(std::fabs(row_signed_area(g, g.nj() - 1)) - std::fabs(row_signed_area(g, 0)));
    return std::fabs(ring_signed_area(g));
}

}  // namespace eg2d
