// Run settings of a grid. Every field is a parameter with an EG2D_PARAM_* id,
// bounds and a default in src/api/parameters.cpp; a solver that needs a new
// setting adds a field here and a line there.
#pragma once

namespace eg2d {

struct Settings {
    double relaxation = 0.0;          // 0 = automatic
    double tolerance = 1e-8;          // on NUMERICS.md's residual
    double max_iterations = 100000;   // per eg2d_solve call
    double divergence_factor = 1e4;   // residual > factor * best of the run = divergence
    double stall_iterations = 0.0;    // 0: the solver's window (Solver::stall_window)
    double monitor_set_up = 0.0;      // 1: the monitor is called during a run's set-up too
    double fold_check = 1;            // 1: solve fails with Folded on a folded converged grid
                                      // (and the variational system's steps may not fold cells)
    // The variational system's weights a, b, c (operator/variational.hpp).
    double variational_area = 0.0;
    double variational_spacing = 1.0;
    double variational_orthogonality = 0.0;
    double variational_smoothness = 0.0;  // d: Brackbill & Saltzman's smoothness (Winslow's) functional
    double variational_orthogonality_form = 0;  // 0: O as dot products, 1: as squared cotangents
    // Multigrid (src/solvers/multigrid*.cpp).
    double mg_cycle = 2;              // cycle index: 1 = V, 2 = W
    double mg_pre_smooth = 2;         // alternating line sweeps before the coarse correction
    double mg_post_smooth = 1;        // and after it
    double mg_fmg = 1;                // 1: the first cycle is a full-multigrid start
    double mg_coarsest = 5;           // a direction is not coarsened below this many nodes
    // Wall orthogonality (src/controls/wall.cpp).
    double wall_decay = 0.3;          // a: the wall control decays as exp(-a (m-1)) at depth m
    double wall_relaxation = 0.1;     // under-relaxation of its updates, (0, 1]
    double wall_growth = 1.15;        // cell-to-cell growth of a marched wall layer, [1, 1.5]
    double wall_layer = 3;            // EG2D_PARAM_WALL_LAYER: 0 control, 1 normals, 2 hybrid, 3 automatic (wall.cpp)
    double hermite_spacing = 1.0;     // EG2D_INIT_HERMITE's alpha (the grid-generation lecture notes eq 2.6)
    // EG2D_INIT_HERMITE at chosen sides (grid/tfi_hermite_sides.cpp): a mask
    // of 1 << side (0: the eta-only form above) and each side's first-node
    // height (0: alpha times the uniform spacing).
    double hermite_sides = 0;
    double hermite_height_jmin = 0, hermite_height_imax = 0, hermite_height_jmax = 0, hermite_height_imin = 0;
    // The hyperbolic march (src/grid/hyperbolic.cpp, docs/hyperbolic.md).
    double march_distance = 0.0;      // marching distance; 0: 10 x the JMIN curve's bounding-box diagonal
    double march_first_height = 0.0;  // first layer's height; 0: the one with constant ratio 1 + (G-1)/2
    double march_growth = 1.2;        // G: largest ratio of consecutive layer heights
    double march_smoothing = 0.5;     // eps_c of Chan & Steger's variable dissipation
    double march_area_smoothing = 20; // area-smoothing passes per layer
    double march_end_imin = 0;        // MarchEnd of the i = 0 end (open sides)
    double march_end_imax = 0;        // and of the i = ni-1 end
    // Airfoil grids (src/geometry/airfoil_boundary.cpp, eg2d_set_airfoil).
    double airfoil_farfield = 100;    // chords
    double airfoil_le_spacing = 0;    // chords; 0: automatic
    double airfoil_te_spacing = 0;    // chords; 0: automatic
    double airfoil_wake_nodes = 0;    // C-grid cut nodes a side; 0: automatic
    double airfoil_trailing_edge = 0; // EG2D_AIRFOIL_TE_BLUNT (0) or _SHARPEN (1)
    double airfoil_o_te_base = 5e-5;  // chords: an O-grid's sharp trailing edge cut to a base this thick; 0 keeps it
    double svg_quality = -1;          // EG2D_QUALITY_* colouring SVG cells, -1 none
    double span = 1.0;                // thickness of the one cell layer of the 3-D files

    // Approximate factorisation (Ly & Norrison 2007 eqs 5-13); 0 = automatic where allowed.
    double af_dtau_min = 0.5;         // smallest step of the cycle, in units of 1/(2(alpha+gamma))
    double af_dtau_max = 0.0;         // largest step; 0: from the grid size
    double af_steps = 0.0;            // steps per cycle M (end points repeated); 0: from the ratio
    double af_a = 0.0;                // Warming-Beam a (Euler implicit a = 0, b = 1)
    double af_b = 1.0;                // Warming-Beam b
    double af_relaxation = 0.0;       // omega of eq 7; 0: automatic
};

}  // namespace eg2d
