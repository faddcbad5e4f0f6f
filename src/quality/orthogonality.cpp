// Orthogonality at a boundary side: at each boundary node the angle between
// the boundary's tangent (central difference of its neighbours on the side)
// and the grid line that leaves the node into the domain, as a deviation
// from 90 degrees. The corners are left out (their angle is the boundary's);
// on an O-grid JMIN and JMAX are closed curves and every node counts once.
#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "quality/quality.hpp"

namespace eg2d {

namespace {
double deviation(double tx, double ty, double lx, double ly) {
    const double angle = std::atan2(std::fabs(tx * ly - ty * lx), tx * lx + ty * ly);
    return std::fabs(angle * (180.0 / 3.14159265358979323846) - 90.0);
}
}  // namespace

OrthogonalitySummary boundary_orthogonality(const Grid &g, Side side) {
    if (!g.has_side(side))
        fail(Failure::Argument, format("the %s topology has no side %s", topology_name(g.topology()), side_name(side)));
    const int ni = g.ni(), nj = g.nj();
    const bool along_i = side == Side::JMin || side == Side::JMax;
    const int n = along_i ? ni : nj;
    const bool closed = along_i && g.connectivity().periodic_i();
    // Node m of the side, and the node one step into the domain from it.
    auto node = [&](int m, int inward) { return side_node(g, side, m, inward); };
    OrthogonalitySummary s;
    const int first = closed ? 0 : 1, last = closed ? n - 2 : n - 2;  // closed: node n-1 is node 0
    int count = 0;
    double sum = 0.0;
    for (int m = first; m <= last; ++m) {
        const int prev = closed && m == 0 ? n - 2 : m - 1, next = m + 1;
        const std::size_t b = node(m, 0), in = node(m, 1), p = node(prev, 0), q = node(next, 0);
        const double d = deviation(g.x[q] - g.x[p], g.y[q] - g.y[p], g.x[in] - g.x[b], g.y[in] - g.y[b]);
        s.max = std::max(s.max, d);
        sum += d;
        ++count;
    }
    s.mean = count > 0 ? sum / count : 0.0;
    return s;
}

}  // namespace eg2d
