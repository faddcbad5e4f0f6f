#include "grid/march_schedule.hpp"

#include <cmath>

#include "base/error.hpp"

namespace eg2d {

namespace {
// h_1 (1 + r + ... + r^(N-1)): the distance N layers cover.
double covered(int n, double h1, double r) {
    if (std::fabs(r - 1.0) < 1e-12) return h1 * n;
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

std::vector<double> graded_cells(int n, double first, double last, double distance) {
    const double la = std::log(first), slope = (std::log(last) - la) / (n - 1);
    auto cells = [&](double q) {
        std::vector<double> c(static_cast<std::size_t>(n));
        for (int k = 0; k < n; ++k) c[static_cast<std::size_t>(k)] = std::exp(la + slope * k + q * k * (k - (n - 1)));
        return c;
    };
    auto sum = [](const std::vector<double> &c) {
        double t = 0.0;
        for (double v : c) t += v;
        return t;
    };
    // The sum falls as q rises (k (k - (n-1)) <= 0): bracket, then bisect.
    double lo = -1.0, hi = 1.0;
    while (sum(cells(lo)) < distance) lo *= 2.0;
    while (sum(cells(hi)) > distance) hi *= 2.0;
    for (int it = 0; it < 100; ++it) {
        const double q = 0.5 * (lo + hi);
        (sum(cells(q)) > distance ? lo : hi) = q;
    }
    std::vector<double> c = cells(0.5 * (lo + hi));
    const double scale = distance / sum(c);  // the bisection's last digits
    for (double &v : c) v *= scale;
    return c;
}

double largest_graded_first(int n, double last, double distance) {
    // first exp(q k^2) with first exp(q (n-1)^2) = last: the sum rises with first.
    auto sum = [&](double first) {
        const double q = std::log(last / first) / ((n - 1.0) * (n - 1.0));
        double t = 0.0;
        for (int k = 0; k < n; ++k) t += first * std::exp(q * k * k);
        return t;
    };
    double lo = 0.0, hi = std::min(last, distance / n);
    if (sum(hi) <= distance) return hi;
    for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (sum(mid) < distance ? lo : hi) = mid;
    }
    return lo;
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
