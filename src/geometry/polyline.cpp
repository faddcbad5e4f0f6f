// A polyline with t proportional to arc length: t_k = (length up to point k)/L.
#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "geometry/curve.hpp"
#include "base/grid.hpp"

namespace eg2d {


namespace {

class Polyline final : public Curve {
public:
    Polyline(const double *x, const double *y, int n) : x_(x, x + n), y_(y, y + n), t_(static_cast<std::size_t>(n)) {
        t_[0] = 0.0;
        for (std::size_t k = 1; k < t_.size(); ++k) t_[k] = t_[k - 1] + std::hypot(x_[k] - x_[k - 1], y_[k] - y_[k - 1]);
        const double L = t_.back();
        if (!(L > 0.0)) fail(Failure::Argument, format("the %d points all lie at (%g, %g)", n, x[0], y[0]));
        for (double &t : t_) t /= L;
    }
    void eval(double t, double &x, double &y) const override {
        const std::size_t k = segment(t);
        const double d = t_[k + 1] - t_[k], u = d > 0 ? (t - t_[k]) / d : 0.0;
        x = x_[k] + u * (x_[k + 1] - x_[k]);
        y = y_[k] + u * (y_[k + 1] - y_[k]);
    }
    void derivative(double t, double lo, double hi, double &dx, double &dy) const override {
        (void)t;  // the piece [lo, hi] is one segment: the derivative is constant on it
        const std::size_t k = segment(0.5 * (lo + hi));
        const double d = t_[k + 1] - t_[k];
        dx = (x_[k + 1] - x_[k]) / d;
        dy = (y_[k + 1] - y_[k]) / d;
    }
    std::vector<double> breaks() const override { return std::vector<double>(t_.begin() + 1, t_.end() - 1); }
    double speed_round_off(double, double, double) const override { return 0.0; }  // the derivative is exact

private:
    std::size_t segment(double t) const {
        // The last segment whose start is <= t (a repeated point has a zero-length segment, never chosen).
        const std::size_t k =
            static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end() - 1, t) - t_.begin());
        return k == 0 ? 0 : k - 1;
    }
    std::vector<double> x_, y_, t_;
};

}  // namespace

std::shared_ptr<Curve> make_polyline(const double *x, const double *y, int n) {
    if (n < 2) fail(Failure::Argument, format("n = %d: a polyline needs at least 2 points", n));
    check_coordinates("x", x, static_cast<std::size_t>(n));
    check_coordinates("y", y, static_cast<std::size_t>(n));
    return std::make_shared<Polyline>(x, y, n);
}

}  // namespace eg2d
