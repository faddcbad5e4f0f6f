// What the hybrid wall layer (hybrid_layer.hpp) does on a C-grid beyond an
// O-grid's: the cut's graded first cells, and the sides the march's ends
// meet (the outflow sides, the far field), whose lines are kept and whose
// nodes are re-spaced to follow the march.
#pragma once
#include <vector>

#include "base/grid.hpp"

namespace eg2d {

// First-cell heights along JMIN (ni values): h on the body; on the cut,
// h (ds / ds_te)^(1/2), ds the cut's spacing at the node and ds_te its
// spacing at the trailing edge, so the cut's normal spacing grows
// downstream. The square root: with ds / ds_te itself (the cells keeping
// the trailing edge's aspect ratio) the cells between the trailing edge's
// column and the first cut columns reached 54-61 degrees of skew on NACA
// 0012 385x97 to 500 chords and 769x193; with the root 36-43.
std::vector<double> cut_first_heights(const Grid &g, double h);

// Side i (0 or ni-1) of g keeps its line; its nodes move along it: rows up
// to `rows` at the distances of the march m's column i, the rows above at
// that column's arc-length fractions over the rest of the line.
void place_outflow_side(Grid &g, const Grid &m, int i, int rows);

// JMAX keeps its line; its nodes between the ends move to the points of the
// line nearest to the march m's last row, kept in order (O-grids too: the
// ends are the cut's node). Returns the largest move over the line's length.
double respace_far_field(Grid &g, const Grid &m);

}  // namespace eg2d
