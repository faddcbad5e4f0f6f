// The graded layer's second step for a start not kept (graded_layer.hpp):
// the lines a cycle of the solve has shaped, re-spaced along themselves,
// turned to the walls' normals and inverted for the controls.
#include <algorithm>
#include <cmath>

#include "base/polyline.hpp"
#include "grid/graded_layer.hpp"
#include "grid/invert_controls.hpp"

namespace eg2d {

namespace {

// m's lines of family f re-spaced along themselves: the target cells near
// the walls, the solve's beyond (the target there too put back the start's
// skew, 43 degrees on the TMR bump, whose top and bottom are spaced
// differently).
void respace_family(Grid &m, const GradedLayer &layer, const GradedFamily &f) {
    const bool ring = m.topology() == Topology::O;
    const int lines = static_cast<int>(f.factor.size()), nodes = f.columns ? m.nj() : m.ni();
    const bool lo = !layer.heights[f.columns ? 0 : 3].empty(), hi = !layer.heights[f.columns ? 2 : 1].empty();
    for (int l = ring ? 0 : 1; l < (ring ? lines : lines - 1); ++l) {
        const std::vector<Vec2> points = f.columns ? grid_column(m, l, nodes - 1) : grid_row(m, l);
        const std::vector<double> arc = arc_lengths(points);
        const std::vector<double> c = graded_target_cells(layer, f, l, nodes - 1, arc.back());
        // Cells: the target's near the walls, the solve's away from them,
        // their logs blended (wall_shares); fitted to the line's length.
        const std::vector<double> share = wall_shares(nodes - 1, lo, hi);
        std::vector<double> cells(c.size());
        for (std::size_t q = 0; q < c.size(); ++q) {
            const double now = arc[q + 1] - arc[q];
            cells[q] = now > 0.0 ? std::exp(share[q] * std::log(c[q]) + (1.0 - share[q]) * std::log(now)) : c[q];
        }
        cells = fit_length(std::move(cells), share, arc.back());
        std::vector<double> want(static_cast<std::size_t>(nodes), 0.0);
        for (int k = 1; k < nodes; ++k)
            want[static_cast<std::size_t>(k)] = want[static_cast<std::size_t>(k - 1)] + cells[static_cast<std::size_t>(k - 1)];
        want.back() = arc.back();
        const std::vector<Vec2> p = points_along(points, want);
        for (int k = 1; k < nodes - 1; ++k)
            set_node(m, f.columns ? l : k, f.columns ? k : l, p[static_cast<std::size_t>(k)]);
    }
    if (ring)
        for (int k = 1; k < nodes - 1; ++k) set_node(m, m.ni() - 1, k, {m.x[node_index(m.ni(), 0, k)], m.y[node_index(m.ni(), 0, k)]});
}

}  // namespace

void reshape_graded_layer(Grid &g, GradedLayer &layer) {
    for (const GradedFamily &f : layer.families) respace_family(g, layer, f);
    turn_to_normals(g, layer);
    invert_grid_controls(g, 1, layer.phi, layer.psi);
    layer.frozen = true;
}

}  // namespace eg2d
