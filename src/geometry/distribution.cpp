// The stretching functions of the grid-generation lecture notes section 2.5 and Vinokur's two-sided
// stretching (M. Vinokur, "On one-dimensional stretching functions for
// finite-difference calculations", J. Comput. Phys. 50 (1983) 215-234; the
// form of Thompson, Warsi & Mastin, "Numerical Grid Generation", 1985,
// pp. 307-308).
#include "geometry/distribution.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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

namespace {
const NamedId kDistributions[] = {
    {EG2D_DIST_UNIFORM, "uniform", "uniform"},
    {EG2D_DIST_EXPONENTIAL, "exponential", "exponential"},
    {EG2D_DIST_TANH_ONE, "tanh", "one-sided tanh"},
    {EG2D_DIST_TANH_TWO, "tanh2", "two-sided tanh"},
    {EG2D_DIST_VINOKUR, "vinokur", "Vinokur"},
};
}  // namespace

Table<NamedId> distribution_table() { return table_of(kDistributions); }

namespace {

// The parameters of the closed-form functions (every id but VINOKUR), checked.
void check_closed_form(int id, double p1, double p2) {
    switch (id) {
    case EG2D_DIST_UNIFORM:
        break;
    case EG2D_DIST_EXPONENTIAL:
        if (p1 == 0.0 || std::fabs(p1) > 700)
            fail(Failure::Argument, format("exponential beta = %g: must be nonzero and |beta| <= 700", p1));
        break;
    case EG2D_DIST_TANH_ONE:
        if (!(p1 > 0.0) || p1 > 700) fail(Failure::Argument, format("tanh delta = %g: must be in (0, 700]", p1));
        break;
    case EG2D_DIST_TANH_TWO:
        if (!(p1 > 0.0) || p1 > 350) fail(Failure::Argument, format("tanh strength b = %g: must be in (0, 350]", p1));
        if (!(p2 >= 0.0 && p2 <= 1.0)) fail(Failure::Argument, format("tanh attraction c = %g: must be in [0, 1]", p2));
        break;
    default:
        fail(Failure::Argument, format("distribution = %d: not one of EG2D_DIST_UNIFORM (0) .. EG2D_DIST_VINOKUR (4)", id));
    }
}

// s(u_k), u_k = k/N, of a closed-form function with checked parameters.
double closed_form(int id, int k, int N, double p1, double p2) {
    const double u = static_cast<double>(k) / N;
    switch (id) {
    // The grid-generation lecture notes, after eq 2.12: s = (e^{beta u} - 1)/(e^beta - 1).
    case EG2D_DIST_EXPONENTIAL:
        return std::expm1(p1 * k / N) / std::expm1(p1);
    // The tanh maps are evaluated in a form without cancellation, so that a
    // small first spacing keeps its relative accuracy (1 + tanh(..)/tanh(..)
    // loses all of it below 1e-16): tanh x - tanh y = sinh(x - y)/(cosh x cosh y).
    // Below a parameter of 1e-8 each map is u to double precision (s - u =
    // O(delta^2)), and a subnormal parameter would give 0/0 (found by fuzz_curves).
    // TANH_ONE, the grid-generation lecture notes eq 2.13:
    case EG2D_DIST_TANH_ONE:  // s = 1 + tanh(delta (u - 1)/2)/tanh(delta/2)
        //                          = sinh(delta u/2)/(cosh(delta (u - 1)/2) sinh(delta/2))
        if (p1 < 1e-8) return u;
        return std::sinh(0.5 * p1 * u) / (std::cosh(0.5 * p1 * (u - 1)) * std::sinh(0.5 * p1));
    // TANH_TWO, the grid-generation lecture notes, end of section 2.5:
    case EG2D_DIST_TANH_TWO:  // s = (tanh(b (u - c)) - A)/(B - A), A = tanh(-b c),
        //                       B = tanh(b (1 - c)); = sinh(b u) cosh(b (1 - c))/(cosh(b (u - c)) sinh(b))
        //                       (b <= 350: no overflow)
        if (p1 < 1e-8) return u;
        return std::sinh(p1 * u) * std::cosh(p1 * (1 - p2)) / (std::cosh(p1 * (u - p2)) * std::sinh(p1));
    default:
        return u;
    }
}

}  // namespace

