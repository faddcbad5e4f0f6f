#include "geometry/sliding.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/error.hpp"

namespace eg2d {

namespace {

// The curve tabulated at M equal steps of normalized arc length and
// evaluated between by cubic Lagrange interpolation (error O(h^4): about
// 1e-14 of the length for M = 4097 on smooth curves).
constexpr int kTable = 4097;

class Sliding final : public BoundaryMotion {
public:
    Sliding(const Grid &g, Side side, const ArcLength &curve) : side_(side), x_(kTable), y_(kTable) {
        for (int k = 0; k < kTable; ++k)
            curve.point(static_cast<double>(k) / (kTable - 1), x_[static_cast<std::size_t>(k)],
                        y_[static_cast<std::size_t>(k)]);
        // Each node's parameter: the nearest table point, refined.
        const int n = g.side_length(side);
        s_.resize(static_cast<std::size_t>(n));
        for (int p = 0; p < n; ++p) {
            const std::size_t k = node(g, p, 0);
            s_[static_cast<std::size_t>(p)] = nearest(g.x[k], g.y[k], 0.0, 1.0);
        }
        s_.front() = 0.0;
        s_.back() = 1.0;
        s0_ = s_;
    }
    Side side() const override { return side_; }
    void restart() const override { s_ = s0_; }

    void apply(Grid &g) const override {
        const int n = static_cast<int>(s_.size());
        std::vector<double> &s = s_;
        for (int p = 1; p < n - 1; ++p) {
            const std::size_t in = node(g, p, 1);
            // Keep the order: stay between the halfway points to the neighbours.
            const double lo = 0.5 * (s[static_cast<std::size_t>(p - 1)] + s[static_cast<std::size_t>(p)]);
            const double hi = 0.5 * (s[static_cast<std::size_t>(p)] + s[static_cast<std::size_t>(p + 1)]);
            const double t = nearest(g.x[in], g.y[in], lo, hi);
            s[static_cast<std::size_t>(p)] = t;
            const std::size_t b = node(g, p, 0);
            eval(t, g.x[b], g.y[b]);
        }
    }

private:
    std::size_t node(const Grid &g, int p, int depth) const { return side_node(g, side_, p, depth); }
    void eval(double s, double &x, double &y) const {
        const double u = s * (kTable - 1);
        int k = static_cast<int>(std::floor(u)) - 1;
        k = std::max(0, std::min(kTable - 4, k));
        const double t = u - k;  // in [0, 3]
        double w[4];
        w[0] = -(t - 1) * (t - 2) * (t - 3) / 6;
        w[1] = t * (t - 2) * (t - 3) / 2;
        w[2] = -t * (t - 1) * (t - 3) / 2;
        w[3] = t * (t - 1) * (t - 2) / 6;
        x = y = 0.0;
        for (int m = 0; m < 4; ++m) {
            x += w[m] * x_[static_cast<std::size_t>(k + m)];
            y += w[m] * y_[static_cast<std::size_t>(k + m)];
        }
    }
    double distance2(double s, double px, double py) const {
        double x, y;
        eval(s, x, y);
        return (x - px) * (x - px) + (y - py) * (y - py);
    }
    // The parameter in [lo, hi] of the curve point nearest (px, py): the best
    // table point, then golden-section search on the two steps around it.
    double nearest(double px, double py, double lo, double hi) const {
        const int k0 = static_cast<int>(std::ceil(lo * (kTable - 1))), k1 = static_cast<int>(std::floor(hi * (kTable - 1)));
        double best = lo, dbest = distance2(lo, px, py);
        for (int k = k0; k <= k1; ++k) {
            const double s = static_cast<double>(k) / (kTable - 1), d = distance2(s, px, py);
            if (d < dbest) { dbest = d; best = s; }
        }
        if (distance2(hi, px, py) < dbest) best = hi;
        double a = std::max(lo, best - 1.0 / (kTable - 1)), b = std::min(hi, best + 1.0 / (kTable - 1));
        const double g = 0.5 * (std::sqrt(5.0) - 1);
        double c = b - g * (b - a), d = a + g * (b - a), fc = distance2(c, px, py), fd = distance2(d, px, py);
        for (int it = 0; it < 60; ++it) {
            if (fc < fd) { b = d; d = c; fd = fc; c = b - g * (b - a); fc = distance2(c, px, py); }
            else { a = c; c = d; fc = fd; d = a + g * (b - a); fd = distance2(d, px, py); }
        }
        return 0.5 * (a + b);
    }

    Side side_;
    std::vector<double> x_, y_;
    mutable std::vector<double> s_;  // the nodes' normalized arc lengths, updated by apply
    std::vector<double> s0_;         // and as the side was set
};

}  // namespace

std::shared_ptr<const BoundaryMotion> make_sliding(const Grid &grid, Side side, const ArcLength &curve) {
    if (grid.topology() != Topology::Single)
        fail(Failure::Unsupported,
             format("sliding side %s: only single-block grids have sliding sides (this one is an %s)", side_name(side),
                    topology_name(grid.topology())));
    return std::make_shared<Sliding>(grid, side, curve);
}

}  // namespace eg2d
