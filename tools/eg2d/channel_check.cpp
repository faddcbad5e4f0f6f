#include "channel_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "failure.hpp"
#include "formula.hpp"

namespace eg2dtool {

namespace {

struct Point {
    double x, y;
};

std::string str(Point p) { return "(" + fmt(p.x) + ", " + fmt(p.y) + ")"; }

// The sign of the turn a -> b -> c (0: collinear).
int turn(Point a, Point b, Point c) {
    const double v = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return (v > 0) - (v < 0);
}

bool on_segment(Point a, Point b, Point p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// Whether segments ab and cd share a point (touching counts).
bool meet(Point a, Point b, Point c, Point d) {
    const int t1 = turn(a, b, c), t2 = turn(a, b, d), t3 = turn(c, d, a), t4 = turn(c, d, b);
    if (t1 * t2 < 0 && t3 * t4 < 0) return true;
    return (t1 == 0 && on_segment(a, b, c)) || (t2 == 0 && on_segment(a, b, d)) ||
           (t3 == 0 && on_segment(c, d, a)) || (t4 == 0 && on_segment(c, d, b));
}

// The boundary loop: lower wall, outlet, upper wall backwards, inlet; point
// k to k+1 is segment k.
struct Loop {
    std::vector<Point> p;
    std::size_t n;  // nodes per wall

    explicit Loop(const Walls &w) : n(w.lx.size()) {
        for (std::size_t k = 0; k < n; ++k) p.push_back({w.lx[k], w.ly[k]});
        for (std::size_t k = n; k-- > 0;) p.push_back({w.ux[k], w.uy[k]});
    }
    std::size_t segments() const { return p.size(); }
    Point a(std::size_t s) const { return p[s]; }
    Point b(std::size_t s) const { return p[(s + 1) % p.size()]; }
    std::string part(std::size_t s) const {
        if (s + 1 < n) return "the lower wall";
        if (s + 1 == n) return "the outlet";
        if (s + 1 < 2 * n) return "the upper wall";
        return "the inlet";
    }
    bool adjacent(std::size_t s, std::size_t t) const {
        const std::size_t m = p.size();
        return s == t || (s + 1) % m == t || (t + 1) % m == s;
    }
};

// The first pair of non-adjacent segments of the loop that meet: a sweep
// along x or y, whichever the loop spans more.
bool crossing(const Loop &loop, std::size_t &first, std::size_t &second) {
    const std::size_t m = loop.segments();
    double x0 = loop.p[0].x, x1 = x0, y0 = loop.p[0].y, y1 = y0;
    for (const Point &q : loop.p) {
        x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
    }
    const bool along_y = y1 - y0 > x1 - x0;
    auto c = [&](Point q) { return along_y ? q.y : q.x; };
    std::vector<std::size_t> order(m);
    for (std::size_t s = 0; s < m; ++s) order[s] = s;
    auto xmin = [&](std::size_t s) { return std::min(c(loop.a(s)), c(loop.b(s))); };
    auto xmax = [&](std::size_t s) { return std::max(c(loop.a(s)), c(loop.b(s))); };
    std::sort(order.begin(), order.end(), [&](std::size_t s, std::size_t t) { return xmin(s) < xmin(t); });
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t s = order[k];
        for (std::size_t l = k + 1; l < m && xmin(order[l]) <= xmax(s); ++l) {
            const std::size_t t = order[l];
            if (loop.adjacent(s, t)) continue;
            if (meet(loop.a(s), loop.b(s), loop.a(t), loop.b(t))) {
                first = std::min(s, t);
                second = std::max(s, t);
                return true;
            }
        }
    }
    return false;
}

}  // namespace

void check_channel_walls(const Walls &w) {
    const std::size_t n = w.lx.size(), e = n - 1;
    const Point l0{w.lx[0], w.ly[0]}, ln{w.lx[e], w.ly[e]}, u0{w.ux[0], w.uy[0]}, un{w.ux[e], w.uy[e]};
    auto d = [](Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); };
    const std::string ends = ": the lower wall runs from " + str(l0) + " to " + str(ln) + ", the upper from " + str(u0) +
                             " to " + str(un);
    if (d(l0, un) + d(ln, u0) < d(l0, u0) + d(ln, un))
        throw Failure(EXIT_GEOMETRY, "channel: the walls run opposite ways" + ends +
                                         "; give both from the inlet to the outlet");
    if (!(d(l0, u0) > 0)) throw Failure(EXIT_GEOMETRY, "channel: the inlet has no width: both walls start at " + str(l0));
    if (!(d(ln, un) > 0)) throw Failure(EXIT_GEOMETRY, "channel: the outlet has no width: both walls end at " + str(ln));
    const Loop loop(w);
    std::size_t s = 0, t = 0;
    if (crossing(loop, s, t)) {
        const std::string a = loop.part(s), b = loop.part(t);
        const bool ends_cross = a == "the outlet" && b == "the inlet";
        throw Failure(EXIT_GEOMETRY, "channel: " + (a == b ? a + " crosses itself" : a + " and " + b + " cross") +
                                         " between " + str(loop.a(s)) + " and " + str(loop.b(s)) +
                                         (ends_cross ? " (do the walls run opposite ways?" + ends + ")" : std::string()));
    }
    double area = 0;  // the shoelace sum: positive when the loop turns anticlockwise
    for (std::size_t k = 0; k < loop.segments(); ++k)
        area += loop.a(k).x * loop.b(k).y - loop.b(k).x * loop.a(k).y;
    if (!(area > 0))
        throw Failure(EXIT_GEOMETRY, "channel: the upper wall lies to the right of the lower wall (looking from the "
                                     "inlet to the outlet)" + ends + "; swap --lower and --upper");
}

}  // namespace eg2dtool
