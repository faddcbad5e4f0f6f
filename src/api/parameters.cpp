// The table of public parameters. Adding one: a Settings field and a line.
#include "api/parameters.hpp"

#include <cmath>

#include "base/error.hpp"
#include "eg2d.h"

namespace eg2d {
namespace api {

namespace {
const ParameterInfo kParameters[] = {
    {EG2D_PARAM_RELAXATION, "relaxation", 0.0, 2.0, true, true, false, true, &Settings::relaxation},
    {EG2D_PARAM_TOLERANCE, "tolerance", 0.0, 1.0, true, true, false, false, &Settings::tolerance},
    {EG2D_PARAM_MAX_ITERATIONS, "max_iterations", 1.0, 1e9, false, false, true, false, &Settings::max_iterations},
    {EG2D_PARAM_DIVERGENCE_FACTOR, "divergence_factor", 10.0, 1e12, false, false, false, false,
     &Settings::divergence_factor},
    {EG2D_PARAM_FOLD_CHECK, "fold_check", 0.0, 1.0, false, false, true, false, &Settings::fold_check},
    {EG2D_PARAM_STALL_ITERATIONS, "stall_iterations", 0.0, 1e9, false, false, true, true,
     &Settings::stall_iterations},
    {EG2D_PARAM_MONITOR_SET_UP, "monitor_set_up", 0.0, 1.0, false, false, true, false, &Settings::monitor_set_up},
    // The variational system's weights (operator/variational.hpp).
    {EG2D_PARAM_VARIATIONAL_AREA, "variational_area", 0.0, 1e6, false, false, false, false,
     &Settings::variational_area},
    {EG2D_PARAM_VARIATIONAL_SPACING, "variational_spacing", 0.0, 1e6, false, false, false, false,
     &Settings::variational_spacing},
    {EG2D_PARAM_VARIATIONAL_ORTHOGONALITY, "variational_orthogonality", 0.0, 1e6, false, false, false, false,
     &Settings::variational_orthogonality},
    {EG2D_PARAM_VARIATIONAL_SMOOTHNESS, "variational_smoothness", 0.0, 1e6, false, false, false, false,
     &Settings::variational_smoothness},
    {EG2D_PARAM_VARIATIONAL_ORTHOGONALITY_FORM, "variational_orthogonality_form", 0.0, 1.0, false, false, true,
     false, &Settings::variational_orthogonality_form},
    {EG2D_PARAM_MG_CYCLE, "mg_cycle", 1.0, 2.0, false, false, true, false, &Settings::mg_cycle},
    {EG2D_PARAM_MG_PRE_SMOOTH, "mg_pre_smooth", 0.0, 20.0, false, false, true, false, &Settings::mg_pre_smooth},
    {EG2D_PARAM_MG_POST_SMOOTH, "mg_post_smooth", 0.0, 20.0, false, false, true, false,
     &Settings::mg_post_smooth},
    {EG2D_PARAM_MG_FMG, "mg_fmg", 0.0, 1.0, false, false, true, false, &Settings::mg_fmg},
    {EG2D_PARAM_MG_COARSEST, "mg_coarsest", 3.0, 1e9, false, false, true, false, &Settings::mg_coarsest},
    // Controls.
    {EG2D_PARAM_WALL_DECAY, "wall_decay", 0.01, 10.0, false, false, false, false, &Settings::wall_decay},
    {EG2D_PARAM_WALL_RELAXATION, "wall_relaxation", 0.0, 1.0, true, false, false, false,
     &Settings::wall_relaxation},
    {EG2D_PARAM_WALL_GROWTH, "wall_growth", 1.0, 1.5, false, false, false, false, &Settings::wall_growth},
    {EG2D_PARAM_WALL_LAYER, "wall_layer", 0.0, 3.0, false, false, true, false, &Settings::wall_layer},
    {EG2D_PARAM_HERMITE_SPACING, "hermite_spacing", 0.0, 10.0, true, false, false, false, &Settings::hermite_spacing},
    {EG2D_PARAM_HERMITE_SIDES, "hermite_sides", 0.0, 15.0, false, false, true, false, &Settings::hermite_sides},
    {EG2D_PARAM_HERMITE_HEIGHT_JMIN, "hermite_height_jmin", 0.0, 1e30, false, false, false, false,
     &Settings::hermite_height_jmin},
    {EG2D_PARAM_HERMITE_HEIGHT_IMAX, "hermite_height_imax", 0.0, 1e30, false, false, false, false,
     &Settings::hermite_height_imax},
    {EG2D_PARAM_HERMITE_HEIGHT_JMAX, "hermite_height_jmax", 0.0, 1e30, false, false, false, false,
     &Settings::hermite_height_jmax},
    {EG2D_PARAM_HERMITE_HEIGHT_IMIN, "hermite_height_imin", 0.0, 1e30, false, false, false, false,
     &Settings::hermite_height_imin},
    {EG2D_PARAM_SVG_QUALITY, "svg_quality", -1.0, 99.0, false, false, true, false, &Settings::svg_quality},
    {EG2D_PARAM_SPAN, "span", 0.0, 1e30, true, false, false, false, &Settings::span},
    // The hyperbolic march (src/grid/hyperbolic.cpp).
    {EG2D_PARAM_MARCH_DISTANCE, "march_distance", 0.0, 1e30, true, false, false, true, &Settings::march_distance},
    {EG2D_PARAM_MARCH_FIRST_HEIGHT, "march_first_height", 0.0, 1e30, true, false, false, true,
     &Settings::march_first_height},
    {EG2D_PARAM_MARCH_GROWTH, "march_growth", 1.0, 3.0, false, false, false, false, &Settings::march_growth},
    {EG2D_PARAM_MARCH_SMOOTHING, "march_smoothing", 0.0, 20.0, false, false, false, false,
     &Settings::march_smoothing},
    {EG2D_PARAM_MARCH_AREA_SMOOTHING, "march_area_smoothing", 0.0, 1000.0, false, false, true, false,
     &Settings::march_area_smoothing},
    {EG2D_PARAM_MARCH_END_IMIN, "march_end_imin", 0.0, 3.0, false, false, true, false, &Settings::march_end_imin},
    {EG2D_PARAM_MARCH_END_IMAX, "march_end_imax", 0.0, 3.0, false, false, true, false, &Settings::march_end_imax},
    // Airfoil grids (src/geometry/airfoil_boundary.cpp).
    {EG2D_PARAM_AIRFOIL_FARFIELD, "airfoil_farfield", 2.0, 1e6, false, false, false, false,
     &Settings::airfoil_farfield},
    {EG2D_PARAM_AIRFOIL_LE_SPACING, "airfoil_le_spacing", 0.0, 0.1, true, false, false, true,
     &Settings::airfoil_le_spacing},
    {EG2D_PARAM_AIRFOIL_TE_SPACING, "airfoil_te_spacing", 0.0, 0.1, true, false, false, true,
     &Settings::airfoil_te_spacing},
    {EG2D_PARAM_AIRFOIL_WAKE_NODES, "airfoil_wake_nodes", 2.0, 1e8, false, false, true, true,
     &Settings::airfoil_wake_nodes},
    {EG2D_PARAM_AIRFOIL_TRAILING_EDGE, "airfoil_trailing_edge", 0.0, 1.0, false, false, true, false,
     &Settings::airfoil_trailing_edge},
    {EG2D_PARAM_AIRFOIL_O_TE_BASE, "airfoil_o_te_base", 0.0, 0.01, false, false, false, false,
     &Settings::airfoil_o_te_base},
    // Approximate factorisation (src/solvers/af.cpp).
    {EG2D_PARAM_AF_DTAU_MIN, "af_dtau_min", 0.0, 1e12, true, false, false, false, &Settings::af_dtau_min},
    {EG2D_PARAM_AF_DTAU_MAX, "af_dtau_max", 0.0, 1e12, true, false, false, true, &Settings::af_dtau_max},
    {EG2D_PARAM_AF_STEPS, "af_steps", 4.0, 1000.0, false, false, true, true, &Settings::af_steps},
    {EG2D_PARAM_AF_A, "af_a", -1.0, 10.0, true, false, false, false, &Settings::af_a},
    {EG2D_PARAM_AF_B, "af_b", 0.0, 10.0, true, false, false, false, &Settings::af_b},
    {EG2D_PARAM_AF_RELAXATION, "af_relaxation", 0.0, 4.0, true, true, false, true, &Settings::af_relaxation},
};
}  // namespace

const ParameterInfo *find_parameter(int id) {
    for (const ParameterInfo &p : kParameters)
        if (p.id == id) return &p;
    return nullptr;
}

void check_parameter(const ParameterInfo &p, double v) {
    if (!std::isfinite(v)) fail(Failure::Argument, format("%s = %g: must be finite", p.name, v));
    if (p.zero_means_auto && v == 0.0) return;
    const bool below = p.open_lower ? !(v > p.lower) : !(v >= p.lower);
    const bool above = p.open_upper ? !(v < p.upper) : !(v <= p.upper);
    if (below || above)
        fail(Failure::Argument, format("%s = %g: must be in %c%g, %g%c%s", p.name, v, p.open_lower ? '(' : '[',
                                       p.lower, p.upper, p.open_upper ? ')' : ']',
                                       p.zero_means_auto ? " (or 0 for automatic)" : ""));
    if (p.integer && v != std::floor(v))
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

}  // namespace api
}  // namespace eg2d
