// The graded layer's lines turned to the walls' normals (graded_layer.hpp):
// the start kept and the re-spaced grid leave the wall control nothing to do.
#include <algorithm>
#include <cmath>

#include "base/polyline.hpp"
#include "grid/graded_layer.hpp"

namespace eg2d {

namespace {

// turn_to_normals turns the lines over this many rows from a wall (at most
// half of them between two walls), the first row all the way. Before the
// controls are inverted from a kept start, so that the wall control has
// nothing left to turn (257x129 at 1e-5; cycles and skewness in degrees for
// 0, 10, 30 and 60 rows, the first turned in part): bend 5, 0, 0, 0 (0.5
// each); pipe 6, 5, 3, 2 (11.7, 15.5, 12.8, 10.0); diffuser 7, 5, 3, 2
// (26.6, 34.7, 29.0, 26.4). The first row all the way: 0 cycles for all
// three, and for the diffuser at 177x81 (2e-4) against 6. After the
// re-spacing of a start not kept: the TMR bump 177x81 at 4e-6 in 4 cycles
// against 9.
constexpr int kTurnRows = 60;

// The unit normal at wall node w (its neighbours along the wall before and
// after), toward the line's next node.
Vec2 wall_normal(const Vec2 &before, const Vec2 &w, const Vec2 &after, const Vec2 &next) {
    const double tx = after.x - before.x, ty = after.y - before.y, tl = std::hypot(tx, ty);
    if (!(tl > 0.0)) return {0.0, 0.0};
    Vec2 n{-ty / tl, tx / tl};
    if (n.x * (next.x - w.x) + n.y * (next.y - w.y) < 0.0) n = {-n.x, -n.y};
    return n;
}

}  // namespace

void turn_to_normals(Grid &g, const GradedLayer &layer) {
    const bool ring = g.topology() == Topology::O;
    for (const GradedFamily &f : layer.families) {
        const int lines = static_cast<int>(f.factor.size()), nodes = f.columns ? g.nj() : g.ni();
        const bool lo = !layer.heights[f.columns ? 0 : 3].empty(), hi = !layer.heights[f.columns ? 2 : 1].empty();
        const double K = std::min<double>(kTurnRows, lo && hi ? (nodes - 1) / 2 : nodes - 1);
        // Lines of a family share no nodes, and walls' nodes never move: each
        // line is read as it is, its neighbours only at the wall.
        auto wall_node = [&](int l, int k) {
            const std::size_t n = f.columns ? node_index(g.ni(), l, k) : node_index(g.ni(), k, l);
            return Vec2{g.x[n], g.y[n]};
        };
        for (int l = ring ? 0 : 1; l < (ring ? lines : lines - 1); ++l) {
            const std::vector<Vec2> p = f.columns ? grid_column(g, l, nodes - 1) : grid_row(g, l);
            const int before = l > 0 ? l - 1 : lines - 1, after = ring && l + 1 == lines ? 0 : l + 1;
            const std::vector<double> arc = arc_lengths(p);
            std::vector<Vec2> q = p;
            for (int end = 0; end < 2; ++end) {
                if (!(end == 0 ? lo : hi)) continue;
                const int w = end == 0 ? 0 : nodes - 1, step = end == 0 ? 1 : -1;
                const std::size_t iw = static_cast<std::size_t>(w);
                const Vec2 n = wall_normal(wall_node(before, w), p[iw], wall_node(after, w), p[static_cast<std::size_t>(w + step)]);
                if (n.x == 0.0 && n.y == 0.0) continue;
                for (int m = 1; m < K && m < nodes - 1; ++m) {
                    const std::size_t k = static_cast<std::size_t>(w + step * m);
                    const double t = (m - 1) / (K - 1), b = 1.0 - t * t * (3.0 - 2.0 * t);
                    const double d = std::fabs(arc[k] - arc[iw]);
                    q[k] = {q[k].x + b * (p[iw].x + d * n.x - q[k].x), q[k].y + b * (p[iw].y + d * n.y - q[k].y)};
                }
            }
            for (int k = 1; k < nodes - 1; ++k) set_node(g, f.columns ? l : k, f.columns ? k : l, q[static_cast<std::size_t>(k)]);
        }
        if (ring)
            for (int k = 1; k < nodes - 1; ++k)
                set_node(g, g.ni() - 1, k, {g.x[node_index(g.ni(), 0, k)], g.y[node_index(g.ni(), 0, k)]});
    }
}

}  // namespace eg2d
