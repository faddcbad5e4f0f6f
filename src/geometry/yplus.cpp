// First-cell height for a target y+ from the flat-plate estimate: Schlichting's
// turbulent skin friction Cf = (2 log10(Re) - 0.65)^-2.3 (H. Schlichting,
// "Boundary-Layer Theory", 7th ed., 1979, eq 21.16; valid for Re < 1e9),
// u_tau = U sqrt(Cf/2) and y = y+ nu / u_tau, so with Re = U c / nu:
//   y / c = y+ / (Re sqrt(Cf/2)).
// Construct2D offers the same kind of estimate for its wall spacing.
#include "geometry/yplus.hpp"

#include <cmath>

#include "base/error.hpp"

namespace eg2d {

double first_cell_height(double yplus, double reynolds, double chord) {
    if (!(yplus > 0.0) || !std::isfinite(yplus)) fail(Failure::Argument, format("y+ = %g: must be positive", yplus));
    if (!(reynolds >= 1e3) || !(reynolds <= 1e9))
        fail(Failure::Argument, format("Reynolds number %g: the flat-plate estimate holds for 1e3 <= Re <= 1e9", reynolds));
    if (!(chord > 0.0) || !std::isfinite(chord)) fail(Failure::Argument, format("chord = %g: must be positive", chord));
    const double cf = std::pow(2 * std::log10(reynolds) - 0.65, -2.3);
    const double height = chord * yplus / (reynolds * std::sqrt(0.5 * cf));
    // A subnormal y+ or a huge chord under- or overflows (found by fuzz_curves);
    // a height of 0 would mean "orthogonality only" to eg2d_set_wall_spacing.
    if (!(height > 0.0) || !std::isfinite(height))
        fail(Failure::Argument, format("y+ = %g, chord = %g: the height %g is not a positive finite number",
                                       yplus, chord, height));
    return height;
}

}  // namespace eg2d
