// The table of public parameters. Adding one: a Settings field, a line here
// (in id order) and its #define in eg2d.h.
#include "base/parameters.hpp"

#include <cmath>

#include "base/error.hpp"
#include "eg2d.h"

namespace eg2d {

namespace {
constexpr ValueRange closed(double a, double b) { return {a, b, false, false}; }
constexpr ValueRange open(double a, double b) { return {a, b, true, true}; }
constexpr ValueRange open_closed(double a, double b) { return {a, b, true, false}; }  // (a, b]

constexpr int kReal = EG2D_VALUE_REAL, kInteger = EG2D_VALUE_INTEGER;
constexpr int kFlag = EG2D_VALUE_FLAG | EG2D_VALUE_INTEGER, kAuto = EG2D_VALUE_AUTOMATIC;

using S = Settings;
const ParameterInfo kParameters[] = {
    // The run (any solver).
    {EG2D_PARAM_RELAXATION, "relaxation", open(0, 2), kReal | kAuto, "1",
     "SOR relaxation factor omega; 0: automatic, from the grid's size", &S::relaxation},
    {EG2D_PARAM_TOLERANCE, "tolerance", open(0, 1), kReal, "1",
     "eg2d_solve ends when the residual (NUMERICS.md) is below this", &S::tolerance},
    {EG2D_PARAM_MAX_ITERATIONS, "max_iterations", closed(1, 1e9), kInteger, "iterations",
     "iteration limit of one eg2d_solve call", &S::max_iterations},
    {EG2D_PARAM_DIVERGENCE_FACTOR, "divergence_factor", closed(10, 1e12), kReal, "1",
     "a residual this many times the run's best is a divergence", &S::divergence_factor},
    {EG2D_PARAM_FOLD_CHECK, "fold_check", closed(0, 1), kFlag, "1",
     "1: a converged grid with folded cells is EG2D_ERR_FOLDED", &S::fold_check},
    {EG2D_PARAM_STALL_ITERATIONS, "stall_iterations", closed(0, 1e9), kInteger | kAuto, "iterations",
     "a run with no 10% gain in this many iterations ends; 0: the solver's window", &S::stall_iterations},
    {EG2D_PARAM_MONITOR_SET_UP, "monitor_set_up", closed(0, 1), kFlag, "1",
     "1: the monitor is called during a run's set-up (march, wall layer) too", &S::monitor_set_up},
    // The variational system V = aA + bS + cO + dW.
    {EG2D_PARAM_VARIATIONAL_AREA, "variational_area", closed(0, 1e6), kReal, "1", "a, the weight of the area term",
     &S::variational_area},
    {EG2D_PARAM_VARIATIONAL_SPACING, "variational_spacing", closed(0, 1e6), kReal, "1",
     "b, the weight of the spacing term", &S::variational_spacing},
    {EG2D_PARAM_VARIATIONAL_ORTHOGONALITY, "variational_orthogonality", closed(0, 1e6), kReal, "1",
     "c, the weight of the orthogonality term", &S::variational_orthogonality},
    {EG2D_PARAM_VARIATIONAL_SMOOTHNESS, "variational_smoothness", closed(0, 1e6), kReal, "1",
     "d, the weight of Brackbill & Saltzman's smoothness term", &S::variational_smoothness},
    {EG2D_PARAM_VARIATIONAL_ORTHOGONALITY_FORM, "variational_orthogonality_form", closed(0, 1), kInteger, "1",
     "the orthogonality term as 0: dot products, 1: squared cotangents", &S::variational_orthogonality_form},
    // Approximate factorisation.
    {EG2D_PARAM_AF_DTAU_MIN, "af_dtau_min", open_closed(0, 1e12), kReal, "1",
     "smallest pseudo-time step of the cycle", &S::af_dtau_min},
    {EG2D_PARAM_AF_DTAU_MAX, "af_dtau_max", open_closed(0, 1e12), kReal | kAuto, "1",
     "largest pseudo-time step; 0: from the grid's size", &S::af_dtau_max},
    {EG2D_PARAM_AF_STEPS, "af_steps", closed(4, 1000), kInteger | kAuto, "iterations",
     "steps per cycle; 0: from the step ratio", &S::af_steps},
    {EG2D_PARAM_AF_A, "af_a", open_closed(-1, 10), kReal, "1", "Warming-Beam a", &S::af_a},
    {EG2D_PARAM_AF_B, "af_b", open_closed(0, 10), kReal, "1", "Warming-Beam b", &S::af_b},
    {EG2D_PARAM_AF_RELAXATION, "af_relaxation", open(0, 4), kReal | kAuto, "1",
     "omega of the update; 0: automatic", &S::af_relaxation},
    // Multigrid.
    {EG2D_PARAM_MG_CYCLE, "mg_cycle", closed(1, 2), kInteger, "1", "cycle index: 1 V, 2 W", &S::mg_cycle},
    {EG2D_PARAM_MG_PRE_SMOOTH, "mg_pre_smooth", closed(0, 20), kInteger, "sweeps",
     "alternating line sweeps before the coarse correction", &S::mg_pre_smooth},
    {EG2D_PARAM_MG_POST_SMOOTH, "mg_post_smooth", closed(0, 20), kInteger, "sweeps",
     "alternating line sweeps after the coarse correction", &S::mg_post_smooth},
    {EG2D_PARAM_MG_FMG, "mg_fmg", closed(0, 1), kFlag, "1", "1: the first cycle is a full-multigrid start",
     &S::mg_fmg},
    {EG2D_PARAM_MG_COARSEST, "mg_coarsest", closed(3, 1e9), kInteger, "nodes",
     "a direction is not coarsened below this many nodes", &S::mg_coarsest},
    // Controls and walls.
    {EG2D_PARAM_WALL_DECAY, "wall_decay", closed(0.01, 10), kReal, "1",
     "the wall control decays as exp(-a (m-1)) at depth m", &S::wall_decay},
    {EG2D_PARAM_WALL_RELAXATION, "wall_relaxation", open_closed(0, 1), kReal, "1",
     "under-relaxation of the wall control's updates", &S::wall_relaxation},
    {EG2D_PARAM_WALL_GROWTH, "wall_growth", closed(1, 1.5), kReal, "1",
     "cell-to-cell growth of a graded wall layer", &S::wall_growth},
    {EG2D_PARAM_WALL_LAYER, "wall_layer", closed(0, 3), kInteger, "1",
     "wall layer: 0 control, 1 normals, 2 hybrid, 3 automatic", &S::wall_layer},
    // Files.
    {EG2D_PARAM_SVG_QUALITY, "svg_quality", closed(-1, 99), kInteger, "1",
     "the EG2D_QUALITY_* metric colouring SVG cells; -1: none", &S::svg_quality},
    {EG2D_PARAM_SPAN, "span", open_closed(0, 1e30), kReal, "length",
     "thickness of the one cell layer of the 3-D files", &S::span},
    // Initial grids: Hermite TFI.
    {EG2D_PARAM_HERMITE_SPACING, "hermite_spacing", open_closed(0, 10), kReal, "1",
     "alpha, the eta-derivative scale of Hermite TFI", &S::hermite_spacing},
    {EG2D_PARAM_HERMITE_SIDES, "hermite_sides", closed(0, 15), kInteger, "1",
     "mask of 1 << side: Hermite blending at these sides; 0: in eta only", &S::hermite_sides},
    {EG2D_PARAM_HERMITE_HEIGHT_JMIN, "hermite_height_jmin", closed(0, 1e30), kReal, "length",
     "first-node height at JMIN; 0: alpha times the uniform spacing", &S::hermite_height_jmin},
    {EG2D_PARAM_HERMITE_HEIGHT_IMAX, "hermite_height_imax", closed(0, 1e30), kReal, "length",
     "first-node height at IMAX; 0: alpha times the uniform spacing", &S::hermite_height_imax},
    {EG2D_PARAM_HERMITE_HEIGHT_JMAX, "hermite_height_jmax", closed(0, 1e30), kReal, "length",
     "first-node height at JMAX; 0: alpha times the uniform spacing", &S::hermite_height_jmax},
    {EG2D_PARAM_HERMITE_HEIGHT_IMIN, "hermite_height_imin", closed(0, 1e30), kReal, "length",
     "first-node height at IMIN; 0: alpha times the uniform spacing", &S::hermite_height_imin},
    // Initial grids: the hyperbolic march.
    {EG2D_PARAM_MARCH_DISTANCE, "march_distance", open_closed(0, 1e30), kReal | kAuto, "length",
     "marching distance; 0: 10 x the JMIN curve's bounding-box diagonal", &S::march_distance},
    {EG2D_PARAM_MARCH_FIRST_HEIGHT, "march_first_height", open_closed(0, 1e30), kReal | kAuto, "length",
     "first layer's height; 0: the one with constant growth", &S::march_first_height},
    {EG2D_PARAM_MARCH_GROWTH, "march_growth", closed(1, 3), kReal, "1",
     "largest ratio of consecutive layer heights", &S::march_growth},
    {EG2D_PARAM_MARCH_SMOOTHING, "march_smoothing", closed(0, 20), kReal, "1",
     "eps_c of Chan & Steger's variable dissipation", &S::march_smoothing},
    {EG2D_PARAM_MARCH_AREA_SMOOTHING, "march_area_smoothing", closed(0, 1000), kInteger, "sweeps",
     "area-smoothing passes per layer", &S::march_area_smoothing},
    {EG2D_PARAM_MARCH_END_IMIN, "march_end_imin", closed(0, 3), kInteger, "1",
     "EG2D_MARCH_END_* of the i = 0 end of an open curve", &S::march_end_imin},
    {EG2D_PARAM_MARCH_END_IMAX, "march_end_imax", closed(0, 3), kInteger, "1",
     "EG2D_MARCH_END_* of the i = ni-1 end of an open curve", &S::march_end_imax},
    // Airfoil grids (eg2d_set_airfoil).
    {EG2D_PARAM_AIRFOIL_FARFIELD, "airfoil_farfield", closed(2, 1e6), kReal, "chords",
     "far-field distance", &S::airfoil_farfield},
    {EG2D_PARAM_AIRFOIL_LE_SPACING, "airfoil_le_spacing", open_closed(0, 0.1), kReal | kAuto, "chords",
     "spacing at the leading edge; 0: automatic", &S::airfoil_le_spacing},
    {EG2D_PARAM_AIRFOIL_TE_SPACING, "airfoil_te_spacing", open_closed(0, 0.1), kReal | kAuto, "chords",
     "spacing at the trailing edge; 0: automatic", &S::airfoil_te_spacing},
    {EG2D_PARAM_AIRFOIL_WAKE_NODES, "airfoil_wake_nodes", closed(2, 1e8), kInteger | kAuto, "nodes",
     "C-grid cut nodes a side; 0: automatic", &S::airfoil_wake_nodes},
    {EG2D_PARAM_AIRFOIL_TRAILING_EDGE, "airfoil_trailing_edge", closed(0, 1), kInteger, "1",
     "EG2D_AIRFOIL_TE_BLUNT (0) or EG2D_AIRFOIL_TE_SHARPEN (1)", &S::airfoil_trailing_edge},
    {EG2D_PARAM_AIRFOIL_O_TE_BASE, "airfoil_o_te_base", closed(0, 0.01), kReal, "chords",
     "an O-grid's sharp trailing edge cut to a base this thick; 0 keeps it", &S::airfoil_o_te_base},
};
}  // namespace

Table<ParameterInfo> parameter_table() { return table_of(kParameters); }

const ParameterInfo *find_parameter(int id) { return parameter_table().find(id); }

void check_parameter(const ParameterInfo &p, double v) {
    if (!std::isfinite(v)) fail(Failure::Argument, format("%s = %g: must be finite", p.name, v));
    const bool automatic = p.kind & EG2D_VALUE_AUTOMATIC;
    if (automatic && v == 0.0) return;
    const ValueRange &r = p.range;
    const bool below = r.open_lower ? !(v > r.lower) : !(v >= r.lower);
    const bool above = r.open_upper ? !(v < r.upper) : !(v <= r.upper);
    if (below || above)
        fail(Failure::Argument, format("%s = %g: must be in %c%g, %g%c%s", p.name, v, r.open_lower ? '(' : '[',
                                       r.lower, r.upper, r.open_upper ? ')' : ']',
                                       automatic ? " (or 0 for automatic)" : ""));
    if ((p.kind & EG2D_VALUE_INTEGER) && v != std::floor(v))
        fail(Failure::Argument, format("%s = %g: must be a whole number", p.name, v));
}

void check_settings(const Settings &s) {
    if (s.af_dtau_max > 0.0 && s.af_dtau_min > s.af_dtau_max)
        fail(Failure::Argument, format("af_dtau_min = %g > af_dtau_max = %g: the cycle needs min <= max",
                                       s.af_dtau_min, s.af_dtau_max));
    if (s.variational_area == 0.0 && s.variational_spacing == 0.0 && s.variational_orthogonality == 0.0 &&
        s.variational_smoothness == 0.0)
        fail(Failure::Argument, "variational_area, variational_spacing, variational_orthogonality and "
                                "variational_smoothness would all be 0: V = 0 has no minimiser (set the new weight "
                                "before zeroing the old one)");
}

}  // namespace eg2d
