// The interpolating cubic spline through points, parameterised by cumulative
// chord length (t_k = chord length up to point k / total): closed curves are
// periodic splines (a cyclic tridiagonal system), open ones natural splines.
#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "geometry/curve.hpp"
#include "base/grid.hpp"
#include "base/tridiagonal.hpp"

namespace eg2d {


namespace {

class Spline final : public Curve {
public:
    Spline(std::vector<double> x, std::vector<double> y, bool periodic)
        : x_(std::move(x)), y_(std::move(y)), t_(x_.size()) {
        const std::size_t n = x_.size();
        t_[0] = 0.0;
        for (std::size_t k = 1; k < n; ++k) t_[k] = t_[k - 1] + std::hypot(x_[k] - x_[k - 1], y_[k] - y_[k - 1]);
        for (double &t : t_) t /= t_.back();
        mx_ = second_derivatives(x_, periodic);
        my_ = second_derivatives(y_, periodic);
    }
    void eval(double t, double &x, double &y) const override {
        const std::size_t k = interval(t);
        x = value(x_, mx_, k, t);
        y = value(y_, my_, k, t);
    }
    void derivative(double t, double lo, double hi, double &dx, double &dy) const override {
        const std::size_t k = interval(0.5 * (lo + hi));  // [lo, hi] is one interval
        dx = slope(x_, mx_, k, t);
        dy = slope(y_, my_, k, t);
    }
    std::vector<double> breaks() const override { return std::vector<double>(t_.begin() + 1, t_.end() - 1); }
    double speed_round_off(double, double, double) const override { return 0.0; }  // the derivative is exact

private:
    std::size_t interval(double t) const {
        const std::size_t k =
            static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end() - 1, t) - t_.begin());
        return k == 0 ? 0 : k - 1;
    }
    double value(const std::vector<double> &f, const std::vector<double> &m, std::size_t k, double t) const {
        const double h = t_[k + 1] - t_[k], a = t_[k + 1] - t, b = t - t_[k];
        return (m[k] * a * a * a + m[k + 1] * b * b * b) / (6 * h) + (f[k] / h - m[k] * h / 6) * a +
               (f[k + 1] / h - m[k + 1] * h / 6) * b;
    }
    double slope(const std::vector<double> &f, const std::vector<double> &m, std::size_t k, double t) const {
        const double h = t_[k + 1] - t_[k], a = t_[k + 1] - t, b = t - t_[k];
        // The points' difference taken first: far from the origin (an outline
        // shifted by 1e6) f/h each lose what the arc length needs.
        return (-m[k] * a * a + m[k + 1] * b * b) / (2 * h) + (f[k + 1] - f[k]) / h - (m[k + 1] - m[k]) * h / 6;
    }
    // h_{k-1} M_{k-1} + 2(h_{k-1} + h_k) M_k + h_k M_{k+1} = 6 (slope_k - slope_{k-1}).
    std::vector<double> second_derivatives(const std::vector<double> &f, bool periodic) const {
        const std::size_t n = f.size();
        std::vector<double> m(n, 0.0);
        auto h = [&](std::size_t k) { return t_[k + 1] - t_[k]; };
        auto rhs = [&](std::size_t km, std::size_t k, std::size_t kp) {
            return 6 * ((f[kp] - f[k]) / h(k) - (f[k] - f[km]) / h(km));
        };
        if (periodic) {  // unknowns M_0 .. M_{n-2}; M_{n-1} = M_0
            const std::size_t p = n - 1;
            std::vector<double> a(p), b(p), c(p), d(p), work;
            for (std::size_t k = 0; k < p; ++k) {
                const std::size_t km = k == 0 ? p - 1 : k - 1;
                a[k] = h(km);
                c[k] = h(k);
                b[k] = 2 * (a[k] + c[k]);
                d[k] = 6 * ((f[k + 1] - f[k]) / h(k) - (f[km + 1] - f[km]) / h(km));
            }
            solve_cyclic_tridiagonal(p, a.data(), b.data(), c.data(), d.data(), work);
            std::copy(d.begin(), d.end(), m.begin());
            m[n - 1] = m[0];
            return m;
        }
        if (n < 3) return m;  // a straight segment
        const std::size_t p = n - 2;  // natural ends: M_0 = M_{n-1} = 0
        std::vector<double> a(p), b(p), c(p), d(p);
        for (std::size_t q = 0; q < p; ++q) {
            const std::size_t k = q + 1;
            a[q] = h(k - 1);
            c[q] = h(k);
            b[q] = 2 * (a[q] + c[q]);
            d[q] = rhs(k - 1, k, k + 1);
        }
        solve_tridiagonal(p, a.data(), b.data(), c.data(), d.data());
        std::copy(d.begin(), d.end(), m.begin() + 1);
        return m;
    }

    std::vector<double> x_, y_, t_, mx_, my_;
};

}  // namespace

std::shared_ptr<Curve> make_spline(const double *x, const double *y, int n, bool corner_at_ends) {
    if (n < 2) fail(Failure::Argument, format("n = %d: a spline needs at least 2 points", n));
    check_coordinates("x", x, static_cast<std::size_t>(n));
    check_coordinates("y", y, static_cast<std::size_t>(n));
    std::vector<double> px, py;  // repeated consecutive points would give zero-length intervals: drop them
    for (int k = 0; k < n; ++k) {
        if (!px.empty() && x[k] == px.back() && y[k] == py.back()) continue;
        px.push_back(x[k]);
        py.push_back(y[k]);
    }
    if (px.size() < 2) fail(Failure::Argument, format("the %d points all lie at (%g, %g)", n, x[0], y[0]));
    double size = 0.0;
    for (std::size_t k = 1; k < px.size(); ++k) size += std::hypot(px[k] - px[k - 1], py[k] - py[k - 1]);
    const bool closed = std::hypot(x[n - 1] - x[0], y[n - 1] - y[0]) <= 1e-12 * size;
    if (closed) {  // exactly closed: the first point again
        px.push_back(x[0]);
        py.push_back(y[0]);
        if (std::hypot(px[px.size() - 2] - x[0], py[py.size() - 2] - y[0]) <= 1e-12 * size) {
            px.erase(px.end() - 2);
            py.erase(py.end() - 2);
        }
    }
    const bool periodic = closed && !corner_at_ends && px.size() >= 4;
    return std::make_shared<Spline>(std::move(px), std::move(py), periodic);
}

}  // namespace eg2d
