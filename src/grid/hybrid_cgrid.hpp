// What the hybrid wall layer (hybrid_layer.hpp) does on a C-grid beyond an
// O-grid's: the cut's graded first cells, and the sides the march's ends
// meet (the outflow sides, the far field), whose lines are kept and whose
// nodes are re-spaced to follow the march.
#pragma once
#include <vector>

#include "base/grid.hpp"
#include "base/polyline.hpp"  // Vec2

namespace eg2d {

// First-cell heights along JMIN of the march m (ni values): h on the body;
// on the cut, h up to a small distance from the trailing edge (a few
// hundredths of the thickness of the layer of `rows` rows there), then
// growing as the cube of the cut's spacing over its spacing at that
// distance. The held rows' cells (respace_layer) keep them only while they
// need not shrink, so in the far wake the heights are the largest that do
// not, and the columns there have one shape.
std::vector<double> cut_first_heights(const Grid &m, double h, int rows);

// Column i of m, rows 0..rows, as the line its held rows are put back on
// (along: its cut distance, thickness: layer_thickness, both computed once
// per layer by the caller): on the cut, moved towards the straight segment between its ends, fully
// a few layer thicknesses from the trailing edge. The march's cut columns
// bend near the outflow sides, which the march keeps straight, and rows
// put on bent columns beside straight ones differ in shape from column to
// column (OpenFOAM's non-orthogonality 86-90 degrees at the outflow side
// of NACA 0012 385x97); straightened all along, the cut column beside the
// trailing edge nearly crossed the trailing edge's (wake skew 89 degrees
// at 385x97 to 500 chords).
std::vector<Vec2> straightened_column(const Grid &m, int i, int rows, double along, double thickness);

// Each JMIN node's distance from the trailing edge along a C-grid's cut (0
// on the body and on other topologies): straightened_column's `along`.
std::vector<double> cut_distances(const Grid &m);
// The length of the trailing edge's column of m up to row `rows`: the held
// layer's thickness there, straightened_column's `thickness`.
double layer_thickness(const Grid &m, int rows);

// Side i (0 or ni-1) of g keeps its line; its nodes move along it: rows up
// to `rows` at the distances of the march m's column i, the rows above at
// that column's arc-length fractions over the rest of the line.
void place_outflow_side(Grid &g, const Grid &m, int i, int rows);

// JMAX keeps its line; its nodes between the ends move to the points of the
// line nearest to the march m's last row, kept in order (O-grids too: the
// ends are the cut's node). Returns the largest move over the line's length.
double respace_far_field(Grid &g, const Grid &m);

}  // namespace eg2d
