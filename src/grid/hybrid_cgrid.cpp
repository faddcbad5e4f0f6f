#include "grid/hybrid_cgrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/polyline.hpp"
#include "grid/march_schedule.hpp"

namespace eg2d {

namespace {

// The cut's first cells stay h up to kRampStart layer thicknesses from the
// trailing edge, then grow as (ds / ds_0)^kRampPower (ds_0: the cut's
// spacing there) until the held rows' graded cells would shrink
// (largest_graded_first), which the far wake reaches. The figures, NACA
// 0012 C-grids (bench/RESULTS.md): a slower ramp leaves the wake's cells
// far apart in shape from column to column where they are 1e4-1e6 times
// wider than high, and OpenFOAM's non-orthogonality (measured between
// cell centres) reached 84-89 degrees on the every-other-node coarser
// levels of 385x97 (start 0.25-0.5, power 1-1.5; 71-75 with (0.06, 3))
// against no face above 70 with (0.03, 3) and one pair at 70.6 with
// (0.03, 2). The first cells growing as (ds / ds_te)^(1/2) all along
// (before): the held rows tilted across the narrow columns beside the
// trailing edge (wake skew 46-52 degrees at 385x97 and 769x193 to 500
// chords), non-orthogonality 69.6 / 83.7 / 88.1 on 385x97's three levels.
constexpr double kRampStart = 0.03;
constexpr double kRampPower = 3.0;
// Cut columns are straightened over this many layer thicknesses from the
// trailing edge (1, 4 and 16 gave the same figures within 0.1 degree).
constexpr double kStraightLength = 4.0;

}  // namespace

std::vector<double> cut_distances(const Grid &m) {
    const int ni = m.ni(), wake = m.connectivity().wake();
    std::vector<double> d(static_cast<std::size_t>(ni), 0.0);
    if (m.topology() != Topology::C || wake <= 0) return d;
    const std::vector<double> arc = arc_lengths(grid_row(m, 0));
    for (int i = 0; i < wake; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        d[k] = arc[static_cast<std::size_t>(wake)] - arc[k];
        d[static_cast<std::size_t>(ni - 1 - i)] = arc[static_cast<std::size_t>(ni - 1 - i)] - arc[static_cast<std::size_t>(ni - 1 - wake)];
    }
    return d;
}

double layer_thickness(const Grid &m, int rows) {
    return arc_lengths(grid_column(m, m.connectivity().wake(), rows)).back();
}

std::vector<double> cut_first_heights(const Grid &m, double h, int rows) {
    const int ni = m.ni(), wake = m.connectivity().wake();
    std::vector<double> first(static_cast<std::size_t>(ni), h);
    if (m.topology() != Topology::C || wake <= 0) return first;
    const std::vector<double> along = cut_distances(m);
    const double start = kRampStart * layer_thickness(m, rows);
    const std::vector<Vec2> cut = grid_row(m, 0);
    double base = 0.0;  // the cut's spacing where the ramp starts
    for (int i = wake - 1; i >= 0; --i) {
        const std::size_t k = static_cast<std::size_t>(i);
        const double ds = std::hypot(cut[k + 1].x - cut[k].x, cut[k + 1].y - cut[k].y);
        if (base == 0.0 && along[k] >= start) base = ds;
        first[k] = first[static_cast<std::size_t>(ni - 1 - i)] =
            base > 0.0 ? h * std::pow(std::max(1.0, ds / base), kRampPower) : h;
    }
    return first;
}

std::vector<Vec2> straightened_column(const Grid &m, int i, int rows, double along, double thickness) {
    std::vector<Vec2> column = grid_column(m, i, rows);
    if (along <= 0.0) return column;
    const std::vector<double> arc = arc_lengths(column);
    const double w = std::min(1.0, along / (kStraightLength * thickness));
    const Vec2 a = column.front(), b = column.back();
    for (std::size_t k = 1; k + 1 < column.size(); ++k) {
        const double t = arc[k] / arc.back();
        column[k] = {(1 - w) * column[k].x + w * (a.x + t * (b.x - a.x)), (1 - w) * column[k].y + w * (a.y + t * (b.y - a.y))};
    }
    return column;
}

void place_outflow_side(Grid &g, const Grid &m, int i, int rows) {
    const int nj = g.nj();
    const std::vector<Vec2> side = grid_column(g, i, nj - 1);
    const std::vector<double> user = arc_lengths(side), march = arc_lengths(grid_column(m, i, nj - 1));
    const double total = user.back(), base = std::min(march[static_cast<std::size_t>(rows)], total);
    const double rest = march.back() - march[static_cast<std::size_t>(rows)];
    std::vector<double> want(static_cast<std::size_t>(nj));
    for (int j = 0; j < nj; ++j) {
        const std::size_t k = static_cast<std::size_t>(j);
        want[k] = j <= rows ? std::min(march[k], total)
                            : base + (total - base) * (march[k] - march[static_cast<std::size_t>(rows)]) / rest;
    }
    const std::vector<Vec2> p = points_along(side, want);
    for (int j = 1; j < nj - 1; ++j) set_node(g, i, j, p[static_cast<std::size_t>(j)]);
}

double respace_far_field(Grid &g, const Grid &m) {
    const int ni = g.ni(), top = g.nj() - 1;
    const std::vector<Vec2> line = grid_row(g, top), target = grid_row(m, top);
    const std::vector<double> arc = arc_lengths(line);
    const double total = arc.back(), gap = 1e-9 * total;
    std::vector<double> want(static_cast<std::size_t>(ni), 0.0);
    for (int i = 1; i < ni - 1; ++i) {  // the nearest point of the line, as an arc length
        const Vec2 p = target[static_cast<std::size_t>(i)];
        double best = std::numeric_limits<double>::infinity(), where = 0.0;
        for (int k = 0; k + 1 < ni; ++k) {
            const Vec2 a = line[static_cast<std::size_t>(k)], b = line[static_cast<std::size_t>(k + 1)];
            const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
            const double t = l2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
            if (d < best) {
                best = d;
                where = arc[static_cast<std::size_t>(k)] + t * std::sqrt(l2);
            }
        }
        want[static_cast<std::size_t>(i)] = std::max(where, want[static_cast<std::size_t>(i - 1)] + gap);
    }
    want[static_cast<std::size_t>(ni - 1)] = total;
    for (int i = ni - 2; i > 0; --i)  // in order at the far end too
        want[static_cast<std::size_t>(i)] = std::min(want[static_cast<std::size_t>(i)], want[static_cast<std::size_t>(i + 1)] - gap);
    const std::vector<Vec2> p = points_along(line, want);
    double moved = 0.0;
    for (int i = 1; i < ni - 1; ++i) {
        moved = std::max(moved, std::fabs(want[static_cast<std::size_t>(i)] - arc[static_cast<std::size_t>(i)]));
        set_node(g, i, top, p[static_cast<std::size_t>(i)]);
    }
    return total > 0.0 ? moved / total : 0.0;
}

}  // namespace eg2d
