#include "quality/wall_layer_stats.hpp"

#include <algorithm>
#include <cmath>

#include "base/patches.hpp"
#include "base/polyline.hpp"

namespace eg2d {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::vector<WallNodeStats> wall_stretch_stats(const Grid &g, Side s, int first, int last, int rows) {
    std::vector<WallNodeStats> out;
    const int n = g.side_length(s);
    const int depth = (s == Side::JMin || s == Side::JMax) ? g.nj() : g.ni();
    rows = std::min(rows, depth - 1);
    auto corner = [&](int q) {
        if (q <= first || q >= last) return false;
        return wall_corner(g, side_node(g, s, q - 1), side_node(g, s, q), side_node(g, s, q + 1));
    };
    for (int q = first + 1; q < last; ++q) {
        if (corner(q - 1) || corner(q) || corner(q + 1)) continue;
        const std::size_t k0 = side_node(g, s, q), kp = side_node(g, s, std::min(q + 1, n - 1)),
                          km = side_node(g, s, std::max(q - 1, 0));
        const double tx = g.x[kp] - g.x[km], ty = g.y[kp] - g.y[km], tl = std::hypot(tx, ty);
        const std::size_t k1 = side_node(g, s, q, 1);
        const double dx = g.x[k1] - g.x[k0], dy = g.y[k1] - g.y[k0], dl = std::hypot(dx, dy);
        if (!(tl > 0 && dl > 0)) continue;
        WallNodeStats w{std::fabs(tx * dy - ty * dx) / tl,
                        std::asin(std::min(1.0, std::fabs(tx * dx + ty * dy) / (tl * dl))) * 180.0 / kPi, 0.0};
        double before = dl;
        for (int m = 2; m <= rows; ++m) {
            const std::size_t a = side_node(g, s, q, m - 1), b = side_node(g, s, q, m);
            const double d = std::hypot(g.x[b] - g.x[a], g.y[b] - g.y[a]);
            if (before > 0) w.growth = std::max(w.growth, d / before);
            before = d;
        }
        out.push_back(w);
    }
    return out;
}

WallLayerFigures wall_layer_figures(const Grid &g, Side s, int rows) {
    std::vector<WallNodeStats> all;
    bool walls = false;
    for (const Patch &p : resolve_patches(g))
        if (p.side == s && p.type == PatchType::Wall) {
            walls = true;
            const std::vector<WallNodeStats> v = wall_stretch_stats(g, s, p.first, p.last, rows);
            all.insert(all.end(), v.begin(), v.end());
        }
    if (!walls) all = wall_stretch_stats(g, s, 0, g.side_length(s) - 1, rows);
    WallLayerFigures f;
    f.nodes = static_cast<int>(all.size());
    if (all.empty()) return f;
    std::vector<double> h;
    for (const WallNodeStats &w : all) {
        h.push_back(w.height);
        f.growth = std::max(f.growth, w.growth);
        f.angle = std::max(f.angle, w.angle);
    }
    std::sort(h.begin(), h.end());
    f.first_min = h.front();
    f.first_max = h.back();
    const std::size_t m = h.size() / 2;
    f.first_median = h.size() % 2 ? h[m] : 0.5 * (h[m - 1] + h[m]);
    return f;
}

}  // namespace eg2d
