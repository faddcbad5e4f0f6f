#include "grid/hybrid_layer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "base/polyline.hpp"
#include "grid/hybrid_cgrid.hpp"
#include "grid/hyperbolic.hpp"
#include "grid/march_schedule.hpp"

namespace eg2d {

namespace {

// The march's dissipation on a retry. Far fields of 100 chords and more
// folded the march's outer layers at its default (0.5): NACA 0012 O-grids
// (385x97, 385x129 to 100 chords, 250x100 to 500) marched at 1; C-grids
// 385x97 to 100 chords at 2, to 500 chords at 4 (bench/RESULTS.md).
constexpr double kRetrySmoothing[] = {1.0, 2.0, 4.0, 8.0};
// The frozen controls are kept within this: central differences are
// monotone while |Phi|, |Psi| < 2 (NUMERICS.md), and the march's outer
// layers, where a C-grid's clustered trailing-edge columns fan out, invert
// to |Psi| up to 114 (NACA 0012 385x97 to 100 chords), with which multigrid
// diverged in one cycle. Clipped at 1.5, 1 and 0.5 it converged in 3
// cycles, the wake's largest skew 23, 20 and 18 degrees; no O-grid case
// of the benchmark reaches the bound.
constexpr double kControlBound = 1.0;

// A wall node that turns by more than this is a corner (a blunt base's:
// 90 degrees); a sharp trailing edge's turn is the section's wedge angle
// short of 180 and is one too, with its neighbours.
constexpr double kCornerTurn = 0.25 * 3.14159265358979323846;

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

// The march's rows above `rows` in columns [first, last), each moved by the
// offset of its outer node to g's, times the arc-length fraction above the layer.
void start_above(Grid &g, const Grid &m, int rows, int first, int last) {
    const int ni = g.ni(), nj = g.nj();
    for (int i = first; i < last; ++i) {
        const std::vector<double> arc = arc_lengths(grid_column(m, i, nj - 1));
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

// Rows 1..rows of each column of m put back along the column at geometric
// distances from its first height (first[i], at most the layer's thickness
// over rows) that end at its row `rows`. The march's area smoothing and its
// step where the front turns leave first cells a few per cent off and the
// growth uneven there (a C-grid's trailing edge, a concave corner of the
// front: first cell 3% short, growth 1.24 at NACA 0012 385x97), and the
// control's contract is the height. The columns keep their lines (normal
// to the wall) and the layer's top row stays, so the rows above are as
// marched.
void respace_layer(Grid &m, int rows, const std::vector<double> &first) {
    for (int i = 0; i < m.ni(); ++i) {
        const std::vector<Vec2> column = grid_column(m, i, rows);
        const double total = arc_lengths(column).back();
        const double h1 = std::min(first[static_cast<std::size_t>(i)], total / rows);
        const double r = covering_ratio(rows, h1, total);
        std::vector<double> want(static_cast<std::size_t>(rows + 1), 0.0);
        double cell = h1;
        for (int j = 1; j <= rows; ++j, cell *= r) want[static_cast<std::size_t>(j)] = want[static_cast<std::size_t>(j - 1)] + cell;
        for (double &d : want) d *= total / want.back();  // the bisection's last digits
        const std::vector<Vec2> p = points_along(column, want);
        for (int j = 1; j < rows; ++j) set_node(m, i, j, p[static_cast<std::size_t>(j)]);
    }
}

// The march, retried with more dissipation while it folds (kRetrySmoothing);
// each retry is noted.
void march_with_retries(const Grid &g, Grid &m, Settings s, std::string &note) {
    std::vector<double> tries{s.march_smoothing};
    for (double r : kRetrySmoothing)
        if (r > tries.back()) tries.push_back(r);
    for (std::size_t k = 0;; ++k) {
        s.march_smoothing = tries[k];
        m = g;
        m.hold_rows(0);
        try {
            hyperbolic_march(m, s);
            return;
        } catch (const Error &e) {
            if (e.failure() != Failure::Folded || k + 1 == tries.size()) throw;
            note += format("%swall layer (hybrid): %s; marched again with EG2D_PARAM_MARCH_SMOOTHING %g",
                           note.empty() ? "" : "; ", e.what(), tries[k + 1]);
        }
    }
}

}  // namespace

int hybrid_layer_rows(int nj) { return std::max(1, std::min(2 * (nj - 1) / 3, nj - 3)); }

HybridLayer shape_hybrid_layer(Grid &g, const Settings &settings, double h, bool fill_above) {
    const int ni = g.ni(), nj = g.nj();
    const bool cgrid = g.topology() == Topology::C;
    HybridLayer out;
    Grid m = g;
    m.hold_rows(0);  // the topology's own connectivity: the C-grid's cut index
    const int wake = cgrid ? m.connectivity().wake() : 0;
    const std::vector<double> first = cut_first_heights(m, h);
    Settings s = settings;
    s.march_first_height = h;
    s.march_distance = outer_distance(g);
    s.march_growth = 3.0;  // the schedule's ratio is the one that reaches the distance in nj-1 layers
    march_with_retries(g, m, s, out.shape.note);  // throws before g changes
    const int rows = hybrid_layer_rows(nj);
    respace_layer(m, rows, first);
    g.hold_rows(0);
    // The columns the solve moves: an O-grid's all (ni-1 is 0), a C-grid's
    // between its outflow sides.
    const int i0 = cgrid ? 1 : 0, i1 = cgrid ? ni - 1 : ni;
    // The far field keeps its line, its nodes moved to where the march's
    // lines reach it (hybrid_cgrid.hpp): on the NACA 0012 O-grid example
    // (129x49, 4.5 chords) the lines met the user's uniform circle at 39
    // degrees from normal on average (54 at most) and at 1.6 (4.7) after.
    const double moved = respace_far_field(g, m);
    out.shape.note += format("%swall layer (hybrid): the far field's nodes moved along it to where the march's "
                             "lines end (at most %.3g of its length)%s", out.shape.note.empty() ? "" : "; ", moved,
                             cgrid ? ", the outflow sides' to follow the march" : "");
    if (cgrid)
        for (int i : {0, ni - 1}) place_outflow_side(g, m, i, rows);
    for (int j = 1; j <= rows; ++j)
        for (int i = i0; i < i1; ++i) set_node(g, i, j, {m.x[at(ni, i, j)], m.y[at(ni, i, j)]});
    if (fill_above) start_above(g, m, rows, i0, i1);
    out.phi.assign(g.size(), 0.0);
    out.psi.assign(g.size(), 0.0);
    int clipped = 0;
    for (int j = rows + 1; j < nj - 1; ++j)
        for (int i = i0; i < ni - 1; ++i) {
            double &phi = out.phi[at(ni, i, j)], &psi = out.psi[at(ni, i, j)];
            invert_controls(m, i, i == 0 ? ni - 2 : i - 1, i + 1, j, phi, psi);
            if (std::fabs(phi) > kControlBound || std::fabs(psi) > kControlBound) ++clipped;
            phi = std::clamp(phi, -kControlBound, kControlBound);
            psi = std::clamp(psi, -kControlBound, kControlBound);
            if (i == 0) {
                out.phi[at(ni, ni - 1, j)] = phi;
                out.psi[at(ni, ni - 1, j)] = psi;
            }
        }
    if (clipped > 0)
        out.shape.note += format("%swall layer (hybrid): the march's controls clipped to |Phi|, |Psi| <= %g at %d "
                                 "node(s) above the layer (its outer layers turn faster than the solve's central "
                                 "differences can follow there)", out.shape.note.empty() ? "" : "; ", kControlBound,
                                 clipped);
    // The first cells against the wall control's contract (height along the
    // normal to the wall's central difference r(i+1) - r(i-1)), over the
    // body but for its corners (a blunt base's, where the wall has no
    // normal) and the nodes beside them, as the grid report measures it.
    std::vector<char> corner(static_cast<std::size_t>(ni), 0);
    for (int i = wake; i < (cgrid ? ni - wake : ni - 1); ++i) {
        const int a = i > 0 ? i - 1 : ni - 2, b = i + 1;
        const double ux = m.x[at(ni, i, 0)] - m.x[at(ni, a, 0)], uy = m.y[at(ni, i, 0)] - m.y[at(ni, a, 0)];
        const double vx = m.x[at(ni, b, 0)] - m.x[at(ni, i, 0)], vy = m.y[at(ni, b, 0)] - m.y[at(ni, i, 0)];
        if (std::fabs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy)) > kCornerTurn)
            for (int k : {a, i, b}) corner[static_cast<std::size_t>(k)] = 1;
    }
    for (int i = wake; i < (cgrid ? ni - wake : ni - 1); ++i) {
        if (corner[static_cast<std::size_t>(i)]) continue;
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
    // The growth at the layer's top, mean over the body: what the report says.
    const int lo = wake, hi = cgrid ? ni - 1 - wake : ni - 1;
    double sum = 0.0;
    for (int i = lo; i < hi; ++i)
        sum += std::hypot(m.x[at(ni, i, rows + 1)] - m.x[at(ni, i, rows)], m.y[at(ni, i, rows + 1)] - m.y[at(ni, i, rows)]) /
               std::hypot(m.x[at(ni, i, rows)] - m.x[at(ni, i, rows - 1)], m.y[at(ni, i, rows)] - m.y[at(ni, i, rows - 1)]);
    out.shape.growth = sum / (hi - lo);
    return out;
}

}  // namespace eg2d
