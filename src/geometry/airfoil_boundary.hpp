// The boundary of an airfoil grid (eg2d_set_airfoil): an O- or C-grid round
// a section given as a curve from its trailing edge along the lower surface
// to the leading edge and back (eg2d_curve_naca4, eg2d_curve_read_airfoil),
// as Construct2D's front end makes it: the section re-panelled with chosen
// leading- and trailing-edge spacings, an open trailing edge kept as a blunt
// base (a wall) or sharpened, a far field some chords out and, on a C-grid,
// a wake cut along the chord line whose spacing grows from the trailing
// edge's to the outflow.
#pragma once
#include "base/grid.hpp"
#include "geometry/curve.hpp"

namespace eg2d {

enum class TrailingEdge { Blunt = 0, Sharpen = 1 };  // EG2D_AIRFOIL_TE_*

struct AirfoilSpec {
    Topology topology = Topology::C;
    double farfield = 100;     // chords: the far field's least distance from the section
    double le_spacing = 0;     // chords; 0: automatic
    double te_spacing = 0;     // chords; 0: automatic
    int wake = 0;              // C-grid: cut nodes a side (the trailing edge's index); 0: automatic
    TrailingEdge trailing_edge = TrailingEdge::Blunt;
    // O-grid: a sharp trailing edge (or one sharpened) cut back to a straight
    // base this many chords thick (EG2D_PARAM_AIRFOIL_O_TE_BASE); 0 keeps
    // the edge a single node.
    double o_te_base = 5e-5;
};


// The boundary ring of an ni x nj grid (ni*nj arrays, Fortran order; only
// the ring is written). Throws Argument for a section, size or setting it
// cannot make (with the value and what would do).
void airfoil_boundary(const ArcLength &section, const AirfoilSpec &spec, int ni, int nj, std::vector<double> &x,
                      std::vector<double> &y);

// The automatic C-grid cut: about 0.21 (ni-1) nodes a side (the ratio of
// NASA's Turbulence Modeling Resource NACA 0012 family, 1536 of 7168), a
// multiple of the largest power of two up to 64 that divides (ni-1)/2 and
// keeps it within 0.02 (ni-1) of that, so that every-other-node coarsenings
// keep the trailing edge on a node (385: 80; 1793: 384; 257: 56).
int automatic_wake(int ni);

}  // namespace eg2d
