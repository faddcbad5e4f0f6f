#include "grid/hybrid_layer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "grid/hyperbolic.hpp"

namespace eg2d {

namespace {

constexpr double kRetrySmoothing = 1.0;

std::size_t at(int ni, int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; }

// The least distance of a JMAX node from a JMIN node.
double outer_distance(const Grid &g) {
    const int ni = g.ni(), top = g.nj() - 1;
    double d2 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < ni; ++a)
        for (int b = 0; b < ni; ++b) {
            const double dx = g.x[at(ni, a, top)] - g.x[at(ni, b, 0)], dy = g.y[at(ni, a, top)] - g.y[at(ni, b, 0)];
            d2 = std::min(d2, dx * dx + dy * dy);
        }
    return std::sqrt(d2);
}

// Phi, Psi at node (i, j) of m, its xi-neighbours a and b, such that
// alpha (r_xixi + Phi r_xi) - 2 beta r_xieta + gamma (r_etaeta + Psi r_eta) = 0
// there (NUMERICS.md's central differences): the 2x2 system
// [alpha r_xi, gamma r_eta] (Phi, Psi) = -(alpha r_xixi - 2 beta r_xieta +
// gamma r_etaeta), by Cramer's rule (determinant alpha gamma J, nonzero on an
// unfolded grid).
void invert_controls(const Grid &m, int i, int a, int b, int j, double &phi, double &psi) {
    const int ni = m.ni();
    auto X = [&](int p, int q) { return m.x[at(ni, p, q)]; };
    auto Y = [&](int p, int q) { return m.y[at(ni, p, q)]; };
    const double xx = 0.5 * (X(b, j) - X(a, j)), yx = 0.5 * (Y(b, j) - Y(a, j));
    const double xe = 0.5 * (X(i, j + 1) - X(i, j - 1)), ye = 0.5 * (Y(i, j + 1) - Y(i, j - 1));
    const double xxx = X(b, j) - 2 * X(i, j) + X(a, j), yxx = Y(b, j) - 2 * Y(i, j) + Y(a, j);
    const double xee = X(i, j + 1) - 2 * X(i, j) + X(i, j - 1), yee = Y(i, j + 1) - 2 * Y(i, j) + Y(i, j - 1);
    const double xxe = 0.25 * (X(b, j + 1) - X(b, j - 1) - X(a, j + 1) + X(a, j - 1));
    const double yxe = 0.25 * (Y(b, j + 1) - Y(b, j - 1) - Y(a, j + 1) + Y(a, j - 1));
    const double al = xe * xe + ye * ye, be = xx * xe + yx * ye, ga = xx * xx + yx * yx, J = xx * ye - xe * yx;
    const double rx = al * xxx - 2 * be * xxe + ga * xee, ry = al * yxx - 2 * be * yxe + ga * yee;
    phi = -(ye * rx - xe * ry) / (al * J);
    psi = -(xx * ry - yx * rx) / (ga * J);
}

// The march's rows above `rows`, each column moved by the offset of its
// outer node to the user's, times the arc-length fraction above the layer.
void start_above(Grid &g, const Grid &m, int rows) {
    const int ni = g.ni(), nj = g.nj();
    std::vector<double> arc(static_cast<std::size_t>(nj));
    for (int i = 0; i < ni; ++i) {
        arc[0] = 0.0;
        for (int j = 1; j < nj; ++j)
            arc[static_cast<std::size_t>(j)] = arc[static_cast<std::size_t>(j - 1)] +
                std::hypot(m.x[at(ni, i, j)] - m.x[at(ni, i, j - 1)], m.y[at(ni, i, j)] - m.y[at(ni, i, j - 1)]);
        const double dx = g.x[at(ni, i, nj - 1)] - m.x[at(ni, i, nj - 1)];
        const double dy = g.y[at(ni, i, nj - 1)] - m.y[at(ni, i, nj - 1)];
        const double base = arc[static_cast<std::size_t>(rows)], span = arc[static_cast<std::size_t>(nj - 1)] - base;
        for (int j = rows + 1; j < nj - 1; ++j) {
            const double f = (arc[static_cast<std::size_t>(j)] - base) / span;
            g.x[at(ni, i, j)] = m.x[at(ni, i, j)] + f * dx;
            g.y[at(ni, i, j)] = m.y[at(ni, i, j)] + f * dy;
        }
    }
}

}  // namespace

