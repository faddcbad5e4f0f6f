// A wall layer made before the elliptic solve: rows 1..N above JMIN of an O-
// or C-grid, marched along the wall normals with a first-cell height and a
// geometric growth, then held fixed while the solvers work on the rows above
// it (Grid::hold_rows). Straight normal rays on a thin layer: the cells leave
// the wall at 90 degrees with exactly the asked height and growth, and a sharp
// trailing edge fans out without folding (its normal is the bisector). This
// is the near-wall part of the hybrid grids of Steger & Sorenson (1980) and
// Pointwise: marched where the wall decides the grid, elliptic beyond.
#pragma once
#include <string>
#include <vector>

#include "base/grid.hpp"

namespace eg2d {

struct WallLayerShape {
    int rows = 0;       // rows made (held)
    int asked = 0;      // rows asked for; fewer where a cell would have folded
    int fold_row = -1;  // the row that would have folded, if any
    double growth = 0;  // the growth used (larger than asked where a corner needs it)
    bool hybrid = false;  // rows of the hyperbolic march (hybrid_layer.hpp)
    bool graded = false;
    bool moved_sides = false;
    // The node counts across the layer (nj for walls at JMIN, JMAX; ni for
    // IMIN, IMAX) that would keep its growth within 1.2 (graded_layer.hpp);
    // 0 where it is met or not known.
    int needed_nj = 0, needed_ni = 0;  // nodes of the user's sides moved: put back before the next shape  // lines re-spaced, nothing held (graded_layer.hpp): the start is kept
    std::string note;     // why no layer was made, when one was asked for
};

// The layer rows for an nj-row grid: a third of the rows, at least 1.
int wall_layer_rows(int nj);

// Distances of the geometric layer: d[k] for k = 0..rows, d[0] = 0.
double layer_distance(double first, double growth, int k);

// One-sided geometric distribution of `intervals` cells over `length`, the
// first cell `first`: the ratio solved by bisection (in [0.5, 2]).
double geometric_ratio(double first, double length, int intervals);

// True for an O-grid whose wall has a sharp convex corner (a trailing edge):
// the rows above a thin layer must turn round it within a cell, which the
// elliptic solve above the layer does not yet do robustly (NACA 0012 65x33
// at 1e-3 chord: line SOR and multigrid diverge at the corner, point SOR
// needs 14000 sweeps), so the wall control keeps its Sorenson-type updates
// there. C-grids and smooth bodies get the layer.
bool wall_has_sharp_corner(const Grid &g);

// Marches rows 1..rows (fewer if a cell would fold), holds them, and, with
// `fill_above`, fills the rows above along straight lines to JMAX with the
// geometric continuation of the layer (the start of the elliptic solve). On
// a C-grid the outflow sides' nodes are placed along the sides at the same
// distances (the user's points define the side lines). The grid must be
// initialised (its row 1 tells on which side of the wall the domain is).
WallLayerShape shape_wall_layer(Grid &g, double h, double growth, bool fill_above);

}  // namespace eg2d
