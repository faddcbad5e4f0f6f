// Arc-length reparameterisation, the grid-generation lecture notes eq 2.11: the integral by adaptive
// Gauss-Legendre panels, its inverse by Newton's method (as the lecture notes say)
// safeguarded by bisection on the panel that holds the answer.
#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "geometry/curve.hpp"

namespace eg2d {

namespace {
// 5-point Gauss-Legendre nodes and weights on [-1, 1].
const double kNode[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                         0.9061798459386640};
const double kWeight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                           0.2369268850561891};
constexpr int kInitialPanels = 16;  // per smooth piece, before refinement
constexpr int kMaxDepth = 30;
constexpr double kRelativeTolerance = 1e-14;
// Panels one curve may use. Depth alone bounds a path, not the tree: a curve
// whose tolerance cannot be met anywhere (noise in a callback, or a length
// in the subnormal range, found by fuzz_api) would otherwise make 2^30 panels.
constexpr std::size_t kMaxPanels = std::size_t{1} << 16;
// The tolerance is not tried where the round-off bound over a piece is this
// far above it: the panels' round-off falls with their width, but it would
// take more than kMaxPanels of them (the bound is about 100x the round-off
// seen on smooth callbacks).
constexpr double kFarBelow = 1e7;
}  // namespace

double ArcLength::speed(double t, std::size_t piece) const {
    double dx, dy;
    curve_->derivative(t, knots_[piece], knots_[piece + 1], dx, dy);
    const double v = std::hypot(dx, dy);
    if (!std::isfinite(v)) fail(Failure::Argument, format("the curve's derivative at t = %.17g is not finite", t));
    return v;
}

double ArcLength::integrate(double a, double b, std::size_t piece) const {
    const double m = 0.5 * (a + b), h = 0.5 * (b - a);
    double sum = 0.0;
    for (int k = 0; k < 5; ++k) sum += kWeight[k] * speed(m + h * kNode[k], piece);
    return h * sum;
}

bool ArcLength::refine(double a, double b, double whole, std::size_t piece, int depth, double tol, double noise) {
    const double m = 0.5 * (a + b);
    const double left = integrate(a, m, piece), right = integrate(m, b, piece);
    // The three integrals' round-off is at most about noise (b - a) each.
    if (depth >= kMaxDepth || std::fabs(left + right - whole) <= std::max(tol, 3.0 * noise * (b - a))) {
        t_.push_back(m);
        piece_.push_back(piece);
        cumulative_.push_back(cumulative_.back() + left);
        t_.push_back(b);
        piece_.push_back(piece);
        cumulative_.push_back(cumulative_.back() + right);
        return true;
    }
    if (t_.size() >= kMaxPanels) return false;
    return refine(a, m, left, piece, depth + 1, tol, noise) && refine(m, b, right, piece, depth + 1, tol, noise);
}

bool ArcLength::tabulate(double tol, double r_max, bool with_round_off) {
    t_.assign(1, 0.0);
    piece_.assign(1, 0);
    cumulative_.assign(1, 0.0);
    for (std::size_t p = 0; p + 1 < knots_.size(); ++p) {
        const double noise = with_round_off ? curve_->speed_round_off(knots_[p], knots_[p + 1], r_max) : 0.0;
        for (int k = 0; k < kInitialPanels; ++k) {
            const double a = knots_[p] + (knots_[p + 1] - knots_[p]) * k / kInitialPanels;
            const double c = k + 1 == kInitialPanels ? knots_[p + 1]
                                                     : knots_[p] + (knots_[p + 1] - knots_[p]) * (k + 1) / kInitialPanels;
            if (!refine(a, c, integrate(a, c, p), p, 0, tol, noise)) return false;
        }
    }
    return true;
}

ArcLength::ArcLength(std::shared_ptr<const Curve> curve) : curve_(std::move(curve)) {
    knots_.push_back(0.0);
    std::vector<double> b = curve_->breaks();
    std::sort(b.begin(), b.end());
    for (double t : b)
        if (t > knots_.back() && t < 1.0) knots_.push_back(t);
    knots_.push_back(1.0);
    // A first estimate of the length sets the absolute tolerance of the
    // panels; the points' distance from the origin, the speed's round-off.
    double estimate = 0.0, r_max = 0.0;
    for (std::size_t p = 0; p + 1 < knots_.size(); ++p)
        for (int k = 0; k < kInitialPanels; ++k) {
            const double a = knots_[p] + (knots_[p + 1] - knots_[p]) * k / kInitialPanels;
            const double c = knots_[p] + (knots_[p + 1] - knots_[p]) * (k + 1) / kInitialPanels;
            estimate += integrate(a, c, p);
            double x, y;
            curve_->eval(a, x, y);
            r_max = std::max({r_max, std::fabs(x), std::fabs(y)});
        }
    if (!(estimate > 0.0) || !std::isfinite(estimate))
        fail(Failure::Argument, format("the curve has length %g: need a finite, positive length", estimate));
    // 1e-14 of the length where the curve's points resolve it; to the
    // speed's round-off where they do not (Curve::speed_round_off: a piece
    // far shorter than its distance from the origin), which the bound on the
    // panels finds, or the bound on that round-off says up front.
    const double tol = kRelativeTolerance * estimate;
    bool hopeless = false;  // the round-off far above the tolerance somewhere
    for (std::size_t p = 0; p + 1 < knots_.size(); ++p)
        hopeless = hopeless || curve_->speed_round_off(knots_[p], knots_[p + 1], r_max) *
                                             (knots_[p + 1] - knots_[p]) > kFarBelow * tol;
    if (!(!hopeless && tabulate(tol, r_max, false)) && !tabulate(tol, r_max, true))
        fail(Failure::Argument, format("the curve's arc length does not converge to %g of its length within %zu "
                                       "panels: the curve is not smooth, or too small (length %g)",
                                       kRelativeTolerance, kMaxPanels, estimate));
    double x, y;
    for (double t : {0.0, 0.5, 1.0}) {
        curve_->eval(t, x, y);
        if (!std::isfinite(x) || !std::isfinite(y))
            fail(Failure::Argument, format("the curve's point at t = %g is (%g, %g): must be finite", t, x, y));
    }
}

double ArcLength::parameter(double s) const {
    if (s <= 0.0) return 0.0;
    if (s >= 1.0) return 1.0;
    const double target = s * length();
    // Panel k holds the answer: cumulative_[k] <= target < cumulative_[k+1].
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), target) -
                                 cumulative_.begin()) - 1;
    if (k + 1 >= t_.size()) return 1.0;
    double lo = t_[k], hi = t_[k + 1];
    const std::size_t piece = piece_[k + 1];
    const double base = cumulative_[k], a = t_[k];
    double t = lo + (hi - lo) * (target - base) / (cumulative_[k + 1] - base);
    for (int it = 0; it < 60; ++it) {
        const double f = base + integrate(a, t, piece) - target;
        if (f > 0) hi = t; else lo = t;
        if (std::fabs(f) <= 1e-15 * length()) break;
        double next = t - f / speed(t, piece);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket
        if (next == t) break;
        t = next;
    }
    return t;
}

void ArcLength::point(double s, double &x, double &y) const {
    curve_->eval(parameter(s), x, y);
}

}  // namespace eg2d
