// The stretching functions of seed 001 section 2.5 and Vinokur's two-sided
// stretching (M. Vinokur, "On one-dimensional stretching functions for
// finite-difference calculations", J. Comput. Phys. 50 (1983) 215-234; the
// form of Thompson, Warsi & Mastin, "Numerical Grid Generation", 1985,
// pp. 307-308).
#include "geometry/distribution.hpp"

#include <cmath>

#include "core/error.hpp"
#include "eg2d.h"

namespace eg2d {

namespace {

// x > 0 with sinh(x)/x = B (B > 1) or sin(x)/x = B (0 < B < 1), by bisection:
// both ratios are monotone in x, so this cannot fail or wander.
double solve_ratio(double B) {
    const bool hyperbolic = B > 1.0;
    auto ratio = [hyperbolic](double x) {
        if (x < 1e-4) return hyperbolic ? 1 + x * x / 6 : 1 - x * x / 6;  // series: no cancellation
        return hyperbolic ? std::sinh(x) / x : std::sin(x) / x;
    };
    double lo = 0.0, hi = hyperbolic ? 1.0 : 3.14159265358979323846;
    if (hyperbolic)
        while (ratio(hi) < B) hi *= 2;
    for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        if ((ratio(mid) < B) == hyperbolic) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

// Vinokur's function for end slopes S0 = ds/du(0), S1 = ds/du(1):
// A = sqrt(S1/S0), B = 1/sqrt(S0 S1); v(u) = 1/2 (1 + tanh(dy (u - 1/2))/tanh(dy/2))
// with sinh(dy)/dy = B (tan and sin when B < 1); s = v/(A + (1 - A) v).
double vinokur(double u, double S0, double S1) {
    const double A = std::sqrt(S1 / S0), B = 1.0 / std::sqrt(S0 * S1);
    double v;
    if (std::fabs(B - 1.0) < 1e-12) {
        v = u;
    } else {
        const double dy = solve_ratio(B);
        v = B > 1.0 ? 0.5 * (1 + std::tanh(dy * (u - 0.5)) / std::tanh(0.5 * dy))
                    : 0.5 * (1 + std::tan(dy * (u - 0.5)) / std::tan(0.5 * dy));
    }
    return v / (A + (1 - A) * v);
}

void fill_vinokur(int n, double ds0, double ds1, double *s) {
    // The function's end slopes give the spacings only to O(1/n^2): correct the
    // slopes until the first and last spacings are the requested ones.
    const int N = n - 1;
    double S0 = ds0 * N, S1 = ds1 * N;
    auto fill = [&] {
        for (int k = 0; k < n; ++k) s[k] = vinokur(static_cast<double>(k) / N, S0, S1);
        s[0] = 0.0;
        s[N] = 1.0;
    };
    for (int it = 0; it < 200; ++it) {
        fill();
        const double e0 = (s[1] - s[0]) / ds0, e1 = (s[N] - s[N - 1]) / ds1;
        if (std::fabs(e0 - 1) < 1e-13 && std::fabs(e1 - 1) < 1e-13) return;
        S0 /= e0;
        S1 /= e1;
    }
    fail(Failure::Argument,
         format("Vinokur spacings %.6g and %.6g (as fractions of the length) cannot both be met with %d points",
                ds0, ds1, n));
}

}  // namespace

void distribute(int id, int n, double p1, double p2, double length, double *s) {
    if (n < 2) fail(Failure::Argument, format("n = %d: need at least 2 points", n));
    if (!std::isfinite(p1) || !std::isfinite(p2))
        fail(Failure::Argument, format("p1 = %g, p2 = %g: must be finite", p1, p2));
    const int N = n - 1;
    switch (id) {
    case EG2D_DIST_UNIFORM:
        for (int k = 0; k <= N; ++k) s[k] = static_cast<double>(k) / N;
        break;
    case EG2D_DIST_EXPONENTIAL:  // seed 001, after eq 2.12: s = (e^{beta u} - 1)/(e^beta - 1)
        if (p1 == 0.0 || std::fabs(p1) > 700)
            fail(Failure::Argument, format("exponential beta = %g: must be nonzero and |beta| <= 700", p1));
        for (int k = 0; k <= N; ++k) s[k] = std::expm1(p1 * k / N) / std::expm1(p1);
        break;
    case EG2D_DIST_TANH_ONE:  // seed 001 eq 2.13: s = 1 + tanh(delta (u - 1)/2)/tanh(delta/2)
        if (!(p1 > 0.0) || p1 > 700) fail(Failure::Argument, format("tanh delta = %g: must be in (0, 700]", p1));
        for (int k = 0; k <= N; ++k) s[k] = 1 + std::tanh(0.5 * p1 * (static_cast<double>(k) / N - 1)) / std::tanh(0.5 * p1);
        break;
    case EG2D_DIST_TANH_TWO: {  // seed 001 end of 2.5: s = (tanh(b (u - c)) - A)/(B - A)
        if (!(p1 > 0.0) || p1 > 350) fail(Failure::Argument, format("tanh strength b = %g: must be in (0, 350]", p1));
        if (!(p2 >= 0.0 && p2 <= 1.0)) fail(Failure::Argument, format("tanh attraction c = %g: must be in [0, 1]", p2));
        const double A = std::tanh(-p1 * p2), B = std::tanh(p1 * (1 - p2));
        for (int k = 0; k <= N; ++k) s[k] = (std::tanh(p1 * (static_cast<double>(k) / N - p2)) - A) / (B - A);
        break;
    }
    case EG2D_DIST_VINOKUR: {
        if (!(p1 > 0.0) || !(p2 > 0.0))
            fail(Failure::Argument, format("Vinokur spacings %g, %g: both must be positive", p1, p2));
        const double d0 = p1 / length, d1 = p2 / length;
        if (N < 2 || d0 + d1 >= 1.0)
            fail(Failure::Argument, format("Vinokur spacings %g + %g leave no room on length %g with %d points",
                                           p1, p2, length, n));
        fill_vinokur(n, d0, d1, s);
        break;
    }
    default:
        fail(Failure::Argument, format("distribution = %d: not one of EG2D_DIST_UNIFORM (0) .. EG2D_DIST_VINOKUR (4)", id));
    }
    s[0] = 0.0;
    s[N] = 1.0;
}

}  // namespace eg2d
