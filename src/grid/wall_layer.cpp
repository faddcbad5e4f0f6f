#include "grid/wall_layer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/cell.hpp"
#include "base/error.hpp"
#include "base/folds.hpp"
#include "base/polyline.hpp"

namespace eg2d {

namespace {

struct Vec {
    double x, y;
};

std::size_t at(const Grid &g, int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(g.ni()) * j; }
Vec point(const Grid &g, int i, int j) { return {g.x[at(g, i, j)], g.y[at(g, i, j)]}; }
void put(Grid &g, int i, int j, Vec p) {
    g.x[at(g, i, j)] = p.x;
    g.y[at(g, i, j)] = p.y;
}

// Unit normals of the JMIN nodes, into the domain: perpendicular to the
// central tangent (one-sided at a C-grid's outflow ends; across the cut of an
// O-grid, so a sharp trailing edge gets the bisector of its two faces).
std::vector<Vec> wall_normals(const Grid &g) {
    const int ni = g.ni();
    const bool ring = g.topology() == Topology::O;
    std::vector<Vec> n(static_cast<std::size_t>(ni));
    double side = 0.0;
    for (int i = 0; i < ni; ++i) {
        int a = i - 1, b = i + 1;
        if (ring) {
            if (a < 0) a = ni - 2;
            if (b > ni - 1) b = 1;
        } else {
            a = std::max(a, 0);
            b = std::min(b, ni - 1);
        }
        const Vec pa = point(g, a, 0), pb = point(g, b, 0);
        const double tx = pb.x - pa.x, ty = pb.y - pa.y, len = std::hypot(tx, ty);
        n[static_cast<std::size_t>(i)] = len > 0.0 ? Vec{-ty / len, tx / len} : Vec{0.0, 0.0};
        const Vec p0 = point(g, i, 0), p1 = point(g, i, 1);
        side += n[static_cast<std::size_t>(i)].x * (p1.x - p0.x) + n[static_cast<std::size_t>(i)].y * (p1.y - p0.y);
    }
    if (side < 0.0)  // the domain lies on the other side of the wall's direction
        for (Vec &v : n) v = {-v.x, -v.y};
    return n;
}

// Distances along one column: the layer (rows 0..rows) then its geometric
// continuation over `length` to row nj-1.
std::vector<double> column_distances(double first, double growth, int rows, int nj, double length) {
    std::vector<double> s(static_cast<std::size_t>(nj), 0.0);
    for (int k = 0; k <= rows; ++k) s[static_cast<std::size_t>(k)] = layer_distance(first, growth, k);
    const double base = s[static_cast<std::size_t>(rows)], rest = std::max(length - base, 0.0);
    const int m = nj - 1 - rows;
    const double next = first * std::pow(growth, rows), r = geometric_ratio(next, rest, m);
    double sum = 0.0, cell = next;
    std::vector<double> cells(static_cast<std::size_t>(m));
    for (int k = 0; k < m; ++k, cell *= r) sum += (cells[static_cast<std::size_t>(k)] = cell);
    for (int k = 0; k < m; ++k)  // scaled to end exactly at the far side
        s[static_cast<std::size_t>(rows + k + 1)] = s[static_cast<std::size_t>(rows + k)] + cells[static_cast<std::size_t>(k)] * rest / sum;
    return s;
}

// Places a boundary column (a C-grid's outflow side) along its own line.
void redistribute_side(Grid &g, int i, const std::vector<double> &s) {
    std::vector<Vec2> line;
    for (int j = 0; j < g.nj(); ++j) line.push_back({g.x[at(g, i, j)], g.y[at(g, i, j)]});
    const std::vector<Vec2> p = points_along(line, s);  // clamped to the side's length
    for (int j = 1; j < g.nj() - 1; ++j) put(g, i, j, {p[static_cast<std::size_t>(j)].x, p[static_cast<std::size_t>(j)].y});
}

}  // namespace

int wall_layer_rows(int nj) { return std::max(1, (nj - 1) / 3); }



namespace {

constexpr double kCornerCover = 2.0;     // layer thickness over the corner's wall cell
constexpr double kMaxLayerShare = 0.6;   // of the grid's rows, at most, for that
constexpr double kSharpTurn = 1.0;       // radians: a wall node that turns more is a corner
constexpr double kMaxCutShare = 0.2;     // of a C-grid cut column's length, for its layer

// The layer thickness a sharp convex corner of an O-grid's wall asks for
// (kCornerCover times its longest wall cell), or 0: none, or not an O-grid
// (a C-grid's rows run from the airfoil into the wake without turning).
double corner_cover(const Grid &g) {
    if (g.topology() != Topology::O) return 0.0;
    const int ni = g.ni();
    double cover = 0.0;
    for (int i = 0; i < ni - 1; ++i) {
        const Vec p = point(g, i, 0), a = point(g, i == 0 ? ni - 2 : i - 1, 0), b = point(g, i + 1, 0);
        const double ux = p.x - a.x, uy = p.y - a.y, vx = b.x - p.x, vy = b.y - p.y;
        const double turn = std::fabs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy));
        if (turn > kSharpTurn) cover = std::max(cover, kCornerCover * std::max(std::hypot(ux, uy), std::hypot(vx, vy)));
    }
    return cover;
}

