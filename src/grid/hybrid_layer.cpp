#include "grid/hybrid_layer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "base/cell.hpp"
#include "base/error.hpp"
#include "base/polyline.hpp"
#include "grid/hybrid_cgrid.hpp"
#include "grid/hyperbolic.hpp"
#include "grid/invert_controls.hpp"
#include "grid/march_schedule.hpp"

namespace eg2d {

namespace {

// The march's dissipation on a retry. Far fields of 100 chords and more
// folded the march's outer layers at its default (0.5): NACA 0012 O-grids
// (385x97, 385x129 to 100 chords, 250x100 to 500) marched at 1; C-grids
// 385x97 to 100 chords at 2, to 500 chords at 4 (bench/RESULTS.md).
constexpr double kRetrySmoothing[] = {1.0, 2.0, 4.0, 8.0};
// A C-grid's march starts at this dissipation. Its cut clusters the lines
// at the trailing edge, and they fan out over the march's outer layers:
// from 0.5 every NACA 0012 C-grid of bench/RESULTS.md's table (385x97,
// 513x129 to 100 chords, 385x97 and 769x193 to 500, first cells 1e-6 to
// 2e-5) folded above the held rows and was marched again, at 2 or 4; those
// marched at 2 ended with layers swung sideways (a last layer 24 degrees
// off its line), whose controls and far-field nodes left the wake's cells
// skewed by up to 63 degrees. From 4 none folds, and the wake's largest
// skew is 10-30 degrees on all of them; from 3, 10-39; from 6, 15-41.
constexpr double kCGridSmoothing = 4.0;
// The frozen controls are kept within this: central differences are
// monotone while |Phi|, |Psi| < 2 (NUMERICS.md), and the march's outer
// layers, where a C-grid's clustered trailing-edge columns fan out, invert
// to |Psi| up to 114 (NACA 0012 385x97 to 100 chords), with which multigrid
// diverged in one cycle. Clipped at 1.5, 1 and 0.5 it converged in 3
// cycles, the wake's largest skew 23, 20 and 18 degrees; no O-grid case
// of the benchmark reaches the bound.
constexpr double kControlBound = 1.0;

// The least distance of a JMAX node from a JMIN node.
double outer_distance(const Grid &g) {
    const int ni = g.ni(), top = g.nj() - 1;
    double d2 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < ni; ++a)
        for (int b = 0; b < ni; ++b) {
            const double dx = g.x[node_index(ni, a, top)] - g.x[node_index(ni, b, 0)], dy = g.y[node_index(ni, a, top)] - g.y[node_index(ni, b, 0)];
            d2 = std::min(d2, dx * dx + dy * dy);
        }
    return std::sqrt(d2);
}

// The march's rows above `rows` in columns [first, last), each moved by the
// offset of its outer node to g's, times the arc-length fraction above the layer.
void start_above(Grid &g, const Grid &m, int rows, int first, int last) {
    const int ni = g.ni(), nj = g.nj();
    for (int i = first; i < last; ++i) {
        const std::vector<double> arc = arc_lengths(grid_column(m, i, nj - 1));
        const double dx = g.x[node_index(ni, i, nj - 1)] - m.x[node_index(ni, i, nj - 1)];
        const double dy = g.y[node_index(ni, i, nj - 1)] - m.y[node_index(ni, i, nj - 1)];
        const double base = arc[static_cast<std::size_t>(rows)], span = arc[static_cast<std::size_t>(nj - 1)] - base;
        for (int j = rows + 1; j < nj - 1; ++j) {
            const double f = (arc[static_cast<std::size_t>(j)] - base) / span;
            g.x[node_index(ni, i, j)] = m.x[node_index(ni, i, j)] + f * dx;
            g.y[node_index(ni, i, j)] = m.y[node_index(ni, i, j)] + f * dy;
        }
    }
}

// Rows 1..rows of each column of m put back along the column
// (straightened_column) at distances from its first height (first[i]) to
// the march's own last cell below row `rows`, the log of the cells a
// quadratic (graded_cells), and ending at row `rows`. The march's area
// smoothing and its step where the front turns leave first cells a few per
// cent off and the growth uneven there (a C-grid's trailing edge, a
// concave corner of the front: first cell 3% short, growth 1.24 at NACA
// 0012 385x97), and the control's contract is the height. Keeping the
// march's last cell keeps the spacing continuous into the rows above: a
// geometric series from a cut's larger first cells made the cells above
// the layer 2.4-11 times its last. The first height is at most the
// largest whose cells do not shrink; the cut columns beyond the first
// that reaches it take its cells' shape, scaled to their length, so that
// neighbouring far-wake columns have the same shape (see
// cut_first_heights).
void respace_layer(Grid &m, int rows, const std::vector<double> &first) {
    const int ni = m.ni(), wake = m.topology() == Topology::C ? m.connectivity().wake() : 0;
    // The body, then each side of the cut outward from the trailing edge.
    std::vector<int> order;
    for (int i = wake; i <= ni - 1 - wake; ++i) order.push_back(i);
    for (int i = wake - 1; i >= 0; --i) order.push_back(i);
    for (int i = ni - wake; i < ni; ++i) order.push_back(i);
    std::vector<double> shape;  // cells over length of the side's first column at the largest first cell
    const std::vector<double> along = cut_distances(m);
    const double thickness = wake > 0 ? layer_thickness(m, rows) : 0.0;
    double most_guess = std::numeric_limits<double>::quiet_NaN(), q_guess = most_guess;  // the previous column's
    for (int i : order) {
        if (i == wake - 1 || i == ni - wake) shape.clear();
        const std::vector<Vec2> column = straightened_column(m, i, rows, along[static_cast<std::size_t>(i)], thickness);
        const std::vector<double> marched = arc_lengths(grid_column(m, i, rows));
        const double total = arc_lengths(column).back();
        const double last = (marched.back() - marched[static_cast<std::size_t>(rows - 1)]) * total / marched.back();
        const double h1 = first[static_cast<std::size_t>(i)];
        std::vector<double> cells;
        if (!shape.empty()) {
            for (double c : shape) cells.push_back(c * total);
        } else {
            const double most = largest_graded_first(rows, last, total, &most_guess);
            cells = graded_cells(rows, std::min(h1, most), last, total, &q_guess);
            if (h1 >= most && (i < wake || i > ni - 1 - wake))
                for (double c : cells) shape.push_back(c / total);
        }
        std::vector<double> want(static_cast<std::size_t>(rows + 1), 0.0);
        for (int j = 1; j <= rows; ++j)
            want[static_cast<std::size_t>(j)] = want[static_cast<std::size_t>(j - 1)] + cells[static_cast<std::size_t>(j - 1)];
        for (double &d : want) d *= total / want.back();  // the bisection's last digits
        const std::vector<Vec2> p = points_along(column, want);
        for (int j = 1; j < rows; ++j) set_node(m, i, j, p[static_cast<std::size_t>(j)]);
    }
}

// An O-grid march whose lines nearly meet above the held rows, though no
// cell folds: the largest angle (degrees) between a face between two cells
// of a row, from row `from` up, and the line joining the cells' centroids
// (what a finite-volume solver calls non-orthogonality; Jasak 1996). RAE
// 2822 257x129 (first cell 4.5e-6) marched at 0.5 with its lines over the
// aft lower surface pinched to a fifth of their spacing at layers 106-108:
// 86 degrees there, and the solve above the layer inherited it through the
// controls; marched at 1, 31.
constexpr double kPinchAngle = 75.0;

double pinch_angle(const Grid &m, int from) {
    const int ni = m.ni(), nj = m.nj();
    auto centroid = [&](int i, int j, double &cx, double &cy) {  // false for a cell of no area
        const Cell c = Cell::at(m, i, j);
        double a = 0;
        cx = cy = 0;
        for (int k = 0; k < 4; ++k) {
            const int n = (k + 1) % 4;
            const double w = c.x[k] * c.y[n] - c.x[n] * c.y[k];
            a += w, cx += (c.x[k] + c.x[n]) * w, cy += (c.y[k] + c.y[n]) * w;
        }
        if (!(a != 0.0)) return false;
        cx /= 3 * a, cy /= 3 * a;
        return true;
    };
    double worst = 0;
    for (int j = from; j < nj - 1; ++j)
        for (int i = 0; i < ni - 1; ++i) {
            const int e = i + 1 < ni - 1 ? i + 1 : 0;  // round the cut
            double ax, ay, bx, by;
            if (!centroid(i, j, ax, ay) || !centroid(e, j, bx, by)) continue;
            const double fx = m.x[node_index(ni, i + 1, j + 1)] - m.x[node_index(ni, i + 1, j)];
            const double fy = m.y[node_index(ni, i + 1, j + 1)] - m.y[node_index(ni, i + 1, j)];
            const double dx = bx - ax, dy = by - ay, d = std::hypot(dx, dy), f = std::hypot(fx, fy);
            if (!(d > 0.0 && f > 0.0)) continue;
            // the face's normal is (fy, -fx): the angle from it is 90 less the angle from the face
            const double c = std::fabs(fy * dx - fx * dy) / (d * f);
            worst = std::max(worst, std::acos(std::min(1.0, c)) * (180.0 / 3.14159265358979323846));
        }
    return worst;
}

// The march, first resumed with more dissipation from a little before the
// layer that folds (hyperbolic.hpp), then, while it still folds, marched
// again from the wall with each value of kRetrySmoothing; each retry is noted.
void march_with_retries(const Grid &g, Grid &m, Settings s, double least, std::string &note) {
    const bool ogrid = g.topology() == Topology::O;
    const int held = hybrid_layer_rows(g.nj());
    struct Pinched {
        Grid m;
        std::string note;
    };
    std::unique_ptr<Pinched> pinched;  // the first march that did not fold, if its lines nearly met
    std::vector<double> tries{std::max(s.march_smoothing, least)};
    for (double r : kRetrySmoothing)
        if (r > tries.back()) tries.push_back(r);
    const std::vector<double> raised(tries.begin() + 1, tries.end());
    // Then down to the user's, for a C-grid started at `least`: a coarse
    // leading edge folded its third layer at 4 and 8 and marched at 2
    // (tests/fortran/test_march.f90's C-grid, NACA 0012 385x97 with both
    // ends of the section at 2e-3 chord).
    for (auto r = std::rbegin(kRetrySmoothing); r != std::rend(kRetrySmoothing); ++r)
        if (*r < tries.front() && *r > s.march_smoothing) tries.push_back(*r);
    if (s.march_smoothing < tries.front()) tries.push_back(s.march_smoothing);
    for (std::size_t k = 0;; ++k) {
        s.march_smoothing = tries[k];
        m = g;
        m.hold_rows(0);
        std::string resumed;
        auto say_resumed = [&] {
            if (!resumed.empty()) note += format("%swall layer (hybrid): %s", note.empty() ? "" : "; ", resumed.c_str());
        };
        try {
            if (k == 0) hyperbolic_march(m, s, raised, resumed);
            else hyperbolic_march(m, s);
            say_resumed();
            const double pinch = ogrid && k + 1 < tries.size() && tries[k + 1] > tries[k] ? pinch_angle(m, held) : 0.0;
            if (pinch > kPinchAngle) {
                if (!pinched) pinched = std::make_unique<Pinched>(Pinched{m, note});
                note += format("%swall layer (hybrid): the march's lines nearly meet above the held rows (faces %.3g "
                               "degrees from their cells' line); marched again with EG2D_PARAM_MARCH_SMOOTHING %g",
                               note.empty() ? "" : "; ", pinch, tries[k + 1]);
                continue;
            }
            return;
        } catch (const Error &e) {
            say_resumed();
            if (e.failure() == Failure::Folded && pinched) {  // the retries fold: the first march, as it was
                m = pinched->m;
                note = pinched->note;
                return;
            }
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
    Settings s = settings;
    s.march_first_height = h;
    s.march_distance = outer_distance(g);
    s.march_growth = 3.0;  // the schedule's ratio is the one that reaches the distance in nj-1 layers
    if (cgrid && s.march_smoothing < kCGridSmoothing)
        out.shape.note = format("wall layer (hybrid): the C-grid marched first with EG2D_PARAM_MARCH_SMOOTHING %g "
                                "(%g asked: C-grids start at %g, as the cut's lines fan out from the trailing edge)",
                                kCGridSmoothing, s.march_smoothing, kCGridSmoothing);
    march_with_retries(g, m, s, cgrid ? kCGridSmoothing : 0.0, out.shape.note);  // throws before g changes
    const int rows = hybrid_layer_rows(nj);
    const std::vector<double> first = cut_first_heights(m, h, rows);
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
        for (int i = i0; i < i1; ++i) set_node(g, i, j, {m.x[node_index(ni, i, j)], m.y[node_index(ni, i, j)]});
    if (fill_above) start_above(g, m, rows, i0, i1);
    out.phi.assign(g.size(), 0.0);
    out.psi.assign(g.size(), 0.0);
    int clipped = 0;
    invert_grid_controls(m, rows + 1, out.phi, out.psi);
    for (int j = rows + 1; j < nj - 1; ++j)
        for (int i = i0; i < ni - 1; ++i) {
            double &phi = out.phi[node_index(ni, i, j)], &psi = out.psi[node_index(ni, i, j)];
            if (std::fabs(phi) > kControlBound || std::fabs(psi) > kControlBound) ++clipped;
            phi = std::clamp(phi, -kControlBound, kControlBound);
            psi = std::clamp(psi, -kControlBound, kControlBound);
            if (i == 0) {
                out.phi[node_index(ni, ni - 1, j)] = phi;
                out.psi[node_index(ni, ni - 1, j)] = psi;
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
        if (wall_corner(m, node_index(ni, a, 0), node_index(ni, i, 0), node_index(ni, b, 0)))
            for (int k : {a, i, b}) corner[static_cast<std::size_t>(k)] = 1;
    }
    for (int i = wake; i < (cgrid ? ni - wake : ni - 1); ++i) {
        if (corner[static_cast<std::size_t>(i)]) continue;
        const int a = i > 0 ? i - 1 : ni - 2, b = i + 1;
        const double tx = m.x[node_index(ni, b, 0)] - m.x[node_index(ni, a, 0)], ty = m.y[node_index(ni, b, 0)] - m.y[node_index(ni, a, 0)];
        const double ex = m.x[node_index(ni, i, 1)] - m.x[node_index(ni, i, 0)], ey = m.y[node_index(ni, i, 1)] - m.y[node_index(ni, i, 0)];
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
        sum += std::hypot(m.x[node_index(ni, i, rows + 1)] - m.x[node_index(ni, i, rows)], m.y[node_index(ni, i, rows + 1)] - m.y[node_index(ni, i, rows)]) /
               std::hypot(m.x[node_index(ni, i, rows)] - m.x[node_index(ni, i, rows - 1)], m.y[node_index(ni, i, rows)] - m.y[node_index(ni, i, rows - 1)]);
    out.shape.growth = sum / (hi - lo);
    return out;
}

}  // namespace eg2d
