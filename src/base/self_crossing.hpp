// Where a boundary crosses itself. A figure eight, a side folded across
// another, an O-grid's inner curve through its outer one: no grid fits
// inside such a boundary, and a solve would only report folds at the end.
// Segments that merely touch (neighbours at their shared node, the two
// sides of a C-grid's wake cut lying on each other) do not count: only a
// proper crossing, each segment's ends strictly on both sides of the other
// (two lines that cross exactly at a node of each are not caught).
#pragma once
#include "base/grid.hpp"

namespace eg2d {

struct BoundaryCrossing {
    bool found = false;
    Side side_a = Side::JMin, side_b = Side::JMin;  // the sides of the two segments
    int a = 0, b = 0;  // each segment's first node along its side (the segment is a..a+1)
    double x = 0.0, y = 0.0;  // where they cross
};

// The first crossing found on the boundary as it stands in g.x, g.y (the
// ring of a single block or C-grid; an O-grid's JMIN and JMAX curves, with
// each other too). Sorted by x and swept: about n log n for n boundary
// segments unless many segments overlap in x (0.6 ms for two 4000-point
// curves of an O-grid).
BoundaryCrossing find_boundary_crossing(const Grid &g);

}  // namespace eg2d
