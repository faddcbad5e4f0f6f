#include "grid/march_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.hpp"

namespace eg2d {

namespace {
// h_1 (1 + r + ... + r^(N-1)): the distance N layers cover.
double covered(int n, double h1, double r) {
    if (std::fabs(r - 1.0) < 1e-12) return h1 * n;
    // Past e^700 the sum is beyond any distance: said as infinity without
    // computing the power, which would raise the overflow flag (a host with
    // FP traps dies of it).
    if (n * std::log(r) > 700.0) return std::numeric_limits<double>::infinity();
    return h1 * (std::pow(r, n) - 1.0) / (r - 1.0);
}
}  // namespace

double covering_ratio(int n, double first, double distance) {
    if (first * n >= distance) return 1.0;
    double lo = 1.0, hi = 2.0;
    while (covered(n, first, hi) < distance) hi *= 2.0;
    for (int it = 0; it < 200; ++it) {
        const double r = 0.5 * (lo + hi);
        (covered(n, first, r) < distance ? lo : hi) = r;
    }
    return 0.5 * (lo + hi);
}

namespace {

// The x with sum_k exp(a_k + b_k x) = target, all b_k of one sign (not all
// 0), x in [lo, hi] where the sum crosses the target: Newton on the log of
// the sum (convex in x), kept inside the bracket, which each step narrows.
// 5-10 steps where bisection took 100 (NACA 0012 1793x513: 3600 columns of
// 341 cells).
double solve_exp_sum(const std::vector<double> &a, const std::vector<double> &b, double target, double lo,
                     double hi, const double *guess) {
    const double goal = std::log(target);
    auto eval = [&](double x, double &g, double &slope) {
        double top = -std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < a.size(); ++k) top = std::max(top, a[k] + b[k] * x);
        double sum = 0.0, weighted = 0.0;
        for (std::size_t k = 0; k < a.size(); ++k) {
            const double e = std::exp(a[k] + b[k] * x - top);
            sum += e;
            weighted += b[k] * e;
        }
        g = top + std::log(sum) - goal;
        slope = weighted / sum;
    };
    const bool rising = b.back() + b.front() > 0.0;
    // isgreater/isless: a NaN guess (none yet) compares quietly, raising no FP flag.
    double x = guess && std::isgreater(*guess, lo) && std::isless(*guess, hi) ? *guess : 0.5 * (lo + hi);
    for (int it = 0; it < 100; ++it) {
        double g, slope;
        eval(x, g, slope);
        ((g > 0.0) == rising ? hi : lo) = x;
        double next = slope != 0.0 ? x - g / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::fabs(next - x) <= 1e-15 * std::max(1.0, std::fabs(x)) || hi - lo <= 1e-15 * std::max(1.0, std::fabs(x)))
            return next;
        x = next;
    }
    return x;
}

}  // namespace

std::vector<double> graded_cells(int n, double first, double last, double distance, double *guess) {
    // cell k = exp(ln first + slope k + q k (k - (n-1))): the sum falls as q rises.
    const double la = std::log(first), slope = (std::log(last) - la) / (n - 1);
    std::vector<double> a(static_cast<std::size_t>(n)), b(a.size());
    for (int k = 0; k < n; ++k) {
        a[static_cast<std::size_t>(k)] = la + slope * k;
        b[static_cast<std::size_t>(k)] = static_cast<double>(k) * (k - (n - 1));
    }
    b.front() = b.back() = -1e-300;  // 0 at both ends: the sign for solve_exp_sum
    // A bracket: the middle cell's log can move by at most the span of the logs.
    const double span = 2.0 * (std::fabs(std::log(distance)) + std::fabs(la) + std::fabs(std::log(last)) + 50.0);
    const double mid = 0.25 * (n - 1.0) * (n - 1.0);
    const double q = solve_exp_sum(a, b, distance, -span / mid, span / mid, guess);
    if (guess) *guess = q;
    std::vector<double> c(a.size());
    double sum = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) sum += (c[k] = std::exp(a[k] + b[k] * q));
    for (double &v : c) v *= distance / sum;  // the solve's last digits
    return c;
}

double largest_graded_first(int n, double last, double distance, double *guess) {
    // first exp(q k^2) with first exp(q (n-1)^2) = last, u = ln first: cell k
    // = exp(ln last t_k + u (1 - t_k)), t_k = (k / (n-1))^2; the sum rises with u.
    const double top = std::log(std::min(last, distance / n));
    std::vector<double> a(static_cast<std::size_t>(n)), b(a.size());
    for (int k = 0; k < n; ++k) {
        const double t = (static_cast<double>(k) / (n - 1)) * (static_cast<double>(k) / (n - 1));
        a[static_cast<std::size_t>(k)] = std::log(last) * t;
        b[static_cast<std::size_t>(k)] = 1.0 - t;
    }
    b.back() = 1e-300;
    double total = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) total += std::exp(a[k] + b[k] * top);
    if (total <= distance) return std::exp(top);
    const double u = solve_exp_sum(a, b, distance, top - 800.0, top, guess);
    if (guess) *guess = u;
    return std::exp(u);
}

std::vector<double> march_schedule(int layers, double distance, double first_height, double growth) {
    double h1 = first_height, r = 1.0;
    if (h1 == 0.0) {
        r = 1.0 + 0.5 * (growth - 1.0);
        h1 = distance / covered(layers, 1.0, r);
    } else {
        const double lo = 1.0 / growth, hi = growth;
        if (covered(layers, h1, hi) < distance * (1 - 1e-12))
            fail(Failure::Argument,
                 format("march: %d layers from a first height of %g reach only %g with growth %g, not the "
                        "distance %g: raise the first height, the growth limit or nj",
                        layers, h1, covered(layers, h1, hi), growth, distance));
        if (covered(layers, h1, lo) > distance * (1 + 1e-12))
            fail(Failure::Argument,
                 format("march: %d layers from a first height of %g go at least %g (shrinking by 1/%g), beyond "
                        "the distance %g: lower the first height or nj", layers, h1, covered(layers, h1, lo),
                        growth, distance));
        // covered() increases with r: bisect for h1 * S(r) = D.
        double a = lo, b = hi;
        for (int it = 0; it < 200 && b - a > 1e-15; ++it) {
            const double m = 0.5 * (a + b);
            (covered(layers, h1, m) < distance ? a : b) = m;
        }
        r = 0.5 * (a + b);
    }
    std::vector<double> h(static_cast<std::size_t>(layers));
    for (int k = 0; k < layers; ++k) h[static_cast<std::size_t>(k)] = h1 * std::pow(r, k);
    return h;
}

}  // namespace eg2d
