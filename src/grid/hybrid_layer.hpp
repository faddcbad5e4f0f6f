// The hybrid wall layer (EG2D_PARAM_WALL_LAYER = 2): the hyperbolic march
// (grid/hyperbolic.hpp) from the wall to the user's outer boundary's
// distance; its first two thirds of the rows are held (Grid::hold_rows), and
// the rows above are solved with the Thomas-Middlecoff controls Phi, Psi that
// make the marched grid an exact discrete solution of the controlled Winslow
// equations (NUMERICS.md), frozen for the run. The solve bends the march onto
// the user's outer boundary. The march turns the rows round a sharp trailing
// edge gradually, and the inverted controls carry that turn into the rows
// above, which a control built from the boundaries alone cannot
// (wall_layer.hpp). The marched-then-elliptic construction is Steger &
// Sorenson's (1980) hybrid; controls taken from a given grid are Thompson,
// Warsi & Mastin's (1985) way of reproducing it.
#pragma once
#include <vector>

#include "base/grid.hpp"
#include "base/settings.hpp"
#include "grid/wall_layer.hpp"

namespace eg2d {

struct HybridLayer {
    WallLayerShape shape;
    std::vector<double> phi, psi;  // ni*nj; zero on held rows and boundaries
    double height_error = 0;       // largest |first cell - h| / h over the wall nodes
    double wall_angle = 0;         // largest angle (degrees) of the first line from the wall normal
};

// O- and C-grids. Marches from JMIN (first cell h; the schedule's own
// ratio) to the least distance of the JMAX nodes from the wall nodes,
// retrying with more dissipation while it folds; puts each column's rows
// 1..hybrid_layer_rows(nj) back along it at geometric distances from its
// first height, and holds them; inverts the controls above (kept within
// |Phi|, |Psi| <= 1); with fill_above starts the rows above from the march
// moved onto JMAX. On a C-grid the cut's first heights grow downstream
// (hybrid_cgrid.hpp), the cut is held with the rows, and the outflow sides
// and the far field keep their lines with their nodes moved along them to
// follow the march. Retries, moves and clipping are in shape.note. Throws
// what the march throws (Failure::Folded, Failure::Argument): the grid is
// then unchanged.
HybridLayer shape_hybrid_layer(Grid &g, const Settings &settings, double h, bool fill_above);

// The rows held: two thirds of them (at most nj-3). Measured on NACA 0012
// O-grids with a sharp trailing edge (bench/RESULTS.md): with a third the
// rows just above the layer folded at the trailing edge at 65x33, 129x33
// and 129x65 (first cell 1e-5); with a half or two thirds none did, and two
// thirds converged in the fewest cycles (250x100: 8).
int hybrid_layer_rows(int nj);

}  // namespace eg2d
