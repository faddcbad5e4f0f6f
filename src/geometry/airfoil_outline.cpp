// Normalising an airfoil outline: the points as a closed loop, turned
// clockwise, then cut open at the trailing edge (a vertex when sharp, the
// base between its two corners when blunt). The same loop read in either
// direction or from any start gives the same points.
#include "geometry/airfoil_outline.hpp"

#include <cmath>

#include "base/error.hpp"

namespace eg2d {

namespace {

using Loop = std::vector<OutlinePoint>;

bool same(const OutlinePoint &a, const OutlinePoint &b) { return a.x == b.x && a.y == b.y; }

// Twice the signed area (shoelace): > 0 counter-clockwise.
double signed_area2(const Loop &p) {
    double s = 0.0;
    for (std::size_t k = 0, n = p.size(); k < n; ++k) {
        const OutlinePoint &a = p[k], &b = p[(k + 1) % n];
        s += a.x * b.y - b.x * a.y;
    }
    return s;
}

std::size_t farthest_from(const Loop &p, double x, double y) {
    std::size_t best = 0;
    double d = -1.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const double dk = std::hypot(p[k].x - x, p[k].y - y);
        if (dk > d) d = dk, best = k;
    }
    return best;
}

// The trailing edge: the point farthest along the chord from the leading
// edge (itself the point farthest from the rightmost point), so a section
// at an angle of attack is found too.
std::size_t trailing_vertex(const Loop &p, double &ux, double &uy) {
    std::size_t right = 0;
    for (std::size_t k = 1; k < p.size(); ++k)
        if (p[k].x > p[right].x) right = k;
    const OutlinePoint le = p[farthest_from(p, p[right].x, p[right].y)];
    const double len = std::hypot(p[right].x - le.x, p[right].y - le.y);
    ux = (p[right].x - le.x) / len;
    uy = (p[right].y - le.y) / len;
    std::size_t te = right;
    double far = -INFINITY;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const double along = (p[k].x - le.x) * ux + (p[k].y - le.y) * uy;
        if (along > far) far = along, te = k;
    }
    return te;
}

// A blunt base runs across the chord; the surfaces leave a sharp edge along it.
bool across(const OutlinePoint &a, const OutlinePoint &b, double ux, double uy) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return std::fabs(dx * uy - dy * ux) > std::fabs(dx * ux + dy * uy);
}

}  // namespace

Outline normalise_outline(Loop pts, const char *path) {
    Outline out;
    Loop p;
    for (const OutlinePoint &q : pts) {
        if (!p.empty() && same(p.back(), q)) {
            ++out.duplicates;
            continue;
        }
        p.push_back(q);
    }
    const bool closed = p.size() > 1 && same(p.front(), p.back());
    if (closed) p.pop_back();
    const std::size_t n = p.size();
    if (n < 4) fail(Failure::Argument, format("airfoil file \"%s\": %zu distinct points, need at least 4", path, n));
    const double area2 = signed_area2(p);
    if (!(area2 != 0.0) || !std::isfinite(area2))
        fail(Failure::Argument, format("airfoil file \"%s\": its %zu points enclose no area (%g)", path, n, area2 / 2));
    if (area2 > 0.0) {  // counter-clockwise (Selig's order): turn it
        for (std::size_t a = 0, b = n - 1; a < b; ++a, --b) std::swap(p[a], p[b]);
    }
    double ux, uy;
    const std::size_t te = trailing_vertex(p, ux, uy);
    const std::size_t next = (te + 1) % n, prev = (te + n - 1) % n;
    // Clockwise, a base runs from the upper corner to the lower one, and the
    // curve starts at the lower: the corner after the base.
    std::size_t start = te;
    bool base = false;
    const bool base_next = across(p[te], p[next], ux, uy), base_prev = across(p[prev], p[te], ux, uy);
    if (base_next || base_prev) {
        base = true;
        const auto along = [&](std::size_t k) { return p[k].x * ux + p[k].y * uy; };
        const bool use_next = base_next && (!base_prev || along(next) >= along(prev));
        start = use_next ? next : te;
    }
    for (std::size_t k = 0; k < n; ++k) {
        out.x.push_back(p[(start + k) % n].x);
        out.y.push_back(p[(start + k) % n].y);
    }
    if (!base) {  // sharp: the trailing edge closes the curve
        out.x.push_back(p[start].x);
        out.y.push_back(p[start].y);
    }
    return out;
}

}  // namespace eg2d