// The growth that makes `rows` cells from `first` reach `thickness` (at most 2).
double growth_for(double first, double thickness, int rows) {
    double lo = 1.0, hi = 2.0;
    for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (layer_distance(first, mid, rows) < thickness ? lo : hi) = mid;
    }
    return hi;
}

}  // namespace

bool wall_has_sharp_corner(const Grid &g) { return corner_cover(g) > 0.0; }

double layer_distance(double first, double growth, int k) {
    return growth == 1.0 ? first * k : first * (std::pow(growth, k) - 1.0) / (growth - 1.0);
}

double geometric_ratio(double first, double length, int intervals) {
    if (intervals <= 1 || first <= 0.0) return 1.0;
    auto span = [&](double r) {
        if (std::fabs(r - 1.0) < 1e-12) return first * intervals;
        if (intervals * std::log(r) > 700.0) return std::numeric_limits<double>::infinity();  // no overflow flag
        return first * (std::pow(r, intervals) - 1.0) / (r - 1.0);
    };
    double lo = 0.5, hi = 2.0;
    if (span(lo) >= length) return lo;
    if (span(hi) <= length) return hi;
    for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        (span(mid) < length ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

WallLayerShape shape_wall_layer(Grid &g, double h, double growth, bool fill_above) {
    const int ni = g.ni(), nj = g.nj();
    const bool cgrid = g.topology() == Topology::C;
    g.hold_rows(0);  // the topology's own connectivity: the C-grid's cut index
    const int wake = cgrid ? g.connectivity().wake() : 0;
    const int orientation = grid_orientation(g);
    const std::vector<Vec> n = wall_normals(g);
    // First heights: h on the wall; along a C-grid's cut graded with the
    // cut's own spacing (ds_i / ds at the trailing edge).
    std::vector<double> first(static_cast<std::size_t>(ni), h);
    if (cgrid && wake > 0) {
        const Vec te = point(g, wake, 0), before = point(g, wake - 1, 0);
        const double ds_te = std::hypot(te.x - before.x, te.y - before.y);
        for (int i = 0; i < wake; ++i) {
            const Vec a = point(g, i, 0), b = point(g, i + 1, 0);
            const double ratio = ds_te > 0.0 ? std::hypot(b.x - a.x, b.y - a.y) / ds_te : 1.0;
            first[static_cast<std::size_t>(i)] = first[static_cast<std::size_t>(ni - 1 - i)] = h * std::max(1.0, ratio);
        }
    }
    WallLayerShape out;
    out.asked = std::min(wall_layer_rows(nj), nj - 3);
    // A sharp convex corner of an O-grid's wall (a trailing edge) turns the
    // rows by nearly 180 degrees over one wall cell: the rows above the layer
    // can follow that only once the layer is thicker than the cells there
    // (measured: NACA 0012 129x33 at 1e-5 chord, a layer 2e-4 thick under
    // cells 0.016 long folded 34 cells at the corner). So the layer reaches
    // kCornerCover times the corner's wall cells: with more rows (up to
    // kMaxLayerShare of the grid), then with a larger growth.
    const double cover = corner_cover(g);
    if (cover > 0.0) {
        const int most = std::max(out.asked, static_cast<int>(kMaxLayerShare * (nj - 1)));
        while (out.asked < most && layer_distance(h, growth, out.asked) < cover) ++out.asked;
        if (layer_distance(h, growth, out.asked) < cover) growth = growth_for(h, cover, out.asked);
    }
    out.growth = growth;
    // The cut's graded heights stop where the layer would take more than
    // kMaxCutShare of its column (the example naca0012-c: wake cells 40x the
    // trailing edge's at the outflow made a layer half the column high, and
    // the rows above folded against the outflow side).
    if (cgrid && wake > 0) {
        const double unit = layer_distance(1.0, growth, out.asked);
        for (int i = 0; i < ni; ++i) {
            if (i >= wake && i <= ni - 1 - wake) continue;
            const Vec a = point(g, i, 0), b = point(g, i, nj - 1);
            const double cap = kMaxCutShare * std::hypot(b.x - a.x, b.y - a.y) / unit;
            first[static_cast<std::size_t>(i)] = std::max(h, std::min(first[static_cast<std::size_t>(i)], cap));
        }
    }
    const std::vector<Vec> wall = [&] {
        std::vector<Vec> w;
        for (int i = 0; i < ni; ++i) w.push_back(point(g, i, 0));
        return w;
    }();
    const int i_end = cgrid ? ni : ni - 1;  // O-grid: column ni-1 is column 0
    auto place_row = [&](int k) {
        for (int i = 0; i < i_end; ++i) {
            const double d = layer_distance(first[static_cast<std::size_t>(i)], growth, k);
            put(g, i, k, {wall[static_cast<std::size_t>(i)].x + d * n[static_cast<std::size_t>(i)].x,
                          wall[static_cast<std::size_t>(i)].y + d * n[static_cast<std::size_t>(i)].y});
        }
        if (!cgrid) put(g, ni - 1, k, point(g, 0, k));
    };
    // Rows one by one; a row whose cells would fold ends the layer below it.
    std::vector<double> saved_x(static_cast<std::size_t>(ni)), saved_y(saved_x.size());
    for (int k = 1; k <= out.asked; ++k) {
        for (int i = 0; i < ni; ++i) {
            saved_x[static_cast<std::size_t>(i)] = g.x[at(g, i, k)];
            saved_y[static_cast<std::size_t>(i)] = g.y[at(g, i, k)];
        }
        place_row(k);
        bool folded = false;
        for (int i = 0; i < ni - 1 && !folded; ++i) folded = is_folded(Cell::at(g, i, k - 1), orientation);
        if (folded) {
            for (int i = 0; i < ni; ++i) {
                g.x[at(g, i, k)] = saved_x[static_cast<std::size_t>(i)];
                g.y[at(g, i, k)] = saved_y[static_cast<std::size_t>(i)];
            }
            out.fold_row = k;
            break;
        }
        out.rows = k;
    }
    // A C-grid's outflow sides follow the layer and its continuation.
    if (cgrid && out.rows > 0) {
        for (int i : {0, ni - 1}) {
            double length = 0.0;
            for (int j = 1; j < nj; ++j) {
                const Vec a = point(g, i, j - 1), b = point(g, i, j);
                length += std::hypot(b.x - a.x, b.y - a.y);
            }
            redistribute_side(g, i, column_distances(first[static_cast<std::size_t>(i)], growth, out.rows, nj, length));
        }
    }
    if (fill_above && out.rows > 0) {
        for (int i = cgrid ? 1 : 0; i < (cgrid ? ni - 1 : ni - 1); ++i) {
            const Vec a = point(g, i, out.rows), b = point(g, i, nj - 1);
            const double length = std::hypot(b.x - a.x, b.y - a.y);
            const std::vector<double> s = column_distances(first[static_cast<std::size_t>(i)], growth, out.rows, nj, 0.0);
            std::vector<double> t = column_distances(first[static_cast<std::size_t>(i)], growth, out.rows, nj,
                                                     s[static_cast<std::size_t>(out.rows)] + length);
            for (int j = out.rows + 1; j < nj - 1; ++j) {
                const double f = (t[static_cast<std::size_t>(j)] - t[static_cast<std::size_t>(out.rows)]) / length;
                put(g, i, j, {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)});
            }
        }
        if (!cgrid)
            for (int j = 0; j < nj; ++j) put(g, ni - 1, j, point(g, 0, j));
    }
    if (out.rows > 0) g.hold_rows(out.rows);
    return out;
}

}  // namespace eg2d
