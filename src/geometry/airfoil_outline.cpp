// Normalising an airfoil outline: the points as a closed loop, turned
// clockwise, then cut open at the trailing edge (a vertex when sharp, the
// base between its two corners when blunt), or where the file's own ends
// are when they lie at the trailing edge. The same loop read in either
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

// The chord's direction: from the leading edge (the point farthest from the
// rightmost point) towards that point, so a section at an angle of attack is
// measured along its own chord.
struct Chord {
    OutlinePoint le;
    double ux, uy;
    double along(const OutlinePoint &q) const { return (q.x - le.x) * ux + (q.y - le.y) * uy; }
};

Chord chord_of(const Loop &p) {
    std::size_t right = 0;
    for (std::size_t k = 1; k < p.size(); ++k)
        if (p[k].x > p[right].x) right = k;
    const OutlinePoint le = p[farthest_from(p, p[right].x, p[right].y)];
    const double len = std::hypot(p[right].x - le.x, p[right].y - le.y);
    return Chord{le, (p[right].x - le.x) / len, (p[right].y - le.y) / len};
}

// A blunt base runs across the chord; the surfaces leave a sharp edge along it.
bool across(const OutlinePoint &a, const OutlinePoint &b, const Chord &c) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return std::fabs(dx * c.uy - dy * c.ux) > std::fabs(dx * c.ux + dy * c.uy);
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
    const bool turned = area2 > 0.0;  // counter-clockwise (Selig's order): turn it
    if (turned)
        for (std::size_t a = 0, b = n - 1; a < b; ++a, --b) std::swap(p[a], p[b]);
    const Chord c = chord_of(p);
    std::size_t te = 0;  // the trailing edge: the point farthest along the chord
    for (std::size_t k = 1; k < n; ++k)
        if (c.along(p[k]) > c.along(p[te])) te = k;
    const double at_te = 0.99 * c.along(p[te]);
    // The file's own ends are kept where they lie at the trailing edge
    // (Selig's order, either way round), so a rounded or odd edge is cut
    // where the file cuts it; elsewhere (a leading-edge start) the cut is found.
    const std::size_t own = closed && turned ? n - 1 : 0;
    std::size_t start = own;
    bool base = !closed;
    if (closed ? c.along(p[own]) < at_te : c.along(p[0]) < at_te || c.along(p[n - 1]) < at_te) {
        // Clockwise, a base runs from the upper corner to the lower one, and
        // the curve starts at the lower: the corner after the base.
        const std::size_t next = (te + 1) % n, prev = (te + n - 1) % n;
        const bool base_next = across(p[te], p[next], c), base_prev = across(p[prev], p[te], c);
        base = base_next || base_prev;
        start = base_next && (!base_prev || c.along(p[next]) >= c.along(p[prev])) ? next : te;
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
