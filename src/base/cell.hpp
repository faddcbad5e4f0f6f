// One cell of a grid as its four corners in the cell's own order
// (i,j), (i+1,j), (i+1,j+1), (i,j+1), and the measures every metric family
// shares. Cells are numbered c = i + (ni-1)*j, as eg2d_get_cell_quality returns them.
#pragma once
#include <cmath>
#include <cstddef>

#include "base/grid.hpp"

namespace eg2d {

struct Cell {
    double x[4], y[4];

    static Cell at(const Grid &g, int i, int j) {
        const std::size_t ni = static_cast<std::size_t>(g.ni());
        const std::size_t k[4] = {i + ni * j, i + 1 + ni * j, i + 1 + ni * (j + 1), i + ni * (j + 1)};
        Cell c;
        for (int m = 0; m < 4; ++m) {
            c.x[m] = g.x[k[m]];
            c.y[m] = g.y[k[m]];
        }
        return c;
    }
    // Area from the cross product of the diagonals: positive for a
    // counter-clockwise cell, zero for a symmetric bow-tie.
    double area() const { return 0.5 * ((x[2] - x[0]) * (y[3] - y[1]) - (y[2] - y[0]) * (x[3] - x[1])); }
    double edge(int m) const {
        const int n = (m + 1) % 4;
        return std::hypot(x[n] - x[m], y[n] - y[m]);
    }
    // Mean length of the two edges along i (0-1 and 3-2) and along j (0-3 and 1-2).
    double width_i() const { return 0.5 * (edge(0) + edge(2)); }
    double width_j() const { return 0.5 * (edge(1) + edge(3)); }
    // The edges from corner m to the next and the previous corner: their
    // cross product (signed by the grid's orientation), dot product and
    // product of squared lengths.
    struct Corner {
        double cross, dot, lengths2;
    };
    Corner corner(int m, int orientation) const {
        const int n = (m + 1) % 4, p = (m + 3) % 4;
        const double ax = x[n] - x[m], ay = y[n] - y[m], bx = x[p] - x[m], by = y[p] - y[m];
        return {(ax * by - ay * bx) * orientation, ax * bx + ay * by, (ax * ax + ay * ay) * (bx * bx + by * by)};
    }
    // The angle at corner m between the edges to the next and the previous
    // corner, in degrees, signed by the grid's orientation: in (0, 180) at a
    // corner that turns with the grid, negative at a folded corner.
    double corner_angle(int m, int orientation) const {
        const Corner k = corner(m, orientation);
        // Collinear edges (a straight-through corner, 180 degrees) give a zero
        // cross product that may carry a sign: atan2(-0, -1) is -180, which
        // would read as a folded corner (skewness 270). A zero turn is no fold.
        return std::atan2(k.cross == 0.0 ? 0.0 : k.cross, k.dot) * (180.0 / 3.14159265358979323846);
    }
};

// Number of cells and the index of cell (i, j).
inline std::size_t cell_count(const Grid &g) {
    return static_cast<std::size_t>(g.ni() - 1) * static_cast<std::size_t>(g.nj() - 1);
}
inline std::size_t cell_index(const Grid &g, int i, int j) {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(g.ni() - 1) * static_cast<std::size_t>(j);
}

}  // namespace eg2d
