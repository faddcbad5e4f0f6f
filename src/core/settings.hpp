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
    double fold_check = 1;            // 1: solve fails with Folded on a folded converged grid
    double svg_quality = -1;          // EG2D_QUALITY_* colouring SVG cells, -1 none
};

}  // namespace eg2d
