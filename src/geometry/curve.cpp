#include "geometry/curve.hpp"

#include <algorithm>
#include <cmath>

namespace eg2d {

void Curve::derivative(double t, double lo, double hi, double &dx, double &dy) const {
    // Fourth-order differences: error ~ h^4 |r^(5)|/30, round-off ~ eps |r|/h;
    // h = 2e-4 of the piece keeps both near 1e-12 of |r'| for curves whose
    // derivatives grow like (2 pi)^k (a closed curve traversed once).
    const double h = 2e-4 * (hi - lo);
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
