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
    const int ni = g.ni();
    for (const GradedFamily &f : layer.families) {
        const int lines = static_cast<int>(f.factor.size()), nodes = f.columns ? g.nj() : g.ni();
        const bool lo = !layer.heights[f.columns ? 0 : 3].empty(), hi = !layer.heights[f.columns ? 2 : 1].empty();
        const double K = std::min<double>(kTurnRows, lo && hi ? (nodes - 1) / 2 : nodes - 1);
        // Node k of line l. Lines of a family share no nodes, and walls'
        // nodes never move: each line is read as it is, its neighbours only
        // at the wall. The passes below go through the grid in storage
        // order (line by line, a column family's lines were read with a
        // stride of a row: a tenth of a straight channel's run).
        auto at = [&](int l, int k) { return f.columns ? node_index(ni, l, k) : node_index(ni, k, l); };
        auto point = [&](std::size_t n) { return Vec2{g.x[n], g.y[n]}; };
        const int first = ring ? 0 : 1, last = ring ? lines : lines - 1;
        // The normals at both ends of each line, before any node moves.
        std::vector<Vec2> normal(2 * static_cast<std::size_t>(lines), Vec2{0.0, 0.0});
        for (int l = first; l < last; ++l) {
            const int before = l > 0 ? l - 1 : lines - 1, after = ring && l + 1 == lines ? 0 : l + 1;
            for (int end = 0; end < 2; ++end) {
                if (!(end == 0 ? lo : hi)) continue;
                const int w = end == 0 ? 0 : nodes - 1, step = end == 0 ? 1 : -1;
                normal[2 * static_cast<std::size_t>(l) + static_cast<std::size_t>(end)] =
                    wall_normal(point(at(before, w)), point(at(l, w)), point(at(after, w)), point(at(l, w + step)));
            }
        }
        // Node m off the wall at `end` of line l, to the point its arc length
        // d from the wall along the line as it was (prev: that line's node
        // m-1 before it moved) reaches on the normal, blended in over K rows.
        // Between two walls their rows do not meet (K is half the line).
        auto move = [&](int l, int end, int m, Vec2 &prev, double &d) {
            const int w = end == 0 ? 0 : nodes - 1;
            const std::size_t iw = at(l, w), k = at(l, end == 0 ? m : w - m);
            const double dx = g.x[k] - prev.x, dy = g.y[k] - prev.y;
            prev = point(k);
            d += std::sqrt(dx * dx + dy * dy);  // as arc_lengths (base/polyline.hpp)
            const Vec2 n = normal[2 * static_cast<std::size_t>(l) + static_cast<std::size_t>(end)];
            if (n.x == 0.0 && n.y == 0.0) return;
            const double t = (m - 1) / (K - 1), b = 1.0 - t * t * (3.0 - 2.0 * t);
            g.x[k] += b * (g.x[iw] + d * n.x - g.x[k]);
            g.y[k] += b * (g.y[iw] + d * n.y - g.y[k]);
        };
        const int rows = static_cast<int>(std::min<double>(K, nodes - 1));  // m < K and m < nodes - 1
        for (int end = 0; end < 2; ++end) {
            if (!(end == 0 ? lo : hi)) continue;
            const int w = end == 0 ? 0 : nodes - 1;
            if (f.columns) {  // row by row
                std::vector<Vec2> prev(static_cast<std::size_t>(lines));
                std::vector<double> d(static_cast<std::size_t>(lines), 0.0);
                for (int l = first; l < last; ++l) prev[static_cast<std::size_t>(l)] = point(at(l, w));
                for (int m = 1; m < rows; ++m)
                    for (int l = first; l < last; ++l)
                        move(l, end, m, prev[static_cast<std::size_t>(l)], d[static_cast<std::size_t>(l)]);
            } else {  // line by line
                for (int l = first; l < last; ++l) {
                    Vec2 prev = point(at(l, w));
                    double d = 0.0;
                    for (int m = 1; m < rows; ++m) move(l, end, m, prev, d);
                }
            }
        }
        if (ring)
            for (int k = 1; k < nodes - 1; ++k)
                set_node(g, g.ni() - 1, k, {g.x[node_index(g.ni(), 0, k)], g.y[node_index(g.ni(), 0, k)]});
    }
}

}  // namespace eg2d
