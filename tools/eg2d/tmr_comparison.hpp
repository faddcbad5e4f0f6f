// The airfoil command's comparison of a C-grid with NASA's Turbulence
// Modeling Resource (TMR) NACA 0012 C-grid family (Rumsey, NASA Langley,
// turbmodels.larc.nasa.gov): seven nested levels 7169x2049 ... 113x33, far
// field about 500 chords, 4097 points on the airfoil and 1537 on each side
// of the wake at the finest, first cell 1e-7 chord growing by about 1.02,
// leading-edge spacing 1.25e-5 chord. Each coarser TMR level is every other
// point of the next, so level k (2^k times coarser) has 4096/2^k + 1 points
// on the airfoil, 1536/2^k + 1 on each wake side, and a first cell of the
// sum of its first 2^k finest cells.
#pragma once
#include <eg2d.h>

#include <string>

namespace eg2dtool {

// The TMR level of a C-grid of ni x nj nodes (0 the finest), or -1 when the
// size is none of the seven.
int tmr_level(int ni, int nj);

// A text table, figure by figure, of the published TMR level against the
// grid g (ni x nj, `wake` nodes on each side of the cut beside the trailing
// edge's, far field asked `farfield` chords, `written_below` coarser levels
// of its family written); empty when tmr_level is -1.
std::string tmr_comparison(const eg2d_grid *g, int ni, int nj, int wake, double farfield, int written_below);

}  // namespace eg2dtool
