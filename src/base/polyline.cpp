#include "base/polyline.hpp"

#include <algorithm>
#include <cmath>

namespace eg2d {

std::vector<double> arc_lengths(const std::vector<Vec2> &line) {
    std::vector<double> s(line.size(), 0.0);
    // sqrt, not hypot: coordinates are within kMaxCoordinate (grid.hpp), whose
    // squares cannot overflow, and hypot was a twentieth of a straight
    // channel's graded run.
    for (std::size_t k = 1; k < line.size(); ++k) {
        const double dx = line[k].x - line[k - 1].x, dy = line[k].y - line[k - 1].y;
        s[k] = s[k - 1] + std::sqrt(dx * dx + dy * dy);
    }
    return s;
}

std::vector<Vec2> points_along(const std::vector<Vec2> &line, const std::vector<double> &s) {
    return points_along(line, arc_lengths(line), s);
}

std::vector<Vec2> points_along(const std::vector<Vec2> &line, const std::vector<double> &cum, const std::vector<double> &s) {
    std::vector<Vec2> out;
    out.reserve(s.size());
    if (line.size() < 2) {
        out.assign(s.size(), line.empty() ? Vec2{0, 0} : line[0]);
        return out;
    }
    std::size_t k = 1;
    for (double d : s) {
        d = std::clamp(d, 0.0, cum.back());
        // the segment [cum[k-1], cum[k]] that holds d: walked on from the
        // last one while s rises (as it does from every caller), searched
        // where it falls
        if (d < cum[k - 1]) k = 1;
        while (k + 1 < line.size() && cum[k] < d) ++k;
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

bool wall_corner(const Grid &g, std::size_t a, std::size_t b, std::size_t c) {
    const double ux = g.x[b] - g.x[a], uy = g.y[b] - g.y[a], vx = g.x[c] - g.x[b], vy = g.y[c] - g.y[b];
    return std::fabs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy)) > 0.25 * 3.14159265358979323846;
}

}  // namespace eg2d
