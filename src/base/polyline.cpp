#include "base/polyline.hpp"

#include <algorithm>
#include <cmath>

namespace eg2d {

std::vector<double> arc_lengths(const std::vector<Vec2> &line) {
    std::vector<double> s(line.size(), 0.0);
    for (std::size_t k = 1; k < line.size(); ++k)
        s[k] = s[k - 1] + std::hypot(line[k].x - line[k - 1].x, line[k].y - line[k - 1].y);
    return s;
}

std::vector<Vec2> points_along(const std::vector<Vec2> &line, const std::vector<double> &s) {
    const std::vector<double> cum = arc_lengths(line);
    std::vector<Vec2> out;
    out.reserve(s.size());
    if (line.size() < 2) {
        out.assign(s.size(), line.empty() ? Vec2{0, 0} : line[0]);
        return out;
    }
    for (double d : s) {
        d = std::clamp(d, 0.0, cum.back());
        // the segment [cum[k-1], cum[k]] that holds d
        const std::size_t k = std::max<std::size_t>(
            1, std::min<std::size_t>(line.size() - 1, static_cast<std::size_t>(std::lower_bound(cum.begin(), cum.end(), d) - cum.begin())));
        const double len = cum[k] - cum[k - 1], t = len > 0.0 ? (d - cum[k - 1]) / len : 0.0;
        out.push_back({line[k - 1].x + t * (line[k].x - line[k - 1].x), line[k - 1].y + t * (line[k].y - line[k - 1].y)});
    }
    return out;
}

namespace {
std::size_t node(const Grid &g, int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(g.ni()) * j; }
}  // namespace

std::vector<Vec2> grid_column(const Grid &g, int i, int last) {
    std::vector<Vec2> c(static_cast<std::size_t>(last + 1));
    for (int j = 0; j <= last; ++j) c[static_cast<std::size_t>(j)] = {g.x[node(g, i, j)], g.y[node(g, i, j)]};
    return c;
}

std::vector<Vec2> grid_row(const Grid &g, int j) {
    std::vector<Vec2> r(static_cast<std::size_t>(g.ni()));
    for (int i = 0; i < g.ni(); ++i) r[static_cast<std::size_t>(i)] = {g.x[node(g, i, j)], g.y[node(g, i, j)]};
    return r;
}

void set_node(Grid &g, int i, int j, Vec2 p) {
    g.x[node(g, i, j)] = p.x;
    g.y[node(g, i, j)] = p.y;
}

bool wall_corner(const Grid &g, std::size_t a, std::size_t b, std::size_t c) {
    const double ux = g.x[b] - g.x[a], uy = g.y[b] - g.y[a], vx = g.x[c] - g.x[b], vy = g.y[c] - g.y[b];
    return std::fabs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy)) > 0.25 * 3.14159265358979323846;
}

}  // namespace eg2d
