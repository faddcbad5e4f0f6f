// Telling Lednicer's counts from a point, and unpacking its two surfaces.
#include "geometry/airfoil_lednicer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.hpp"

namespace eg2d {

namespace {

bool count_like(double v) { return v >= 2.0 && std::isfinite(v) && v == std::floor(v); }

struct Box { double x0, x1, y0, y1; };

Box box_after_first(const std::vector<OutlinePoint> &p) {
    Box b{p[1].x, p[1].x, p[1].y, p[1].y};
    for (std::size_t k = 2; k < p.size(); ++k) {
        b.x0 = std::min(b.x0, p[k].x), b.x1 = std::max(b.x1, p[k].x);
        b.y0 = std::min(b.y0, p[k].y), b.y1 = std::max(b.y1, p[k].y);
    }
    return b;
}

// Where the second surface starts among the surfaces' points (index into
// pts, 0 if not seen): the first point where x jumps back by over half the extent.
std::size_t visible_split(const std::vector<OutlinePoint> &pts, double extent) {
    for (std::size_t k = 2; k < pts.size(); ++k)
        if (pts[k - 1].x - pts[k].x > 0.5 * extent) return k;
    return 0;
}

}  // namespace

bool first_off_outline(const std::vector<OutlinePoint> &pts) {
    if (pts.size() < 3) return false;
    const Box b = box_after_first(pts);
    const double diagonal = std::hypot(b.x1 - b.x0, b.y1 - b.y0);
    double nearest = INFINITY;
    for (std::size_t k = 1; k < pts.size(); ++k)
        nearest = std::min(nearest, std::hypot(pts[k].x - pts[0].x, pts[k].y - pts[0].y));
    return nearest > 0.5 * diagonal;
}

bool lednicer_counts(const std::vector<OutlinePoint> &pts) {
    if (pts.size() < 3 || !count_like(pts[0].x) || !count_like(pts[0].y) || !first_off_outline(pts)) return false;
    const Box b = box_after_first(pts);
    return pts[1].x - b.x0 <= 0.25 * (b.x1 - b.x0);
}

std::vector<OutlinePoint> lednicer_outline(const std::vector<OutlinePoint> &pts, const std::vector<std::size_t> &lines,
                                           const char *path) {
    const std::size_t n = pts.size() - 1;  // the surfaces' points
    const double nu = pts[0].x, nl = pts[0].y;
    const Box b = box_after_first(pts);
    const std::size_t split = visible_split(pts, b.x1 - b.x0);
    // Compared as doubles: a count beyond size_t is undefined to convert
    // (UBSan, found by fuzz_airfoil), and size_t sums could wrap.
    const bool sum_ok = nu + nl == static_cast<double>(n);
    if (!sum_ok || (split != 0 && nu != static_cast<double>(split - 1))) {
        const std::string seen = split ? format(" (%zu + %zu: the lower surface starts at line %zu, where x returns to the "
                                          "leading edge)",
                                          split - 1, n - (split - 1), lines[split])
                                 : std::string();
        fail(Failure::Argument, format("Lednicer file \"%s\" (line %zu): announces %.15g + %.15g points but has %zu%s: "
                                       "correct the counts",
                                       path, lines[0], nu, nl, n, seen.c_str()));
    }
    const std::size_t upper = static_cast<std::size_t>(nu);
    std::vector<OutlinePoint> out;
    for (std::size_t k = upper; k >= 1; --k) out.push_back(pts[k]);  // upper, trailing edge first
    for (std::size_t k = upper + 1; k <= n; ++k) out.push_back(pts[k]);
    return out;
}

}  // namespace eg2d