void distribute(int id, int n, double p1, double p2, double length, double *s) {
    if (n < 2) fail(Failure::Argument, format("n = %d: need at least 2 points", n));
    if (!std::isfinite(p1) || !std::isfinite(p2))
        fail(Failure::Argument, format("p1 = %g, p2 = %g: must be finite", p1, p2));
    const int N = n - 1;
    if (id == EG2D_DIST_VINOKUR) {
        if (!(p1 > 0.0) || !(p2 > 0.0))
            fail(Failure::Argument, format("Vinokur spacings %g, %g: both must be positive", p1, p2));
        const double d0 = p1 / length, d1 = p2 / length;
        if (N < 2 || d0 + d1 >= 1.0)
            fail(Failure::Argument, format("Vinokur spacings %g + %g leave no room on length %g with %d points",
                                           p1, p2, length, n));
        // Below this share of the length B = 1/sqrt(S0 S1) and the stretching
        // dy solved from sinh(dy)/dy = B overflow.
        if (std::min(d0, d1) < 1e-100)
            fail(Failure::Argument, format("Vinokur spacings %g, %g: below 1e-100 of the length %g", p1, p2, length));
        fill_vinokur(n, d0, d1, s);
    } else {
        check_closed_form(id, p1, p2);
        for (int k = 0; k <= N; ++k) s[k] = closed_form(id, k, N, p1, p2);
    }
    s[0] = 0.0;
    s[N] = 1.0;
}

namespace {

// One branch of a closed-form function's first spacing s_1 as its parameter
// t >= 0 grows from 0 (the uniform spacing 1/N, the limit) to its bound;
// EXPONENTIAL's beta is sign * t.
struct Branch {
    int id, N;
    double sign, p2, bound;
    double at(double t) const { return t == 0.0 ? 1.0 / N : closed_form(id, 1, N, sign * t, p2); }
};

// The t in [lo, hi] whose first spacing is `target`, where s_1 - target
// changes sign between lo and hi: bisection to the last bit (the map is
// smooth, so that is about 1e-13 of the spacing at worst).
double bisect(const Branch &b, double target, double lo, double hi) {
    const bool rising = b.at(lo) < target;
    for (int it = 0; it < 2000; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        const double d = b.at(mid) - target;
        if (d == 0.0) return mid;
        if ((d < 0.0) == rising) lo = mid; else hi = mid;
    }
    const bool low = lo > 0.0 && std::fabs(b.at(lo) - target) <= std::fabs(b.at(hi) - target);
    return low ? lo : hi;
}

// The smallest t in (0, bound] with s_1 = target, or -1 when there is none;
// [lo, hi] receives the range of s_1 seen. s_1 is monotone in t for every
// branch but TANH_TWO with 1/N < c < 1/2, where it rises and then falls:
// so the branch is scanned on a geometric grid for the first sign change,
// and a grid point that comes closest without crossing is refined (golden
// section) in case the extremum between grid points crosses.
double solve_branch(const Branch &b, double target, double &lo, double &hi) {
    constexpr int K = 400;
    constexpr double tmin = 1e-8;  // below it the tanh maps are u exactly
    std::vector<double> t(K + 1), d(K + 1);
    t[0] = 0.0;
    d[0] = b.at(0.0) - target;
    lo = hi = b.at(0.0);
    int closest = 0;
    for (int k = 1; k <= K; ++k) {
        t[k] = k == K ? b.bound : tmin * std::pow(b.bound / tmin, static_cast<double>(k - 1) / (K - 1));
        const double v = b.at(t[k]);
        d[k] = v - target;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        if (d[k] == 0.0) return t[k];
        if (d[k - 1] != 0.0 && (d[k - 1] < 0.0) != (d[k] < 0.0)) return bisect(b, target, t[k - 1], t[k]);
        if (std::fabs(d[k]) < std::fabs(d[closest]) || closest == 0) closest = k;
    }
    if (closest > 0 && closest < K) {
        double a = t[closest - 1], c = t[closest + 1];
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int it = 0; it < 200 && c - a > 1e-15 * c; ++it) {
            const double x1 = c - g * (c - a), x2 = a + g * (c - a);
            if (std::fabs(b.at(x1) - target) < std::fabs(b.at(x2) - target)) c = x2; else a = x1;
        }
        const double te = 0.5 * (a + c), v = b.at(te);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        if (v == target) return te;
        if ((v < target) != (d[closest] < 0.0)) return bisect(b, target, t[closest - 1], te);
    }
    return -1.0;
}

}  // namespace

