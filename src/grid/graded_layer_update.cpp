// The graded layer's updates during the run (graded_layer.hpp).
#include <algorithm>
#include <cmath>

#include "base/polyline.hpp"
#include "grid/graded_layer.hpp"

namespace eg2d {

namespace {

// A first cell may change by at most this factor per update: a guard
// against a measure taken on a grid far from converged.
constexpr double kMostScale = 2.0;
// The scales are updated at least kFirstUpdates times, then until every
// first cell is within kSettled of its height, at most kScaleUpdates times,
// and then frozen. The first cells settle within 1% in 3-6 updates against
// multigrid cycles (a pipe, a bend, a diffuser between two walls); left on,
// the scales crept by 0.3% per cycle against the angle's updates and the run
// did not converge in 3000 cycles. Frozen, it converges as with a fixed
// control.
constexpr int kFirstUpdates = 3;
constexpr int kScaleUpdates = 8;
constexpr double kSettled = 0.01;

std::size_t at(int ni, int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; }

// Node (line l, position k) of a family, k = 0 at its low wall.
std::size_t node(const Grid &g, const GradedFamily &f, int l, int k) { return f.columns ? at(g.ni(), l, k) : at(g.ni(), k, l); }

// The height of the node at k1 above the wall node k0 of line l, along the
// normal to the wall's central difference (its neighbours' lines l-1, l+1).
double normal_height(const Grid &g, const GradedFamily &f, int l, int k0, int k1, int lines) {
    const bool ring = g.topology() == Topology::O;
    const int a = l > 0 ? l - 1 : lines - 1, b = ring && l + 1 == lines ? 0 : l + 1;
    const std::size_t w = node(g, f, l, k0), c = node(g, f, l, k1), m = node(g, f, a, k0), p = node(g, f, b, k0);
    const double tx = g.x[p] - g.x[m], ty = g.y[p] - g.y[m], tl = std::hypot(tx, ty);
    const double dx = g.x[c] - g.x[w], dy = g.y[c] - g.y[w];
    return tl > 0.0 ? std::fabs(tx * dy - ty * dx) / tl : std::hypot(dx, dy);
}

double rescale(double scale, double asked, double measured, double omega) {
    if (!(asked > 0.0) || !(measured > 0.0)) return scale;
    return scale * std::pow(std::clamp(asked / measured, 1.0 / kMostScale, kMostScale), omega);
}

}  // namespace

double update_graded_layer(const Grid &g, GradedLayer &layer, double omega) {
    if (layer.frozen) return 0.0;
    ++layer.updates;
    double worst = 0.0;  // the largest |log(height / measured)| seen
    auto measure = [&](double asked, double measured) {
        if (asked > 0.0 && measured > 0.0) worst = std::max(worst, std::fabs(std::log(asked / measured)));
        return measured;
    };
    const bool ring = g.topology() == Topology::O;
    const int ni = g.ni();
    double change = 0.0;
    for (GradedFamily &f : layer.families) {
        std::vector<double> &field = f.columns ? layer.psi : layer.phi;
        const std::vector<double> &lo = layer.heights[f.columns ? 0 : 3], &hi = layer.heights[f.columns ? 2 : 1];
        const int lines = static_cast<int>(f.scale_lo.size()), nodes = f.columns ? g.nj() : g.ni();
        for (int l = ring ? 0 : 1; l < (ring ? lines : lines - 1); ++l) {
            const std::size_t q = static_cast<std::size_t>(l);
            if (!lo.empty()) f.scale_lo[q] = rescale(f.scale_lo[q], lo[q], measure(lo[q], normal_height(g, f, l, 0, 1, lines)), omega);
            if (!hi.empty()) f.scale_hi[q] = rescale(f.scale_hi[q], hi[q], measure(hi[q], normal_height(g, f, l, nodes - 1, nodes - 2, lines)), omega);
            std::vector<Vec2> line(static_cast<std::size_t>(nodes));
            for (int k = 0; k < nodes; ++k) line[static_cast<std::size_t>(k)] = {g.x[node(g, f, l, k)], g.y[node(g, f, l, k)]};
            const std::vector<double> c = graded_target_cells(layer, f, l, nodes - 1, arc_lengths(line).back());
            for (int k = 1; k < nodes - 1; ++k) {
                const double psi = -2.0 * (c[static_cast<std::size_t>(k)] - c[static_cast<std::size_t>(k - 1)]) /
                                   (c[static_cast<std::size_t>(k)] + c[static_cast<std::size_t>(k - 1)]);
                double &old = field[node(g, f, l, k)];
                change = std::max(change, std::fabs(psi - old) * 0.25 * (c[static_cast<std::size_t>(k)] + c[static_cast<std::size_t>(k - 1)]));
                old = psi;
                if (ring && l == 0) field[at(ni, ni - 1, k)] = psi;
            }
        }
    }
    layer.frozen = layer.updates >= kScaleUpdates || (layer.updates >= kFirstUpdates && worst <= kSettled);
    return change;
}

}  // namespace eg2d
