// The graded wall layer of every wall that the hybrid layer (hybrid_layer.hpp)
// does not take: any sides of a single block, alone, opposite or meeting at
// a corner, and an O-grid's JMIN and JMAX together. Before the solve each
// grid line leaving a wall is re-spaced along itself so that its cells
// grade from the wall's first-cell height (geometrically off one wall; from
// both heights, the log of the cell a quadratic, between two: see
// march_schedule.hpp's graded_cells), and the controls Phi, Psi that hold
// each line's spacing (the one-dimensional inversion of Thomas & Middlecoff
// 1980: Psi_j = -(t_{j+1} - 2 t_j + t_{j-1}) / ((t_{j+1} - t_{j-1}) / 2) of
// the line's arc lengths t, Phi likewise along the rows) are taken from
// that start and frozen. The solve then smooths the grid with the spacing
// kept; the wall control's Sorenson-type updates (controls/wall.cpp) add the
// last correction of the height and the angle at the wall. A re-spaced
// start whose cells are near square is kept instead: the controls are
// those that make it an exact solution (invert_controls.hpp), and the
// solve only turns the lines to the wall's normal.
//
// A wall covers the stretches of its side whose patches are of type wall
// (all of it by default); on the other stretches the first cell blends
// geometrically from the wall's height to the spacing of the corner the
// stretch reaches. A side that is no wall and meets a wall keeps its
// points when they already follow the layer, else its nodes are moved
// along it to the layer's spacing, and the shape's note says so.
#pragma once
#include <array>
#include <vector>

#include "base/grid.hpp"
#include "grid/wall_layer.hpp"

namespace eg2d {

// The layer's own figures: the largest ratio of consecutive cells within
// kGradedRows of a wall, and the node count of a wall-normal line that
// would keep it within kGradedGrowth (0 when it is met).
constexpr int kGradedRows = 30;
constexpr double kGradedGrowth = 1.2;

// One family of wall-normal lines (eta lines for JMIN/JMAX walls, xi lines
// for IMIN/IMAX), kept for the second step (reshape_graded_layer).
struct GradedFamily {
    bool columns = true;
    std::vector<std::vector<double>> factor;  // per line, per cell: the shape taken from kept sides
};

struct GradedLayer {
    WallLayerShape shape;          // note: sides re-spaced; growth: the largest ratio
    std::vector<double> phi, psi;  // ni*nj, the frozen background; zero on the boundary
    std::array<std::vector<double>, 4> heights;  // per wall side, each node's first cell (empty: no wall)
    std::vector<GradedFamily> families;
    bool frozen = false;  // the controls are final: no more updates
    bool kept = false;    // the re-spaced start is kept (its controls inverted from it; frozen)
};

// The first-cell height at each node of side s of g (empty: no height
// there): height[s], or the side's heights node by node where the grid has
// them (Grid::wall_node_spacing), on its stretches of type wall (all of it
// when it has none), blended in the log toward a corner's own spacing on
// the rest.
std::vector<double> wall_node_heights(const Grid &g, Side s, const std::array<double, 4> &height);

// The cells of a line of `cells` cells and length `length` off a wall at
// its start (first > 0), its end (last > 0) or both: geometric from one
// wall; from two, each cell the smaller of two geometric series of one
// ratio (march_schedule.hpp's graded_cells where even ratio 1 overfills).
std::vector<double> graded_line_cells(int cells, double first, double last, double length);

// The largest ratio of consecutive cells within kGradedRows of each walled end.
double graded_end_growth(const std::vector<double> &cells, bool from_start, bool from_end);

// height[side] > 0 makes a side a wall (0 or less: not graded). The grid
// must be initialised; its lines are re-spaced in place and the sides that
// meet a wall may move along themselves. Single blocks and O-grids.
GradedLayer shape_graded_layer(Grid &g, const std::array<double, 4> &height);

// The cells line l of a family should have at its length: graded from its
// walls' heights, in the shape of kept sides.
std::vector<double> graded_target_cells(const GradedLayer &layer, const GradedFamily &f, int l, int cells,
                                        double length);

// How much of each of a line's cells belongs to its walls (lo: its first
// end, hi: its last): 1 within kGradedRows cells of a wall, 0 from twice
// that, a smoothstep between.
std::vector<double> wall_shares(int cells, bool lo, bool hi);

// Cells scaled by F^(1 - share) with the F that makes them sum to length:
// the walls' cells keep their heights, the rest take up the length (all in
// proportion when that cannot be done).
std::vector<double> fit_length(std::vector<double> cells, const std::vector<double> &share, double length);

// Each wall's lines turned to its normal near it: all the way at the wall,
// less over the first rows (a smoothstep), keeping each node's distance
// along its line.
void turn_to_normals(Grid &g, const GradedLayer &layer);

// The second step of a start not kept (graded_layer_update.cpp), on g
// solved one multigrid cycle on the one-dimensional controls. Those hold
// each line's spacing as fractions of its length, not its first cell:
// where the solve bends the lines (the rings of an O-grid between an
// ellipse and a circle pull on its radial lines) the first cells drift from
// the height, by 3x at a pipe's wall. So each line of g is re-spaced along
// itself to its target cells near the walls (blended into the solve's
// spacing beyond), turned to the normals, and the controls are replaced by
// those that make g an exact solution; frozen. TMR's bump 177x81 at 4e-6:
// growth 1.1750 (TMR's grid: 1.17507), skewness 14.5 degrees, and the run
// needs no further cycle; re-spaced after two cycles: the same to 0.01.
// Before, 3-8 rescalings of each line's first cell in the one-dimensional
// Psi, one per cycle of the run, grew it by 1.184.
void reshape_graded_layer(Grid &g, GradedLayer &layer);

}  // namespace eg2d
