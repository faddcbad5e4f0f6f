#include "grid/graded_layer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/cell.hpp"
#include "base/error.hpp"
#include "base/folds.hpp"
#include "base/patches.hpp"
#include "base/polyline.hpp"
#include "grid/invert_controls.hpp"
#include "grid/march_schedule.hpp"

namespace eg2d {

namespace {

// A re-spaced start whose cells are all within this of square (its largest
// corner angle's deviation from 90 degrees) is kept: its controls are the
// ones that make it an exact solution (invert_controls.hpp), and the solve
// adds the wall's angle alone. Measured (bench --internal, 257x129 at 1e-5):
// a bend's start is within 0.5 degrees, a pipe's 12, a diffuser's
// (untangled) 27; kept, they converge in 5-7 multigrid cycles against 14-15
// on the one-dimensional controls, and their skewness is 0.5, 11.7 and 26.6
// degrees against 15.4, 15.5 and 26.5 (the solve's Laplace-like pull toward
// a bend's inner wall skews it). The TMR bump's start (its top and bottom
// spaced differently) is skewed 56 degrees where the one-dimensional
// controls smooth it to 14.5: not kept.
constexpr double kKeepStartSkew = 30.0;


// The longest wall-normal line searched for `needed`.
constexpr int kMostNodes = 1 << 20;

double dist(const Vec2 &a, const Vec2 &b) { return std::hypot(b.x - a.x, b.y - a.y); }

// First-cell height at each node of a wall side: h on its wall stretches,
// log-linear in the index between them and toward a corner's own spacing on
// the rest (an O-grid's side wraps round).
// A side's points are kept when its first cell is within this factor of
// the layer's there and its cells grow within kGradedGrowth: the lines
// beside it then take its shape (blend_sides); else its nodes are moved.
constexpr double kKeepFirst = 1.1;

// A wall that runs into a corner of a side that is no wall and keeps its
// points (their first cell within kKeepFirst of h) ends on that side's first
// cell, blended over this many nodes: ending on h, the TMR flat plate's last
// column met the outflow's 2.0047e-6 at 2e-6, which checkMesh saw as 10.4
// degrees of non-orthogonality in cells 2e4 times longer than high.
constexpr int kCornerBlend = 8;

}  // namespace

std::vector<double> wall_node_heights(const Grid &g, Side s, const std::array<double, 4> &height) {
    const double h = height[static_cast<std::size_t>(s)];
    const int n = g.side_length(s);
    const bool ring = g.topology() == Topology::O;
    auto asked = [&](int k) { return g.wall_height_at(s, k, h); };
    std::vector<double> v(static_cast<std::size_t>(n), -1.0);
    for (const Patch &p : resolve_patches(g))
        if (p.side == s && p.type == PatchType::Wall)
            for (int k = p.first; k <= p.last; ++k) v[static_cast<std::size_t>(k)] = asked(k);
    // A side given a height but no stretch of type wall (an O-grid's JMAX is
    // "farfield" by default) is a wall all along: the height was asked for it.
    if (std::none_of(v.begin(), v.end(), [](double d) { return d > 0.0; }))
        for (int k = 0; k < n; ++k) v[static_cast<std::size_t>(k)] = asked(k);
    if (ring && v.front() > 0.0) v.back() = v.front();
    if (!ring) {
        const bool eta = s == Side::JMin || s == Side::JMax;
        for (int k : {0, n - 1}) {
            const double corner = std::hypot(g.x[side_node(g, s, k, 1)] - g.x[side_node(g, s, k)],
                                             g.y[side_node(g, s, k, 1)] - g.y[side_node(g, s, k)]);
            double &vk = v[static_cast<std::size_t>(k)];
            const std::size_t across = static_cast<std::size_t>(k == 0 ? (eta ? 3 : 0) : (eta ? 1 : 2));
            if (vk < 0.0) {
                vk = corner;
            } else if (!(height[across] > 0.0) && corner > 0.0 && corner != vk &&
                       std::fabs(std::log(corner / vk)) <= std::log(kKeepFirst)) {
                vk = corner;
                for (int m = 1; m <= kCornerBlend && m < n / 4; ++m) {
                    const int km = k == 0 ? m : n - 1 - m;
                    double &vm = v[static_cast<std::size_t>(km)];
                    if (vm == asked(km)) vm = -1.0;  // filled by the blend below
                }
            }
        }
    }
    const int span = ring ? n - 1 : n;  // an O-grid's last node is its first
    int known = -1;
    for (int k = 0; k < span && known < 0; ++k)
        if (v[static_cast<std::size_t>(k)] > 0.0) known = k;
    if (known < 0) return {};
    if (!ring) known = 0;  // both ends are known
    for (int step = 0; step < span; ++step) {  // from each known node to the next
        const int a = (known + step) % span;
        if (!(v[static_cast<std::size_t>(a)] > 0.0)) continue;
        int b = a + 1;
        while (!(v[static_cast<std::size_t>(b % span)] > 0.0)) ++b;
        if (!ring && b >= span) break;
        const double la = std::log(v[static_cast<std::size_t>(a)]), lb = std::log(v[static_cast<std::size_t>(b % span)]);
        // Smoothstep in the log: no kink where the blend leaves a wall
        // stretch (log-linear, the rows bent there by Phi 1.03 at the TMR
        // bump's plate ends, and multigrid's coarse levels folded).
        for (int k = a + 1; k < b; ++k) {
            const double u = static_cast<double>(k - a) / (b - a);
            v[static_cast<std::size_t>(k % span)] = std::exp(la + (lb - la) * u * u * (3.0 - 2.0 * u));
        }
    }
    if (ring) v.back() = v.front();
    return v;
}

// The cells of a line of `cells` cells and length `length` off a wall at its
// start (first > 0), at its end (last > 0) or both.
// Between two walls: geometric from both ends at one ratio r, each cell the
// smaller of the two series, r such that they fill the line; the log-
// quadratic graded_cells where even r = 1 overfills it.
namespace {

std::vector<double> two_sided_cells(int cells, double first, double last, double length) {
    // In logs, so that no power overflows (the FP flags stay clear): cell k
    // is exp(min(ln first + k ln r, ln last + (cells-1-k) ln r)); a sum past
    // the length ends early, which is all the bisection needs.
    auto fill = [&](double r, std::vector<double> *c) {
        const double lr = std::log(r), la = std::log(first), lb = std::log(last);
        double sum = 0.0;
        for (int k = 0; k < cells; ++k) {
            const double e = std::min(la + k * lr, lb + (cells - 1 - k) * lr);
            if (!c && (e > 700.0 || sum > length)) return std::numeric_limits<double>::infinity();
            const double v = std::exp(e);
            sum += v;
            if (c) c->push_back(v);
        }
        return sum;
    };
    if (!(fill(1.0, nullptr) < length)) return graded_cells(cells, first, last, length);
    double lo = 1.0, hi = 2.0;
    while (fill(hi, nullptr) < length && hi < 1e3) hi *= 2.0;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (fill(mid, nullptr) < length ? lo : hi) = mid;
    }
    std::vector<double> c;
    const double sum = fill(hi, &c);
    for (double &v : c) v *= length / sum;
    return c;
}

}  // namespace

