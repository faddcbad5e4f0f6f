// Orientation and folding of a grid's cells: what the run, the solvers'
// divergence checks and the quality metrics all ask of a grid.
#pragma once
#include "base/cell.hpp"
#include "base/grid.hpp"

namespace eg2d {

// Orientation and folding of the cells (i, j), i < ni-1, j < nj-1.
struct FoldSummary {
    int orientation = 1;      // +1 right-handed (counter-clockwise cells), -1 left-handed
    long folded = 0;          // cells with a corner turning against the orientation
    int first_i = -1, first_j = -1;  // the first folded cell in storage order
    double min_area = 0.0;    // smallest cell area times the orientation
};

FoldSummary fold_summary(const Grid &grid);
// Whether any cell is folded (fold_summary's folded > 0) in one pass: some
// corner turns one way and some the other.
bool has_folds(const Grid &grid);

// +1 for a right-handed grid (total area positive), -1 for a left-handed one.
int grid_orientation(const Grid &g);

// The area the boundary encloses, >= 0: the shoelace area of the ring
// JMIN, IMAX, JMAX, IMIN (a C-grid's cut, run both ways, cancels); on an
// O-grid the area between the outer curve (JMAX) and the inner one (JMIN).
double boundary_area(const Grid &g);
// The signed shoelace areas behind it: of row j as a closed curve (an
// O-grid's JMIN or JMAX), and of the boundary ring, positive counter-clockwise.
double row_signed_area(const Grid &g, int j);
double ring_signed_area(const Grid &g);
// J's sign from the boundary alone (the interior may be anything, e.g.
// folded during a run): the turn of the boundary ring; on an O-grid the
// JMIN curve's, whose counter-clockwise turn means J < 0 (eta outward, the
// domain on its right). Zero area counts as right-handed (O: left-handed).
int boundary_orientation(const Grid &g);

// A folded cell has a corner whose turn (the cross product of the two edges
// leaving it) has the sign opposite to the grid's orientation.
bool is_folded(const Cell &c, int orientation);

}  // namespace eg2d
