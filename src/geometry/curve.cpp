#include "geometry/curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eg2d {

namespace {
// The differences' step, relative to the piece: fourth-order error ~ h^4
// |r^(5)|/30, round-off ~ eps |r|/h; 2e-4 keeps both near 1e-12 of |r'| for
// curves whose derivatives grow like (2 pi)^k (a closed curve traversed once).
constexpr double kStep = 2e-4;
// Round-off of one callback coordinate, in units of eps |r| (a few operations).
constexpr double kPointUlps = 4.0;
}  // namespace

double Curve::speed_round_off(double lo, double hi, double r_max) const {
    // The central formula's weights sum to 18/12 in absolute value.
    return 1.5 * kPointUlps * std::numeric_limits<double>::epsilon() * r_max / (kStep * (hi - lo));
}

void Curve::derivative(double t, double lo, double hi, double &dx, double &dy) const {
    const double h = kStep * (hi - lo);  // fourth-order differences
    double x[5], y[5];
    if (t - 2 * h >= lo && t + 2 * h <= hi) {  // central
        for (int k = 0; k < 5; ++k) eval(t + (k - 2) * h, x[k], y[k]);
        dx = (x[0] - 8 * x[1] + 8 * x[3] - x[4]) / (12 * h);
        dy = (y[0] - 8 * y[1] + 8 * y[3] - y[4]) / (12 * h);
        return;
    }
    const double step = (t - 2 * h < lo) ? h : -h;  // one-sided, pointing into the piece
    for (int k = 0; k < 5; ++k) eval(t + k * step, x[k], y[k]);
    dx = (-25 * x[0] + 48 * x[1] - 36 * x[2] + 16 * x[3] - 3 * x[4]) / (12 * step);
    dy = (-25 * y[0] + 48 * y[1] - 36 * y[2] + 16 * y[3] - 3 * y[4]) / (12 * step);
}

}  // namespace eg2d