std::vector<double> graded_line_cells(int cells, double first, double last, double length) {
    if (first > 0.0 && last > 0.0) return two_sided_cells(cells, first, last, length);
    const double h = first > 0.0 ? first : last;
    // Growing cells at whatever ratio reaches the length, so that the first
    // cell is the one asked even where the growth then exceeds
    // kGradedGrowth (the run says so: `needed`); shrinking ones (a first
    // cell above the uniform one) down to geometric_ratio's 0.5.
    const double r = h * cells < length ? covering_ratio(cells, h, length) : geometric_ratio(h, length, cells);
    std::vector<double> c(static_cast<std::size_t>(cells));
    double cell = h, sum = 0.0;
    for (double &v : c) {
        v = cell;
        sum += cell;
        cell *= r;
    }
    for (double &v : c) v *= length / sum;  // the ratio's last digits
    if (!(first > 0.0)) std::reverse(c.begin(), c.end());
    return c;
}

double graded_end_growth(const std::vector<double> &c, bool from_start, bool from_end) {
    const int n = static_cast<int>(c.size());
    double worst = 1.0;
    auto ratio = [&](int k) {
        const double r = c[static_cast<std::size_t>(k + 1)] / c[static_cast<std::size_t>(k)];
        return std::max(r, 1.0 / r);
    };
    for (int k = 0; k + 1 < n && k < kGradedRows; ++k) {
        if (from_start) worst = std::max(worst, ratio(k));
        if (from_end) worst = std::max(worst, ratio(n - 2 - k));
    }
    return worst;
}

