// The grid levels of the FAS multigrid solver (and of the nested solver's
// coarse-to-fine start) and the transfers between them. Level 0 is the
// user's grid; each coarser level has about half the cells in each direction
// that can be coarsened (coarse_axis.hpp: any node count; at least 3 nodes
// left, on the periodic direction of an O-grid at least 8 cells), or in one
// direction only (semicoarsening, Winslow) when the other cannot.
#pragma once
#include <vector>

#include "base/connectivity.hpp"
#include "operator/control_fields.hpp"
#include "operator/operator.hpp"
#include "operator/system.hpp"
#include "solvers/coarse_axis.hpp"
#include "solvers/line_relax.hpp"
#include "solvers/multigrid_ilu.hpp"

namespace eg2d {

struct MgLevel {
    explicit MgLevel(const Connectivity &c) : conn(c) {}
    Connectivity conn;
    CoarseAxis ai, aj;               // where the nodes sit in the finer level, per direction
    std::vector<double> x, y;        // coordinates (empty on level 0: the grid's own)
    std::vector<double> x0, y0;      // I u: the finer solution injected (FAS)
    std::vector<double> fx, fy;      // FAS right-hand side (level 0 has none)
    std::vector<double> rx, ry;      // R = L(r) - f, for the restriction
    std::vector<double> best_x, best_y;  // coarsest level: the best iterate of its solve
    ControlFields controls;          // the finer fields injected and rescaled
    Functional functional;           // the variational system's, for this level's cells
    long refused = 0;                // variational: node steps the fold guard refused (reset by the solver)
    std::vector<Connectivity::Node> singular;    // boundary singularities (multigrid_local.hpp)
    std::vector<Connectivity::Node> trailing_edge;  // a C-grid's cut ends on this level
    Level level;                     // the operator's view of this level
    LineWork work;
    IluWork ilu;
    bool clip = false;               // built past the controls' stretching limit: clip_coarse_stretching applies
    std::size_t size() const { return static_cast<std::size_t>(conn.ni()) * conn.nj(); }
};

// Builds the levels below a fine grid of this connectivity. Level 0 gets only
// residual scratch; its coordinates and controls are attached by the solver.
// `coarsest`: a direction is not coarsened once it has <= coarsest nodes.
// `stretch_i`, `stretch_j`: the largest |Phi| and |Psi| of the fine grid's
// controls (coarse_stretch): a direction stops coarsening before either
// would pass kMaxCoarseStretching on a coarse level, unless that level would
// still have more than kLargeCoarsest nodes; then coarsening goes on past the
// limit, and the levels past it are marked `clip` (clip_coarse_stretching).
std::vector<MgLevel> build_hierarchy(const Connectivity &fine, System system, int coarsest, double stretch_i = 0.0,
                                     double stretch_j = 0.0);

// A coarse level's |Phi| or |Psi| grows with its spacing; past this the coarse
// line systems lose their sign structure (cell Peclet number 2) and the coarse
// problem corrects nothing: a wall layer's outer stretching, Psi -0.26 on the
// fine grid, is -2.1 three levels down, and multigrid stalled there (annulus
// 65x33 with a 1e-3 wall, far field 10: residual stuck at 6e-4).
constexpr double kMaxCoarseStretching = 1.0;
// Above held rows (a wall layer) the rings are coarsened only while |Psi|
// stays below this: the annulus's -0.26 (above) must not pass, the hybrid
// layer's 0.12 (grid/hybrid_layer.hpp) may, twice.
constexpr double kMaxHeldStretching = 0.5;

// A coarsest level this large costs more than it brings: its solve is the
// smoother alone (up to 50 sweeps, multigrid_smoother.cpp), several times a
// W cycle, and on a large level those sweeps barely reduce its residual.
// The TMR-class hybrid C-grid 1793x513 (500 chords, first cell 4e-7)
// stopped at 225x513 for the stretching (its march's controls, clipped to
// |Psi| <= 1, at 5% of the nodes): 50 sweeps per visit took the coarse
// residual down by 1.3-4x only, 80% of the run, 7 cycles in 12.9 CPU s.
// Going on with the coarse controls clipped: 5 levels down to 113x34, the
// same 7 cycles in 2.9 s. Smaller coarsest levels keep the limit, where
// clipping cost more than it saved: the hybrid C-grid 385x97 (coarsest
// 97x49) took more than 10 cycles instead of 4, and the marched wall layer
// on a C-grid 129x33 folded.
constexpr std::size_t kLargeCoarsest = 65536;

// Clips a `clip` level's Phi (a_xi) and Psi (c_eta) to |.| <=
// kMaxCoarseStretching and returns how many values it changed. Its coarse
// equations then differ from the fine ones there; FAS still converges to the
// fine grid's solution (the coarse right-hand side is built with the same
// clipped operator), only the correction is less accurate. Clipping at 2
// stalled the TMR-class grid (residual 1.4e-7); at 0.5 and 1 it did not.
long clip_coarse_stretching(MgLevel &coarse);

// The largest |Phi| (a_xi) and |Psi| (c_eta) of a control field, 0 without.
void coarse_stretch(const ControlFields *fields, double &stretch_i, double &stretch_j);

// How much larger the coarse operator is than the fine one for the same
// smooth grid at coarse node (I, J) (the operator is written in index units):
// (hi*hj)^2 for Winslow, whose terms are quartic in index spacing, hi*hj for
// Laplace and the variational system (its V is the same on every level, and
// a coarse node gathers the gradient of hi*hj fine ones), with hi, hj the
// fine cells per coarse cell there (coarse_axis.hpp).
double operator_scale(System system, const MgLevel &coarse, int I, int J);

// The variational functional of every level: `fine` on level 0, and on each
// coarse level the same weights over that level's mean cell area, without
// the fold guard (variational.hpp's coarsened).
void attach_functional(std::vector<MgLevel> &levels, const Functional *fine);

// coarse.controls = the fine fields at the coarse nodes, rescaled to the
// coarse index units (controls/control_fields.hpp; derivation in the .cpp).
void restrict_controls(const ControlFields *fine, const Connectivity &fine_conn, MgLevel &coarse);

// dst (coarse) = src (fine) sampled at the coarse nodes (interpolated between
// fine nodes where a coarse node falls between them): coordinates, boundary
// included.
void inject(const Connectivity &fine_conn, const double *src, const MgLevel &coarse, double *dst);

// Full weighting of fine.rx, fine.ry at the coarse unknowns, times
// operator_scale at each coarse node, into out_x, out_y (coarse-sized).
void restrict_residual(System system, const MgLevel &fine, const MgLevel &coarse, double *out_x, double *out_y);

// The nodes of `fine` (a level's nodes) on the next coarser level: the nearest coarse node of each.
std::vector<Connectivity::Node> coarse_nodes(const std::vector<Connectivity::Node> &fine, const MgLevel &coarse);

// Fine unknowns += bilinear interpolation of (coarse x - coarse x0).
// Also the nested solver's coarse-to-fine step (x0: its start injected).
void prolong_correction(const MgLevel &coarse, const Level &fine);

}  // namespace eg2d
