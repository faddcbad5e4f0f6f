#include "blocks/join_kinks.hpp"

#include <algorithm>
#include <cmath>

#include "generator/generator.hpp"

namespace eg2d {

namespace {

struct Point {
    double x, y;
};

// The angle in degrees between segments p->q and q->r (0: straight on).
double turn(Point p, Point q, Point r) {
    const double ax = q.x - p.x, ay = q.y - p.y, bx = r.x - q.x, by = r.y - q.y;
    return std::fabs(std::atan2(ax * by - ay * bx, ax * bx + ay * by)) * (180.0 / M_PI);
}

Point at(const Grid &g, const SideRange &r, int t, int depth) {
    const std::size_t k = side_node(g, r.side, r.at(t), depth);
    return Point{g.x[k], g.y[k]};
}

}  // namespace

JoinKinks join_kinks(const BlockSet &set) {
    JoinKinks k;
    for (const Join &j : set.joins()) {
        if (j.held) continue;  // a boundary the lines meet from either side
        const Grid &a = set.block(j.a.block)->grid(), &b = set.block(j.b.block)->grid();
        for (int t = 1; t + 1 < j.a.count(); ++t) {
            // The line across the join: two nodes into a, the joined node, two into b.
            const Point a2 = at(a, j.a, t, 2), a1 = at(a, j.a, t, 1), c = at(a, j.a, t, 0);
            const Point b1 = at(b, j.b, t, 1), b2 = at(b, j.b, t, 2);
            k.at_joins = std::max(k.at_joins, turn(a1, c, b1));
            k.nearby = std::max({k.nearby, turn(a2, a1, c), turn(c, b1, b2)});
        }
    }
    return k;
}

}  // namespace eg2d
