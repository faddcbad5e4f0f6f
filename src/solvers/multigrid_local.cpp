#include "solvers/multigrid_local.hpp"

#include <algorithm>
#include <cmath>

namespace eg2d {

namespace {
// Turning angle (radians) of the boundary polyline above which a node counts
// as singular. A smooth side resolved by the grid turns by a few degrees per
// node; a NACA0012 trailing edge turns by about 165.
constexpr double kSingularTurn = 0.5;

double turn(const double *x, const double *y, std::size_t a, std::size_t b, std::size_t c) {
    const double ux = x[b] - x[a], uy = y[b] - y[a], vx = x[c] - x[b], vy = y[c] - y[b];
    const double cross = ux * vy - uy * vx, dot = ux * vx + uy * vy;
    if (cross == 0.0 && dot == 0.0) return 0.0;  // coincident nodes (a collapsed side)
    return std::fabs(std::atan2(cross, dot));
}
}  // namespace

std::vector<Connectivity::Node> singular_nodes(const Connectivity &conn, const double *x, const double *y) {
    const int ni = conn.ni(), nj = conn.nj();
    auto at = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
    std::vector<Connectivity::Node> nodes;
    if (conn.periodic_i()) {
        for (int j : {0, nj - 1})
            for (int i = 0; i < ni - 1; ++i) {
                const int w = i == 0 ? ni - 2 : i - 1;
                if (turn(x, y, at(w, j), at(i, j), at(i + 1, j)) > kSingularTurn) nodes.push_back({i, j});
            }
        return nodes;
    }
    nodes = cut_ends(conn);  // relaxed here too: measured, the two rounds together do best
    for (int j : {0, nj - 1}) {
        nodes.push_back({0, j});
        nodes.push_back({ni - 1, j});
        for (int i = 1; i < ni - 1; ++i)
            if (turn(x, y, at(i - 1, j), at(i, j), at(i + 1, j)) > kSingularTurn) nodes.push_back({i, j});
    }
    for (int i : {0, ni - 1})
        for (int j = 1; j < nj - 1; ++j)
            if (turn(x, y, at(i, j - 1), at(i, j), at(i, j + 1)) > kSingularTurn) nodes.push_back({i, j});
    return nodes;
}

std::vector<Connectivity::Node> cut_ends(const Connectivity &conn) {
    if (conn.wake() <= 0) return {};
    return {{conn.wake(), 0}, {conn.ni() - 1 - conn.wake(), 0}};
}

void relax_near(System system, const Level &L, const std::vector<Connectivity::Node> &nodes, int radius,
                int sweeps) {
    const Connectivity &conn = *L.conn;
    const int period = conn.ni() - 1;
    auto relax = [&](int i, int j) {
        if (conn.periodic_i()) i = ((i % period) + period) % period;
        // A C-grid's wake cut is relaxed too (its upper copies through the
        // lower nodes that own them): round the trailing edge the box spans
        // both sides of the cut, and without the cut nodes the error stays
        // on them (measured: naca0012-c 513x129, 27 cycles instead of 6).
        if (j == 0 && conn.wake() > 0 && i > conn.ni() - 1 - conn.wake() && i < conn.ni() - 1) i = conn.ni() - 1 - i;
        if (!conn.on_cut(i, j) && (i < conn.i_begin() || i >= conn.i_end() || j < conn.j_begin() || j >= conn.j_end()))
            return;
        relax_point(system, L, i, j, 1.0);
    };
    for (const Connectivity::Node &n : nodes)
        for (int s = 0; s < sweeps; ++s) {
            if (s % 2 == 0) {
                for (int j = n.j - radius; j <= n.j + radius; ++j)
                    for (int i = n.i - radius; i <= n.i + radius; ++i) relax(i, j);
            } else {
                for (int j = n.j + radius; j >= n.j - radius; --j)
                    for (int i = n.i + radius; i >= n.i - radius; --i) relax(i, j);
            }
        }
}

}  // namespace eg2d
