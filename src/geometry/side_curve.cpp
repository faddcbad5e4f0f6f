#include "geometry/side_curve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.hpp"
#include "base/plane.hpp"
#include "geometry/distribution.hpp"
#include "geometry/sliding.hpp"

namespace eg2d {

namespace {

// The points of side s as the grid holds them.
void side_points(const Grid &g, Side s, std::vector<double> &x, std::vector<double> &y) {
    g.read_side(s, g.x.data(), g.y.data(), x, y);
}

double signed_area(const std::vector<double> &x, const std::vector<double> &y) {
    return 0.5 * shoelace(x.data(), y.data(), x.size());
}

Side opposite(Side s) {
    switch (s) {
    case Side::JMin: return Side::JMax;
    case Side::JMax: return Side::JMin;
    case Side::IMin: return Side::IMax;
    case Side::IMax: return Side::IMin;
    }
    return s;
}

// Why the points (x, y) run against the grid, or "" if they do not.
std::string against_grid(const Grid &g, Side s, const std::vector<double> &x, const std::vector<double> &y) {
    const std::size_t n = x.size();
    const double size = g.extent() + std::hypot(x[n - 1] - x[0], y[n - 1] - y[0]);
    // Adjacent sides: the corner at this side's start is shared with the
    // side it starts from (JMIN, JMAX: IMIN; IMIN, IMAX: JMIN).
    if (g.topology() != Topology::O) {
        const bool along_i = s == Side::JMin || s == Side::JMax;
        const Side start_side = along_i ? Side::IMin : Side::JMin, end_side = along_i ? Side::IMax : Side::JMax;
        for (Side adj : {start_side, end_side}) {
            if (!g.side_set(adj)) continue;
            std::vector<double> ax, ay;
            side_points(g, adj, ax, ay);
            const std::size_t p = (s == Side::JMin || s == Side::IMin) ? 0 : ax.size() - 1;
            const double cx = ax[p], cy = ay[p];  // the shared corner
            const bool at_start = adj == start_side;
            const double dx_own = at_start ? x[0] - cx : x[n - 1] - cx, dy_own = at_start ? y[0] - cy : y[n - 1] - cy;
            const double dx_rev = at_start ? x[n - 1] - cx : x[0] - cx, dy_rev = at_start ? y[n - 1] - cy : y[0] - cy;
            if (std::hypot(dx_rev, dy_rev) <= 1e-8 * size && std::hypot(dx_own, dy_own) > 1e-8 * size)
                return format("its %s point (%.17g, %.17g) is the corner it shares with side %s, where it should %s",
                              at_start ? "last" : "first", at_start ? x[n - 1] : x[0], at_start ? y[n - 1] : y[0],
                              side_name(adj), at_start ? "start" : "end");
        }
        if (g.side_set(start_side) || g.side_set(end_side)) return "";
    }
    const Side opp = opposite(s);
    if (!g.has_side(opp) || !g.side_set(opp)) return "";
    std::vector<double> ox, oy;
    side_points(g, opp, ox, oy);
    if (g.topology() != Topology::Single && (s == Side::JMin || s == Side::JMax)) {
        const double a = signed_area(x, y), b = signed_area(ox, oy);
        if (a * b < 0)
            return format("it runs %s but side %s runs %s", a > 0 ? "counter-clockwise" : "clockwise", side_name(opp),
                          b > 0 ? "counter-clockwise" : "clockwise");
        return "";
    }
    const double dot = (x[n - 1] - x[0]) * (ox.back() - ox[0]) + (y[n - 1] - y[0]) * (oy.back() - oy[0]);
    if (dot < 0) return format("it runs from first to last point against the direction of side %s", side_name(opp));
    return "";
}

}  // namespace

void curve_points(const ArcLength &curve, int n, int distribution, double p1, double p2, double *x, double *y) {
    std::vector<double> s(static_cast<std::size_t>(n));
    distribute(distribution, n, p1, p2, curve.length(), s.data());
    for (int k = 0; k < n; ++k) curve.point(s[static_cast<std::size_t>(k)], x[k], y[k]);
    check_coordinates("curve x", x, static_cast<std::size_t>(n));
    check_coordinates("curve y", y, static_cast<std::size_t>(n));
}

void set_side_curve(Generator &gen, Side side, const ArcLength &curve, int distribution, double p1, double p2,
                    int flags) {
    const Grid &g = gen.grid();
    if (!g.has_side(side))
        fail(Failure::Argument, format("side %s: an %s has only the sides JMIN and JMAX", side_name(side),
                                       topology_name(g.topology())));
    const int n = g.side_length(side);
    std::vector<double> x(static_cast<std::size_t>(n)), y(static_cast<std::size_t>(n));
    curve_points(curve, n, distribution, p1, p2, x.data(), y.data());
    auto reverse = [&] {
        std::reverse(x.begin(), x.end());
        std::reverse(y.begin(), y.end());
    };
    if (flags & kCurveReverse) reverse();
    const std::string why = against_grid(g, side, x, y);
    if (!why.empty()) {
        if (!(flags & kCurveOrient))
            fail(Failure::Boundary,
                 format("side %s runs against the grid: %s; pass EG2D_CURVE_ORIENT to reverse it when needed, "
                        "or EG2D_CURVE_REVERSE", side_name(side), why.c_str()));
        reverse();
    }
    if (flags & kCurveSliding) {
        // Build the motion before changing anything (strong guarantee). Its
        // parameters are found from the points, so the direction does not matter.
        Grid trial(g);
        trial.set_side(side, x.data(), y.data());
        std::shared_ptr<const BoundaryMotion> motion = make_sliding(trial, side, curve);
        gen.set_side(side, x.data(), y.data());
        gen.set_motion(std::move(motion));
        return;
    }
    gen.set_side(side, x.data(), y.data());
}

}  // namespace eg2d
