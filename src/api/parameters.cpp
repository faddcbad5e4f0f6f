// The table of public parameters. Adding one: a Settings field and a line.
#include "api/parameters.hpp"

#include <cmath>

#include "core/error.hpp"
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
    {EG2D_PARAM_SVG_QUALITY, "svg_quality", -1.0, 99.0, false, false, true, false, &Settings::svg_quality},
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

}  // namespace api
}  // namespace eg2d