double distribution_parameter(int id, int n, double first, double p2) {
    if (n < 2) fail(Failure::Argument, format("n = %d: need at least 2 points", n));
    if (!(std::isgreater(first, 0.0) && std::isless(first, 1.0)))  // quiet on NaN
        fail(Failure::Argument, format("first_spacing = %g: must be in (0, 1), a fraction of the length", first));
    if (!std::isfinite(p2)) fail(Failure::Argument, format("p2 = %g: must be finite", p2));
    const int N = n - 1;
    const double uniform = 1.0 / N;
    if (id == EG2D_DIST_VINOKUR) {  // its p1 is the first spacing: check that it and p2 can be met
        std::vector<double> s(static_cast<std::size_t>(n));
        distribute(id, n, first, p2, 1.0, s.data());
        return first;
    }
    if (id == EG2D_DIST_UNIFORM)
        fail(Failure::Argument, "distribution = EG2D_DIST_UNIFORM (0): has no parameter (its first spacing is 1/(n-1))");
    check_closed_form(id, id == EG2D_DIST_TANH_TWO ? 1.0 : 0.5, p2);
    const char *name = id == EG2D_DIST_EXPONENTIAL ? "exponential beta in [-700, 700]"
                       : id == EG2D_DIST_TANH_ONE  ? "tanh delta in (0, 700]"
                                                   : "tanh strength b in (0, 350]";
    if (first == uniform)
        fail(Failure::Argument, format("first_spacing = %g is the uniform spacing 1/(n-1) with n = %d: that is "
                                       "EG2D_DIST_UNIFORM (%s would be 0)", first, n, name));
    // EXPONENTIAL widens the first interval with beta < 0; the tanh maps have t > 0 only.
    const double sign = id == EG2D_DIST_EXPONENTIAL && first > uniform ? -1.0 : 1.0;
    const Branch b{id, N, sign, p2, id == EG2D_DIST_TANH_TWO ? 350.0 : 700.0};
    double lo = 0, hi = 0;
    const double t = solve_branch(b, first, lo, hi);
    if (t < 0.0) {
        if (id == EG2D_DIST_EXPONENTIAL) {  // the other branch's range, for the message
            const Branch other{id, N, -sign, p2, 700.0};
            lo = std::min(lo, other.at(other.bound));
            hi = std::max(hi, other.at(other.bound));
        }
        const std::string c = id == EG2D_DIST_TANH_TWO ? format(" and c = %g", p2) : std::string();
        fail(Failure::Argument,
             format("first_spacing = %g: not reachable with n = %d%s: over %s the first spacing stays within "
                    "[%.6g, %.6g]%s",
                    first, n, c.c_str(), name, lo, hi,
                    id == EG2D_DIST_TANH_ONE && first > uniform
                        ? " (it clusters at s = 0: its first spacing is below the uniform 1/(n-1))"
                        : ""));
    }
    const double got = b.at(t);
    if (!(std::fabs(got - first) <= 1e-12 * first))
        fail(Failure::Argument, format("first_spacing = %.17g: the closest %s gives is %.17g (at %.17g)", first,
                                       name, got, sign * t));
    return sign * t;
}

}  // namespace eg2d
