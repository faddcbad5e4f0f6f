#include "grid/hybrid_cgrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/polyline.hpp"

namespace eg2d {

std::vector<double> cut_first_heights(const Grid &g, double h) {
    const int ni = g.ni(), wake = g.connectivity().wake();
    std::vector<double> first(static_cast<std::size_t>(ni), h);
    if (g.topology() != Topology::C || wake <= 0) return first;
    const std::vector<Vec2> cut = grid_row(g, 0);
    auto gap = [&](int a) {
        return std::hypot(cut[static_cast<std::size_t>(a + 1)].x - cut[static_cast<std::size_t>(a)].x,
                          cut[static_cast<std::size_t>(a + 1)].y - cut[static_cast<std::size_t>(a)].y);
    };
    const double te = gap(wake - 1);
    for (int i = 0; i < wake; ++i) {
        const double ratio = te > 0.0 ? gap(i) / te : 1.0;
        first[static_cast<std::size_t>(i)] = first[static_cast<std::size_t>(ni - 1 - i)] = h * std::sqrt(std::max(1.0, ratio));
    }
    return first;
}

void place_outflow_side(Grid &g, const Grid &m, int i, int rows) {
    const int nj = g.nj();
    const std::vector<Vec2> side = grid_column(g, i, nj - 1);
    const std::vector<double> user = arc_lengths(side), march = arc_lengths(grid_column(m, i, nj - 1));
    const double total = user.back(), base = std::min(march[static_cast<std::size_t>(rows)], total);
    const double rest = march.back() - march[static_cast<std::size_t>(rows)];
    std::vector<double> want(static_cast<std::size_t>(nj));
    for (int j = 0; j < nj; ++j) {
        const std::size_t k = static_cast<std::size_t>(j);
        want[k] = j <= rows ? std::min(march[k], total)
                            : base + (total - base) * (march[k] - march[static_cast<std::size_t>(rows)]) / rest;
    }
    const std::vector<Vec2> p = points_along(side, want);
    for (int j = 1; j < nj - 1; ++j) set_node(g, i, j, p[static_cast<std::size_t>(j)]);
}

double respace_far_field(Grid &g, const Grid &m) {
    const int ni = g.ni(), top = g.nj() - 1;
    const std::vector<Vec2> line = grid_row(g, top), target = grid_row(m, top);
    const std::vector<double> arc = arc_lengths(line);
    const double total = arc.back(), gap = 1e-9 * total;
    std::vector<double> want(static_cast<std::size_t>(ni), 0.0);
    for (int i = 1; i < ni - 1; ++i) {  // the nearest point of the line, as an arc length
        const Vec2 p = target[static_cast<std::size_t>(i)];
        double best = std::numeric_limits<double>::infinity(), where = 0.0;
        for (int k = 0; k + 1 < ni; ++k) {
            const Vec2 a = line[static_cast<std::size_t>(k)], b = line[static_cast<std::size_t>(k + 1)];
            const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
            const double t = l2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
            if (d < best) {
                best = d;
                where = arc[static_cast<std::size_t>(k)] + t * std::sqrt(l2);
            }
        }
        want[static_cast<std::size_t>(i)] = std::max(where, want[static_cast<std::size_t>(i - 1)] + gap);
    }
    want[static_cast<std::size_t>(ni - 1)] = total;
    for (int i = ni - 2; i > 0; --i)  // in order at the far end too
        want[static_cast<std::size_t>(i)] = std::min(want[static_cast<std::size_t>(i)], want[static_cast<std::size_t>(i + 1)] - gap);
    const std::vector<Vec2> p = points_along(line, want);
    double moved = 0.0;
    for (int i = 1; i < ni - 1; ++i) {
        moved = std::max(moved, std::fabs(want[static_cast<std::size_t>(i)] - arc[static_cast<std::size_t>(i)]));
        set_node(g, i, top, p[static_cast<std::size_t>(i)]);
    }
    return total > 0.0 ? moved / total : 0.0;
}

}  // namespace eg2d
