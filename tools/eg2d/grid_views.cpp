#include "grid_views.hpp"

#include <algorithm>
#include <cmath>

#include "failure.hpp"

namespace eg2dtool {

View domain_view(const GridLines &g) {
    const auto [xlo, xhi] = std::minmax_element(g.x.begin(), g.x.end());
    const auto [ylo, yhi] = std::minmax_element(g.y.begin(), g.y.end());
    const double w = *xhi - *xlo, h = *yhi - *ylo, pad = 0.02 * std::max(w, h);
    // the longer side kViewWidth pixels, the other in proportion (at least 100)
    const double aspect = std::max(w, 1e-300) / std::max(h, 1e-300);
    const int width = aspect >= 1 ? kViewWidth : std::max(100, static_cast<int>(std::lround(kViewWidth * aspect)));
    const int height = aspect >= 1 ? std::max(100, static_cast<int>(std::lround(kViewWidth / aspect))) : kViewWidth;
    return fitted_view("domain", *xlo - pad, *ylo - pad, *xhi + pad, *yhi + pad, width, height);
}

std::vector<View> airfoil_views(const GridLines &g) {
    const LineRef *wall = nullptr;
    for (const LineRef &l : g.lines)
        if (l.kind == kWallLine && (!wall || l.count > wall->count)) wall = &l;
    if (!wall) throw Failure(EXIT_GEOMETRY, "the grid has no wall patch to frame the airfoil's views on");
    const std::size_t first = wall->first, last = first + (wall->count - 1) * wall->stride;
    const double tx = 0.5 * (g.x[first] + g.x[last]), ty = 0.5 * (g.y[first] + g.y[last]);
    double lx = tx, ly = ty, chord = 0;
    for (int k = 0; k < wall->count; ++k) {
        const std::size_t n = first + k * wall->stride;
        const double d = std::hypot(g.x[n] - tx, g.y[n] - ty);
        if (d > chord) chord = d, lx = g.x[n], ly = g.y[n];
    }
    if (!(chord > 0)) throw Failure(EXIT_GEOMETRY, "the wall patch has no extent to frame the airfoil's views on");
    auto around = [&](const char *name, double cx, double cy, double width) {
        return fitted_view(name, cx - 0.5 * width, cy, cx + 0.5 * width, cy, kViewWidth, kViewHeight);
    };
    return {domain_view(g), around("airfoil", 0.5 * (lx + tx), 0.5 * (ly + ty), 1.5 * chord),
            around("le", lx, ly, 0.05 * chord), around("te", tx, ty, 0.05 * chord)};
}

}  // namespace eg2dtool