namespace {

// The smallest node count at which a line of this length keeps its cells
// within kGradedGrowth at its wall ends (a growth falls as nodes are added).
int nodes_needed(double first, double last, double length, int nodes, bool from_lo, bool from_hi) {
    auto meets = [&](int n) {
        try {
            return graded_end_growth(graded_line_cells(n - 1, first, last, length), from_lo, from_hi) <= kGradedGrowth;
        } catch (const Error &) {
            return false;
        }
    };
    if (meets(nodes)) return 0;
    int lo = nodes, hi = nodes;
    while (!meets(hi)) {
        lo = hi;
        if (hi >= kMostNodes) return kMostNodes;
        hi = std::min(2 * hi, kMostNodes);
    }
    while (hi - lo > 1) {
        const int mid = lo + (hi - lo) / 2;
        (meets(mid) ? hi : lo) = mid;
    }
    return hi;
}

// One family of lines (eta lines: columns, for JMIN/JMAX walls; xi lines:
// rows, for IMIN/IMAX), each with its arc lengths and target cells (its
// points read again where it is moved: kept for every line they were a
// fifth of a straight channel's new pages).
struct Line {
    std::vector<double> arc, cells;
    bool kept = false;  // a side whose points stay
};

std::vector<Vec2> line_points(const Grid &g, bool columns, int l) {
    return columns ? grid_column(g, l, g.nj() - 1) : grid_row(g, l);
}

std::vector<double> actual_cells(const std::vector<double> &arc) {
    std::vector<double> c(arc.size() - 1);
    for (std::size_t k = 0; k + 1 < arc.size(); ++k) c[k] = arc[k + 1] - arc[k];
    return c;
}

// Whether a side that is no wall follows the layer well enough to keep.
bool follows(const std::vector<double> &actual, const std::vector<double> &target, bool from_start, bool from_end) {
    auto close = [](double a, double t) { return a > 0.0 && std::fabs(std::log(a / t)) <= std::log(kKeepFirst); };
    if (from_start && !close(actual.front(), target.front())) return false;
    if (from_end && !close(actual.back(), target.back())) return false;
    return graded_end_growth(actual, from_start, from_end) <= kGradedGrowth;
}

// Cells times a shape factor (none: unchanged), fitted to the length
// away from the walls (fit_length).
std::vector<double> shaped(std::vector<double> cells, const std::vector<double> &factor, double length, bool lo,
                           bool hi) {
    if (factor.empty()) return cells;
    for (std::size_t k = 0; k < cells.size(); ++k) cells[k] *= factor[k];
    // (the shares first: an argument's std::move may run before cells.size())
    const std::vector<double> share = wall_shares(static_cast<int>(cells.size()), lo, hi);
    return fit_length(std::move(cells), share, length);
}

// The lines between two kept sides take their shape: each cell times
// exp((1-s) r_0 + s r_N), r the log of a kept side's cell over its target,
// s = l/(lines-1) (Thomas & Middlecoff's linear interpolation across, in the
// log of the cells so that they stay positive), then scaled to the length.
std::vector<std::vector<double>> blend_sides(std::vector<Line> &lines, bool lo, bool hi) {
    const std::size_t n = lines.size();
    std::vector<double> r0(lines[0].cells.size(), 0.0), rn(r0);
    auto logs = [](const Line &L, std::vector<double> &r) {
        if (!L.kept) return;
        const std::vector<double> a = actual_cells(L.arc);
        for (std::size_t k = 0; k < r.size(); ++k) r[k] = a[k] > 0.0 ? std::log(a[k] / L.cells[k]) : 0.0;
    };
    logs(lines.front(), r0);
    logs(lines.back(), rn);
    std::vector<std::vector<double>> factor(n);
    if (!lines.front().kept && !lines.back().kept) return factor;
    // One side kept and the other moved: the moved one takes the kept one's
    // shape too, and so every line between. A wall IMIN clustered at both
    // ends (a cavity's, Vinokur's) with IMAX moved to the layer's one-sided
    // spacing sheared the rows between by up to 89 degrees (177x81 at 1e-4:
    // every multigrid cycle folded), where the unit square has a tensor grid.
    // Not where that shape, on the moved side's length, grows faster than
    // the layer allows and than the kept side itself does (an S-shaped
    // diffuser's outlet, twice its inlet's width, took the inlet's Vinokur
    // spacing, 1.165, to 1.21 at 177x81).
    auto adopts = [&](const Line &moved, const Line &kept, const std::vector<double> &r) {
        std::vector<double> f(r.size());
        for (std::size_t k = 0; k < r.size(); ++k) f[k] = std::exp(r[k]);
        const double grows = graded_end_growth(shaped(moved.cells, f, moved.arc.back(), lo, hi), lo, hi);
        // (to round-off: alike sides of a square grow alike)
        return grows <= std::max(kGradedGrowth, graded_end_growth(actual_cells(kept.arc), lo, hi)) * (1.0 + 1e-9);
    };
    if (!lines.front().kept && adopts(lines.front(), lines.back(), rn)) r0 = rn;
    if (!lines.back().kept && adopts(lines.back(), lines.front(), r0)) rn = r0;
    for (std::size_t l = 0; l < n; ++l) {
        if (lines[l].kept) continue;
        const double t = static_cast<double>(l) / static_cast<double>(n - 1);
        factor[l].resize(r0.size());
        for (std::size_t k = 0; k < r0.size(); ++k) factor[l][k] = std::exp((1 - t) * r0[k] + t * rn[k]);
        lines[l].cells = shaped(lines[l].cells, factor[l], lines[l].arc.back(), lo, hi);
    }
    return factor;
}

// Re-spaces one family's lines in place: targets from the heights at their
// ends, the sides kept or moved, the lines between blended to kept sides.
void grade_family(Grid &g, bool columns, GradedLayer &out, std::string &moved, std::string &shaped_by) {
    GradedFamily fam;
    fam.columns = columns;
    const bool ring = g.topology() == Topology::O;
    const std::vector<double> &lo = out.heights[columns ? 0 : 3], &hi = out.heights[columns ? 2 : 1];
    const int count = columns ? g.ni() : g.nj(), nodes = columns ? g.nj() : g.ni();
    const int lines = ring ? count - 1 : count;  // a ring's last column is its first
    const Side across[2] = {columns ? Side::IMin : Side::JMin, columns ? Side::IMax : Side::JMax};
    std::vector<Line> all(static_cast<std::size_t>(lines));
    for (int l = 0; l < lines; ++l) {
        Line &L = all[static_cast<std::size_t>(l)];
        const double a = lo.empty() ? 0.0 : lo[static_cast<std::size_t>(l)];
        const double b = hi.empty() ? 0.0 : hi[static_cast<std::size_t>(l)];
        L.arc = arc_lengths(line_points(g, columns, l));
        try {
            // Lines alike (a straight channel's) share their cells: the
            // ratio's search per line was a fifth of such a run.
            const Line *prev = l > 0 ? &all[static_cast<std::size_t>(l - 1)] : nullptr;
            const double pa = l > 0 && !lo.empty() ? lo[static_cast<std::size_t>(l - 1)] : 0.0;
            const double pb = l > 0 && !hi.empty() ? hi[static_cast<std::size_t>(l - 1)] : 0.0;
            L.cells = prev && pa == a && pb == b && prev->arc.back() == L.arc.back() ? prev->cells
                                                                                   : graded_line_cells(nodes - 1, a, b, L.arc.back());
        } catch (const Error &e) {
            fail(Failure::Argument, format("graded wall layer: the %s %d (length %.6g) cannot take first cells %.6g "
                                           "and %.6g in %d cells: %s", columns ? "column" : "row", l, L.arc.back(),
                                           a, b, nodes - 1, e.what()));
        }
        // The node count that would do, searched only where this line needs
        // more than the family's worst so far (a search per line took most of
        // the set-up of a bend 257x65).
        int &needed = columns ? out.shape.needed_nj : out.shape.needed_ni;
        if (graded_end_growth(L.cells, a > 0.0, b > 0.0) > kGradedGrowth)
            needed = std::max(needed, nodes_needed(a, b, L.arc.back(), std::max(nodes, needed), a > 0.0, b > 0.0));
        if (ring || (l != 0 && l != lines - 1)) continue;
        const Side side = across[l == 0 ? 0 : 1];
        L.kept = !out.heights[static_cast<std::size_t>(side)].empty() ||  // a wall's points never move
                 follows(actual_cells(L.arc), L.cells, a > 0.0, b > 0.0);
        if (!L.kept) moved += format("%s%s", moved.empty() ? "" : ", ", side_name(side));
    }
    fam.factor = ring ? std::vector<std::vector<double>>(all.size()) : blend_sides(all, !lo.empty(), !hi.empty());
    // Lines shaped by kept sides grow as those do: a wall side clustered at
    // both ends (Vinokur's function, 80 cells of 1e-4 at each end grow by
    // 1.21), whose points never move, passes its growth to every line
    // beside it; no node count of the layer's own would mend that.
    for (int end = 0; end < 2 && !ring; ++end) {
        const Line &L = all[end == 0 ? 0 : all.size() - 1];
        const double grows = graded_end_growth(actual_cells(L.arc), !lo.empty(), !hi.empty());
        if (L.kept && grows > kGradedGrowth)
            shaped_by += format("%sthe points of %s (kept as given) grow by %.3g within %d cells of the wall, and so "
                                "do the lines beside them: space them as the layer or give more nodes",
                                shaped_by.empty() ? "" : "; ", side_name(across[end]), grows, kGradedRows);
    }
    out.families.push_back(std::move(fam));
    for (int l = 0; l < lines; ++l) {
        const Line &L = all[static_cast<std::size_t>(l)];
        const double a = lo.empty() ? 0.0 : lo[static_cast<std::size_t>(l)];
        const double b = hi.empty() ? 0.0 : hi[static_cast<std::size_t>(l)];
        out.shape.growth = std::max(out.shape.growth, graded_end_growth(L.kept ? actual_cells(L.arc) : L.cells, a > 0.0, b > 0.0));
        if (L.kept) continue;
        std::vector<double> want(static_cast<std::size_t>(nodes), 0.0);
        for (int k = 1; k < nodes; ++k)
            want[static_cast<std::size_t>(k)] = want[static_cast<std::size_t>(k - 1)] + L.cells[static_cast<std::size_t>(k - 1)];
        want.back() = L.arc.back();
        // (a family's lines share no node that moves: line l is as it was)
        const std::vector<Vec2> p = points_along(line_points(g, columns, l), L.arc, want);
        for (int k = 1; k < nodes - 1; ++k) set_node(g, columns ? l : k, columns ? k : l, p[static_cast<std::size_t>(k)]);
    }
    if (ring)
        for (int k = 1; k < nodes - 1; ++k) set_node(g, count - 1, k, {g.x[node_index(g.ni(), 0, k)], g.y[node_index(g.ni(), 0, k)]});
}

// Two walls that meet at a corner hold each other's first cells: the
// points of each, next to the corner, are the other's layer, and no move
// can mend them (a wall's points never move). Where they are more than
// kCornerMismatch apart the corner cells fold or pinch: said up front.
constexpr double kCornerMismatch = 2.0;

std::string corner_notes(const Grid &g, const std::array<double, 4> &height) {
    if (g.topology() != Topology::Single) return {};
    std::string out;
    // (side a, its end node index: 0 or last; side b at that corner)
    static const int corners[4][3] = {{0, 0, 3}, {0, 1, 1}, {2, 0, 3}, {2, 1, 1}};
    for (const auto &c : corners) {
        const Side a = static_cast<Side>(c[0]), b = static_cast<Side>(c[2]);
        const double ha = height[static_cast<std::size_t>(c[0])], hb = height[static_cast<std::size_t>(c[2])];
        if (!(ha > 0.0) || !(hb > 0.0)) continue;
        const int ka = c[1] ? g.side_length(a) - 1 : 0, kb = c[0] == 0 ? 0 : g.side_length(b) - 1;
        const int step_a = c[1] ? -1 : 1, step_b = c[0] == 0 ? 1 : -1;
        // a's first spacing from the corner is b's layer, and b's is a's.
        const double along_a = std::hypot(g.x[side_node(g, a, ka + step_a)] - g.x[side_node(g, a, ka)],
                                          g.y[side_node(g, a, ka + step_a)] - g.y[side_node(g, a, ka)]);
        const double along_b = std::hypot(g.x[side_node(g, b, kb + step_b)] - g.x[side_node(g, b, kb)],
                                          g.y[side_node(g, b, kb + step_b)] - g.y[side_node(g, b, kb)]);
        auto off = [](double x, double y) { return std::max(x / y, y / x) > kCornerMismatch; };
        if (off(along_a, hb) || off(along_b, ha))
            out += format("%swall layer (graded): at the corner of walls %s and %s the points of %s are %.3g apart "
                          "where %s's first cell is %.3g, and those of %s %.3g where %s's is %.3g: cluster each "
                          "wall's points at the corner to the other's first cell, or the corner's cells fold",
                          out.empty() ? "" : "; ", side_name(a), side_name(b), side_name(a), along_a, side_name(b),
                          hb, side_name(b), along_b, side_name(a), ha);
    }
    return out;
}

// Whether every cell's corners are within `degrees` of 90 and turn alike
// (none folded or flat): |cos| <= sin(degrees) at each, no atan2 (the
// check took a tenth of a straight channel's whole run). Corners that all
// turn one way make that the grid's orientation: no pass for it first.
bool near_square(const Grid &g, double degrees) {
    const double s = std::sin(degrees * std::acos(-1.0) / 180.0), s2 = s * s;
    const std::size_t ni = static_cast<std::size_t>(g.ni());
    double o = 0.0;
    // Corner m of a cell lies between its edges e[m] (to the next corner)
    // and -e[m-1] (to the previous one): four edges a cell, not eight.
    auto square = [&](double ax, double ay, double bx, double by) {
        const double cross = bx * ay - by * ax, dot = -(ax * bx + ay * by);  // a x (-b), a . (-b)
        if (o == 0.0) o = cross > 0.0 ? 1.0 : -1.0;
        return cross * o > 0.0 && dot * dot <= s2 * ((ax * ax + ay * ay) * (bx * bx + by * by));
    };
    for (std::size_t j = 0; j + 1 < static_cast<std::size_t>(g.nj()); ++j) {
        const double *x0 = g.x.data() + j * ni, *x1 = x0 + ni, *y0 = g.y.data() + j * ni, *y1 = y0 + ni;
        for (std::size_t i = 0; i + 1 < ni; ++i) {
            const double e0x = x0[i + 1] - x0[i], e0y = y0[i + 1] - y0[i];
            const double e1x = x1[i + 1] - x0[i + 1], e1y = y1[i + 1] - y0[i + 1];
            const double e2x = x1[i] - x1[i + 1], e2y = y1[i] - y1[i + 1];
            const double e3x = x0[i] - x1[i], e3y = y0[i] - y1[i];
            if (!square(e0x, e0y, e3x, e3y) || !square(e1x, e1y, e0x, e0y) || !square(e2x, e2y, e1x, e1y) ||
                !square(e3x, e3y, e2x, e2y))
                return false;
        }
    }
    return true;
}

// The frozen background of a start not kept: each line's one-dimensional
// Phi, Psi (Thomas & Middlecoff 1980).
void one_dimensional_controls(const Grid &g, GradedLayer &out) {
    const int ni = g.ni(), nj = g.nj();
    const bool ring = g.topology() == Topology::O;
    for (int j = 1; j < nj - 1; ++j)
        for (int i = ring ? 0 : 1; i < ni - 1; ++i) {
            const int a = i == 0 ? ni - 2 : i - 1, b = i + 1;
            const Vec2 c{g.x[node_index(ni, i, j)], g.y[node_index(ni, i, j)]};
            const double back = dist({g.x[node_index(ni, a, j)], g.y[node_index(ni, a, j)]}, c),
                         ahead = dist(c, {g.x[node_index(ni, b, j)], g.y[node_index(ni, b, j)]});
            const double below = dist({g.x[node_index(ni, i, j - 1)], g.y[node_index(ni, i, j - 1)]}, c),
                         above = dist(c, {g.x[node_index(ni, i, j + 1)], g.y[node_index(ni, i, j + 1)]});
            out.phi[node_index(ni, i, j)] = -2.0 * (ahead - back) / (ahead + back);
            out.psi[node_index(ni, i, j)] = -2.0 * (above - below) / (above + below);
            if (ring && i == 0) {
                out.phi[node_index(ni, ni - 1, j)] = out.phi[node_index(ni, 0, j)];
                out.psi[node_index(ni, ni - 1, j)] = out.psi[node_index(ni, 0, j)];
            }
        }
}

// The start kept: every interior node's controls inverted from it, frozen.
void keep_start(const Grid &g, GradedLayer &out) {
    invert_grid_controls(g, 1, out.phi, out.psi);
    out.frozen = out.kept = true;
}

}  // namespace

