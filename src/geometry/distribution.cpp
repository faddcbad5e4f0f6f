// The stretching functions of seed 001 section 2.5 and Vinokur's two-sided
// stretching (M. Vinokur, "On one-dimensional stretching functions for
// finite-difference calculations", J. Comput. Phys. 50 (1983) 215-234; the
// form of Thompson, Warsi & Mastin, "Numerical Grid Generation", 1985,
// pp. 307-308).
#include "geometry/distribution.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
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
// Written as v = sinh(dy u)/(2 cosh(dy (u - 1/2)) sinh(dy/2)) (and 1 - v with
// 1 - u), which has no cancellation at the ends, and returning s and 1 - s
// so that both end spacings are accurate to round-off.
struct Pair { double s, rest; };
Pair vinokur(double u, double S0, double S1) {
    const double A = std::sqrt(S1 / S0), B = 1.0 / std::sqrt(S0 * S1);
    double v, w;  // v and 1 - v
    if (std::fabs(B - 1.0) < 1e-12) {
        v = u;
        w = 1.0 - u;
    } else {
        const double dy = solve_ratio(B);
        if (B > 1.0) {
            const double d = 2 * std::cosh(dy * (u - 0.5)) * std::sinh(0.5 * dy);
            v = std::sinh(dy * u) / d;
            w = std::sinh(dy * (1 - u)) / d;
        } else {
            const double d = 2 * std::cos(dy * (u - 0.5)) * std::sin(0.5 * dy);
            v = std::sin(dy * u) / d;
            w = std::sin(dy * (1 - u)) / d;
        }
    }
    const double den = A + (1 - A) * v;
    return Pair{v / den, A * w / den};
}

void fill_vinokur(int n, double ds0, double ds1, double *s) {
    // The function's end slopes give the spacings only to O(1/n^2) (and far
    // worse for strong stretching): solve for the slopes that give the
    // requested spacings, by Newton's method on the logarithms with a
    // difference Jacobian.
    const int N = n - 1;
    auto residual = [&](double a, double b, double &r0, double &r1) {
        const double S0 = std::exp(a), S1 = std::exp(b);
        r0 = std::log(vinokur(1.0 / N, S0, S1).s / ds0);
        r1 = std::log(vinokur(1.0 - 1.0 / N, S0, S1).rest / ds1);
    };
    double a = std::log(ds0 * N), b = std::log(ds1 * N), r0, r1;
    residual(a, b, r0, r1);
    for (int it = 0; it < 100 && (std::fabs(r0) > 1e-13 || std::fabs(r1) > 1e-13); ++it) {
        const double h = 1e-7;
        double a0, a1, b0, b1;
        residual(a + h, b, a0, a1);
        residual(a, b + h, b0, b1);
        const double j00 = (a0 - r0) / h, j10 = (a1 - r1) / h, j01 = (b0 - r0) / h, j11 = (b1 - r1) / h;
        const double det = j00 * j11 - j01 * j10;
        if (!(std::fabs(det) > 0) || !std::isfinite(det)) break;
        double da = -(j11 * r0 - j01 * r1) / det, db = -(-j10 * r0 + j00 * r1) / det;
        // Damp: never change a slope by more than a factor e in one step.
        const double big = std::max(std::fabs(da), std::fabs(db));
        if (big > 1.0) { da /= big; db /= big; }
        // Backtrack while the step makes the residual worse.
        const double before = std::max(std::fabs(r0), std::fabs(r1));
        double t = 1.0, n0 = 0, n1 = 0;
        for (int k = 0; k < 30; ++k, t *= 0.5) {
            residual(a + t * da, b + t * db, n0, n1);
            if (std::isfinite(n0) && std::isfinite(n1) && std::max(std::fabs(n0), std::fabs(n1)) < before) break;
        }
        a += t * da;
        b += t * db;
        r0 = n0;
        r1 = n1;
    }
    if (!(std::fabs(r0) <= 1e-11 && std::fabs(r1) <= 1e-11))
        fail(Failure::Argument,
             format("Vinokur spacings %.6g and %.6g (as fractions of the length) cannot both be met with %d points",
                    ds0, ds1, n));
    // Each half from its own end, so both end spacings keep their accuracy.
    for (int k = 0; k <= N; ++k) {
        const Pair p = vinokur(static_cast<double>(k) / N, std::exp(a), std::exp(b));
        s[k] = 2 * k <= N ? p.s : 1.0 - p.rest;
    }
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
        // Below delta = 1e-8 the map is u to double precision (s - u = O(delta^2)), and
        // tanh(delta/2) of a subnormal delta is 0: 0/0 (found by fuzz_curves).
        for (int k = 0; k <= N; ++k)
            s[k] = p1 < 1e-8 ? static_cast<double>(k) / N
                             : 1 + std::tanh(0.5 * p1 * (static_cast<double>(k) / N - 1)) / std::tanh(0.5 * p1);
        break;
    case EG2D_DIST_TANH_TWO: {  // seed 001 end of 2.5: s = (tanh(b (u - c)) - A)/(B - A)
        if (!(p1 > 0.0) || p1 > 350) fail(Failure::Argument, format("tanh strength b = %g: must be in (0, 350]", p1));
        if (!(p2 >= 0.0 && p2 <= 1.0)) fail(Failure::Argument, format("tanh attraction c = %g: must be in [0, 1]", p2));
        const double A = std::tanh(-p1 * p2), B = std::tanh(p1 * (1 - p2));
        // As for TANH_ONE: below b = 1e-8 the map is u, and B - A of a subnormal b is 0.
        for (int k = 0; k <= N; ++k)
            s[k] = p1 < 1e-8 ? static_cast<double>(k) / N
                             : (std::tanh(p1 * (static_cast<double>(k) / N - p2)) - A) / (B - A);
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
