#include "base/self_crossing.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace eg2d {

namespace {

struct Segment {
    double x0, y0, x1, y1;
    Side side;
    int node;  // first node along the side
};

// Twice the signed area of (p, q, r), zero within tol.
double turn(double px, double py, double qx, double qy, double rx, double ry, double tol) {
    const double t = (qx - px) * (ry - py) - (qy - py) * (rx - px);
    return std::fabs(t) <= tol ? 0.0 : t;
}

// The segments of a side from node `from` to node `to` (either way).
void add_side(const Grid &g, Side s, int from, int to, std::vector<Segment> &out) {
    const int step = to >= from ? 1 : -1;
    for (int p = from; p != to; p += step) {
        const std::size_t k = side_node(g, s, p), m = side_node(g, s, p + step);
        if (g.x[k] == g.x[m] && g.y[k] == g.y[m]) continue;  // a repeated point
        out.push_back({g.x[k], g.y[k], g.x[m], g.y[m], s, std::min(p, p + step)});
    }
}

}  // namespace

BoundaryCrossing find_boundary_crossing(const Grid &g) {
    const int ni = g.ni(), nj = g.nj();
    std::vector<Segment> seg;
    add_side(g, Side::JMin, 0, ni - 1, seg);
    if (g.topology() == Topology::O) {
        add_side(g, Side::JMax, 0, ni - 1, seg);
    } else {
        add_side(g, Side::IMax, 0, nj - 1, seg);
        add_side(g, Side::JMax, ni - 1, 0, seg);
        add_side(g, Side::IMin, nj - 1, 0, seg);
    }
    // Turns below this are "on the line": rounding, or a wake cut's two sides.
    const double L = g.extent(), tol = 1e-12 * L * L;
    std::vector<std::size_t> order(seg.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    auto xmin = [&](std::size_t k) { return std::min(seg[k].x0, seg[k].x1); };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return xmin(a) < xmin(b); });
    for (std::size_t u = 0; u < order.size(); ++u) {
        const Segment &p = seg[order[u]];
        const double pxmax = std::max(p.x0, p.x1), pymin = std::min(p.y0, p.y1), pymax = std::max(p.y0, p.y1);
        for (std::size_t v = u + 1; v < order.size() && xmin(order[v]) <= pxmax; ++v) {
            const Segment &q = seg[order[v]];
            if (std::max(q.y0, q.y1) < pymin || std::min(q.y0, q.y1) > pymax) continue;
            const double d1 = turn(p.x0, p.y0, p.x1, p.y1, q.x0, q.y0, tol);
            const double d2 = turn(p.x0, p.y0, p.x1, p.y1, q.x1, q.y1, tol);
            const double d3 = turn(q.x0, q.y0, q.x1, q.y1, p.x0, p.y0, tol);
            const double d4 = turn(q.x0, q.y0, q.x1, q.y1, p.x1, p.y1, tol);
            if (!(d1 * d2 < 0.0 && d3 * d4 < 0.0)) continue;
            const double t = d3 / (d3 - d4);  // along p
            const double x = p.x0 + t * (p.x1 - p.x0), y = p.y0 + t * (p.y1 - p.y0);
            // named in side order (JMIN, IMAX, JMAX, IMIN), then node order
            const bool p_first = std::make_pair(p.side, p.node) < std::make_pair(q.side, q.node);
            const Segment &f = p_first ? p : q, &s = p_first ? q : p;
            return {true, f.side, s.side, f.node, s.node, x, y};
        }
    }
    return {};
}

}  // namespace eg2d
