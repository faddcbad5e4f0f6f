// The hyperbolic march (Steger & Chaussee 1980; Chan & Steger 1992; the grid-generation lecture notes
// sections 2.8-2.10): from the JMIN curve, layer by layer, the grid that is
// orthogonal to the previous layer with the cell areas the marching schedule
// asks for. It fills the whole grid, outer boundary included. The equations,
// the dissipation and the end conditions are in docs/hyperbolic.md.
#pragma once
#include <string>
#include <vector>

#include "base/grid.hpp"
#include "base/settings.hpp"

namespace eg2d {

// Open ends of a single-block or C-grid march (EG2D_MARCH_END_*).
enum class MarchEnd { Free = 0, ConstantX = 1, ConstantY = 2, Splay = 3 };

// Marches from row j = 0 (which must hold the JMIN side) and overwrites
// every other row. O-grids march outward from the closed curve, C-grids
// away from the body, single blocks to the left of JMIN as it runs.
// Throws Failure::Argument for an unreachable schedule, Failure::Folded
// when a layer folds (naming the layer and node).
void hyperbolic_march(Grid &grid, const Settings &settings);

// The march as above, but a layer that folds is not the end while
// `raised` has values left: the march goes back at least 64 layers (to a
// state saved every 32) and goes on from there with the next value of
// `raised` as EG2D_PARAM_MARCH_SMOOTHING. Each resumption is added to
// `note`. Throws Failure::Folded when a layer folds at the last value.
// Measured on the NACA 0012 C-grid 7169x2049 (first cell 1e-7, 500 chords):
// from dissipation 4 the march folded at layer 1758-1806; marched again
// from the wall at 8 the run took about 20 CPU s more than resumed at layer
// 1665-1729 (bench/RESULTS.md).
void hyperbolic_march(Grid &grid, const Settings &settings, const std::vector<double> &raised, std::string &note);

}  // namespace eg2d