GradedLayer shape_graded_layer(Grid &g, const std::array<double, 4> &height) {
    if (g.topology() == Topology::C)
        fail(Failure::Unsupported, "graded wall layer: C-grids have the hybrid layer (hybrid_layer.hpp)");
    GradedLayer out;
    out.shape.graded = true;
    std::array<std::vector<double>, 4> &h = out.heights;
    for (int s = 0; s < 4; ++s)
        if (height[static_cast<std::size_t>(s)] > 0.0 && g.has_side(static_cast<Side>(s)))
            h[static_cast<std::size_t>(s)] = wall_node_heights(g, static_cast<Side>(s), height);
    const std::string corners = corner_notes(g, height);
    std::string moved, shaped_by;
    for (bool columns : {true, false})
        if (!h[columns ? 0 : 3].empty() || !h[columns ? 2 : 1].empty()) grade_family(g, columns, out, moved, shaped_by);
    out.shape.moved_sides = !moved.empty();
    if (!moved.empty())
        out.shape.note = format("wall layer (graded): the nodes of %s moved along the side to the wall layer's "
                                "spacing, or to the shape of the side opposite where that is kept (their first cell "
                                "was more than %g times the layer's, or their cells grew by more than %g)",
                                moved.c_str(), kKeepFirst, kGradedGrowth);
    if (!corners.empty()) out.shape.note += (out.shape.note.empty() ? "" : "; ") + corners;
    if (!shaped_by.empty()) out.shape.note += (out.shape.note.empty() ? "wall layer (graded): " : "; ") + shaped_by;
    // Kept when near square, turned to the normals when that keeps it so
    // (one pass over the turned grid checks both); else the one-dimensional
    // background. Turned in place, its coordinates alone kept to go back to
    // (a copy of the grid was a twentieth of a straight channel's run), and
    // their storage then the controls': new pages, touched first, were most
    // of what a straight channel's layer cost over the solve without it.
    std::vector<double> x = g.x, y = g.y;
    turn_to_normals(g, out);
    const bool turned = near_square(g, kKeepStartSkew);
    if (!turned) {
        g.x.swap(x);
        g.y.swap(y);
    }
    out.phi = std::move(x);
    out.psi = std::move(y);
    out.phi.assign(g.size(), 0.0);
    out.psi.assign(g.size(), 0.0);
    if (turned || near_square(g, kKeepStartSkew)) keep_start(g, out);
    else one_dimensional_controls(g, out);
    return out;
}

std::vector<double> graded_target_cells(const GradedLayer &layer, const GradedFamily &f, int l, int cells,
                                        double length) {
    const std::vector<double> &lo = layer.heights[f.columns ? 0 : 3], &hi = layer.heights[f.columns ? 2 : 1];
    const std::size_t k = static_cast<std::size_t>(l);
    const double a = lo.empty() ? 0.0 : lo[k], b = hi.empty() ? 0.0 : hi[k];
    return shaped(graded_line_cells(cells, a, b, length), f.factor[k], length, !lo.empty(), !hi.empty());
}

}  // namespace eg2d
