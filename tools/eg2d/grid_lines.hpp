// A grid as the lines a picture draws: its interior grid lines and its
// boundary patches (eg2d_get_patch), each line a stride through the
// coordinate arrays, so a picture of a large grid copies no coordinates.
#pragma once

#include <cstddef>
#include <vector>

typedef struct eg2d_grid eg2d_grid;

namespace eg2dtool {

// How a line is drawn: a grid line (and a cut, which is interior), a
// boundary other than a wall (far field, outflow, ...), or a wall.
enum LineKind { kGridLine = 0, kBoundaryLine = 1, kWallLine = 2 };

struct LineRef {
    LineKind kind;
    std::size_t first, stride;  // node k of the line is first + k * stride
    int count;                  // its nodes
};

struct GridLines {
    int ni = 0, nj = 0;
    std::vector<double> x, y;    // the library's order: node (i, j) at i + ni j
    std::vector<LineRef> lines;  // grid lines first, then boundaries, walls last (drawn on top)
};

// The lines of `grid`; throws Failure with the library's message on an error.
GridLines grid_lines(const eg2d_grid *grid);

}  // namespace eg2dtool