int hybrid_layer_rows(int nj) { return std::max(1, std::min(2 * (nj - 1) / 3, nj - 3)); }

HybridLayer shape_hybrid_layer(Grid &g, const Settings &settings, double h, bool fill_above) {
    const int ni = g.ni(), nj = g.nj();
    Grid m = g;
    m.hold_rows(0);
    Settings s = settings;
    s.march_first_height = h;
    s.march_distance = outer_distance(g);
    s.march_growth = 3.0;  // the schedule's ratio is the one that reaches the distance in nj-1 layers
    HybridLayer out;
    try {
        hyperbolic_march(m, s);  // throws before g changes
    } catch (const Error &e) {
        // Far fields of 100 chords and more folded the march's outer layers
        // at its default dissipation (0.5) and marched without folds at 1.0
        // (NACA 0012 385x97 and 385x129 to 100 chords, 250x100 to 500;
        // 1.5 to 3 folded them again; bench/RESULTS.md): one retry.
        if (e.failure() != Failure::Folded || s.march_smoothing == kRetrySmoothing) throw;
        out.shape.note = format("wall layer (hybrid): %s; marched again with EG2D_PARAM_MARCH_SMOOTHING %g",
                                e.what(), kRetrySmoothing);
        s.march_smoothing = kRetrySmoothing;
        m = g;
        m.hold_rows(0);
        hyperbolic_march(m, s);
    }
    const int rows = hybrid_layer_rows(nj);
    g.hold_rows(0);
    for (int j = 1; j <= rows; ++j)
        for (int i = 0; i < ni; ++i) {
            g.x[at(ni, i, j)] = m.x[at(ni, i, j)];
            g.y[at(ni, i, j)] = m.y[at(ni, i, j)];
        }
    if (fill_above) start_above(g, m, rows);
    out.phi.assign(g.size(), 0.0);
    out.psi.assign(g.size(), 0.0);
    for (int j = rows + 1; j < nj - 1; ++j)
        for (int i = 0; i < ni - 1; ++i) {
            invert_controls(m, i, i == 0 ? ni - 2 : i - 1, i + 1, j, out.phi[at(ni, i, j)], out.psi[at(ni, i, j)]);
            if (i == 0) {
                out.phi[at(ni, ni - 1, j)] = out.phi[at(ni, 0, j)];
                out.psi[at(ni, ni - 1, j)] = out.psi[at(ni, 0, j)];
            }
        }
    // The first cells against the wall control's contract (height along the
    // normal to the wall's central difference r(i+1) - r(i-1)).
    for (int i = 0; i < ni - 1; ++i) {
        const int a = i > 0 ? i - 1 : ni - 2, b = i + 1;
        const double tx = m.x[at(ni, b, 0)] - m.x[at(ni, a, 0)], ty = m.y[at(ni, b, 0)] - m.y[at(ni, a, 0)];
        const double ex = m.x[at(ni, i, 1)] - m.x[at(ni, i, 0)], ey = m.y[at(ni, i, 1)] - m.y[at(ni, i, 0)];
        const double e = std::hypot(ex, ey), t = std::hypot(tx, ty);
        out.height_error = std::max(out.height_error, std::fabs(e - h) / h);
        if (e > 0.0 && t > 0.0)
            out.wall_angle = std::max(out.wall_angle, std::asin(std::min(1.0, std::fabs(ex * tx + ey * ty) / (e * t))) *
                                                          (180.0 / 3.14159265358979323846));
    }
    g.hold_rows(rows);
    out.shape.rows = out.shape.asked = rows;
    out.shape.hybrid = true;
    // The growth at the layer's top, mean over the wall: what the report says.
    double sum = 0.0;
    for (int i = 0; i < ni - 1; ++i)
        sum += std::hypot(m.x[at(ni, i, rows + 1)] - m.x[at(ni, i, rows)], m.y[at(ni, i, rows + 1)] - m.y[at(ni, i, rows)]) /
               std::hypot(m.x[at(ni, i, rows)] - m.x[at(ni, i, rows - 1)], m.y[at(ni, i, rows)] - m.y[at(ni, i, rows - 1)]);
    out.shape.growth = sum / (ni - 1);
    return out;
}

}  // namespace eg2d
