#include "base/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

#include "base/error.hpp"
#include "base/plane.hpp"

namespace eg2d {

namespace {
std::vector<double> allocate(std::size_t n) {
    try {
        return std::vector<double>(n, 0.0);
    } catch (const std::bad_alloc &) {
        fail(Failure::Memory, format("cannot allocate %zu nodes", n));
    } catch (const std::length_error &) {
        fail(Failure::Memory, format("cannot allocate %zu nodes", n));
    }
}
}  // namespace

const char *side_name(Side s) {
    switch (s) {
    case Side::JMin: return "JMIN";
    case Side::IMax: return "IMAX";
    case Side::JMax: return "JMAX";
    case Side::IMin: return "IMIN";
    }
    return "?";
}

void check_coordinates(const char *what, const double *v, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        if (!std::isfinite(v[k]))
            fail(Failure::Argument, format("%s[%zu] = %g: coordinates must be finite", what, k, v[k]));
        if (std::fabs(v[k]) > kMaxCoordinate)
            fail(Failure::Argument, format("%s[%zu] = %g: coordinates must be within +-%g (the metric terms "
                                           "grow as their fourth power)", what, k, v[k], kMaxCoordinate));
    }
}

Grid::Grid(int ni, int nj) : ni_(ni), nj_(nj), base_connectivity_(ni, nj, Topology::Single), connectivity_(ni, nj, Topology::Single) {
    if (ni < 3) fail(Failure::Argument, format("ni = %d: need at least 3", ni));
    if (nj < 3) fail(Failure::Argument, format("nj = %d: need at least 3", nj));
    // Each node costs tens of doubles across the library; refuse sizes whose
    // byte counts could overflow before any allocation is tried.
    const std::size_t limit = std::numeric_limits<std::size_t>::max() / (64 * sizeof(double));
    if (static_cast<std::size_t>(ni) > limit / static_cast<std::size_t>(nj) ||
        static_cast<long long>(ni) * nj > std::numeric_limits<int>::max())
        fail(Failure::Argument, format("ni*nj = %d*%d overflows the node count", ni, nj));
    const std::size_t n = static_cast<std::size_t>(ni) * static_cast<std::size_t>(nj);
    x = allocate(n);
    y = allocate(n);
}

void Grid::set_topology(Topology t) {
    if (t == Topology::O && ni_ < 4)
        fail(Failure::Argument, format("ni = %d: an O-grid needs at least 4", ni_));
    if (t == Topology::C && ni_ < 7)
        fail(Failure::Argument, format("ni = %d: a C-grid needs at least 7 (wake, airfoil, wake)", ni_));
    base_connectivity_ = connectivity_ = Connectivity(ni_, nj_, t);
    held_rows_ = 0;
    lines_.clear();
    sides_set_ = 0;
    patches.clear();
    for (std::vector<double> &h : wall_node_spacing) h.clear();
    for (int si = 0; si < 4; ++si) {
        user_x_[si].clear();
        user_y_[si].clear();
    }
    initialized_ = false;
    std::fill(x.begin(), x.end(), 0.0);
    std::fill(y.begin(), y.end(), 0.0);
}

int Grid::side_length(Side s) const {
    return (s == Side::JMin || s == Side::JMax) ? ni_ : nj_;
}

bool Grid::has_side(Side s) const {
    if (topology() == Topology::O) return s == Side::JMin || s == Side::JMax;
    return true;
}

bool Grid::boundary_complete() const {
    for (int s = 0; s < 4; ++s)
        if (has_side(static_cast<Side>(s)) && !side_set(static_cast<Side>(s))) return false;
    return true;
}

double Grid::extent() const {
    Bounds box;
    for (int s = 0; s < 4; ++s) {
        const Side side = static_cast<Side>(s);
        if (!side_set(side)) continue;
        for (int p = 0; p < side_length(side); ++p) {
            const std::size_t k = side_node(ni_, nj_, side, p);
            box.add(x[k], y[k]);
        }
    }
    return box.diagonal();
}

void Grid::check_closed(Side s, const double *px, const double *py, int n) const {
    const double L = bounding_diagonal(px, py, static_cast<std::size_t>(n));
    if (std::hypot(px[n - 1] - px[0], py[n - 1] - py[0]) > kCornerTolerance * L)
        fail(Failure::Boundary,
             format("O-grid side %s is not closed: first point (%.17g, %.17g) vs last (%.17g, %.17g)",
                    side_name(s), px[0], py[0], px[n - 1], py[n - 1]));
    if (L == 0.0)
        fail(Failure::Boundary, format("side %s has all its points at (%g, %g)", side_name(s), px[0], py[0]));
}

void Grid::check_corners(Side s, const double *px, const double *py) const {
    const int n = side_length(s);
    // The side's first and last points and the sides they are shared with.
    struct End { int p; Side other; };
    End ends[2];
    switch (s) {
    case Side::JMin: ends[0] = {0, Side::IMin}; ends[1] = {n - 1, Side::IMax}; break;
    case Side::IMax: ends[0] = {0, Side::JMin}; ends[1] = {n - 1, Side::JMax}; break;
    case Side::JMax: ends[0] = {0, Side::IMin}; ends[1] = {n - 1, Side::IMax}; break;
    case Side::IMin: ends[0] = {0, Side::JMin}; ends[1] = {n - 1, Side::JMax}; break;
    }
    // Domain size: the bounding box of this side and of the sides already set.
    const double L = std::max(bounding_diagonal(px, py, static_cast<std::size_t>(n)), extent());
    for (const End &e : ends) {
        if (!side_set(e.other)) continue;
        const std::size_t k = side_node(ni_, nj_, s, e.p);
        const double dx = px[e.p] - x[k], dy = py[e.p] - y[k];
        if (std::hypot(dx, dy) > kCornerTolerance * L) {
            // Name the pair in the fixed order JMIN/IMAX, IMAX/JMAX, IMIN/JMAX, JMIN/IMIN.
            const bool first_is_j = (s == Side::JMin || s == Side::JMax);
            const Side a = first_is_j ? s : e.other, b = first_is_j ? e.other : s;
            const double ax = first_is_j ? px[e.p] : x[k], ay = first_is_j ? py[e.p] : y[k];
            const double bx = first_is_j ? x[k] : px[e.p], by = first_is_j ? y[k] : py[e.p];
            fail(Failure::Boundary, format("corner %s/%s: (%.17g, %.17g) vs (%.17g, %.17g)",
                                           side_name(a), side_name(b), ax, ay, bx, by));
        }
    }
}

int Grid::detect_wake(const double *px, const double *py) const {
    // The wake cut is the leading run of JMIN points that coincide with their
    // mirror images i <-> ni-1-i; its last point is the trailing edge.
    const double tol = kCornerTolerance * bounding_diagonal(px, py, static_cast<std::size_t>(ni_));
    auto same = [&](int i) { return std::hypot(px[i] - px[ni_ - 1 - i], py[i] - py[ni_ - 1 - i]) <= tol; };
    if (!same(0))
        fail(Failure::Boundary,
             format("C-grid side JMIN: its first point (%.17g, %.17g) and last point (%.17g, %.17g) must coincide "
                    "(the outflow end of the wake cut)", px[0], py[0], px[ni_ - 1], py[ni_ - 1]));
    int wake = 0;
    while (wake + 1 < (ni_ - 1) / 2 && same(wake + 1)) ++wake;
    if (wake < 1)
        fail(Failure::Boundary,
             format("C-grid side JMIN: points 1 and %d, (%.17g, %.17g) and (%.17g, %.17g), differ: the wake cut needs "
                    "at least its outflow point and the trailing edge on both halves", ni_ - 2, px[1], py[1],
                    px[ni_ - 2], py[ni_ - 2]));
    if (wake + 1 >= (ni_ - 1) / 2)
        fail(Failure::Boundary, format("C-grid side JMIN: points 0..%d all coincide with their mirror images: "
                                       "no body between the wake halves", wake));
    return wake;
}

void Grid::set_side(Side s, const double *px, const double *py) {
    if (!has_side(s))
        fail(Failure::Argument, format("side %s: an %s has only the sides JMIN (inner) and JMAX (outer); "
                                       "IMIN/IMAX is its periodic cut", side_name(s), topology_name(topology())));
    const int n = side_length(s);
    check_coordinates(s == Side::JMin ? "JMIN x" : s == Side::IMax ? "IMAX x" : s == Side::JMax ? "JMAX x" : "IMIN x",
                 px, static_cast<std::size_t>(n));
    check_coordinates(s == Side::JMin ? "JMIN y" : s == Side::IMax ? "IMAX y" : s == Side::JMax ? "JMAX y" : "IMIN y",
                 py, static_cast<std::size_t>(n));
    if (connectivity_.periodic_i()) check_closed(s, px, py, n);
    else check_corners(s, px, py);
    const int wake = (topology() == Topology::C && s == Side::JMin) ? detect_wake(px, py) : -1;
    write_side(s, px, py);
    if (connectivity_.periodic_i()) {  // the cut column holds the same point exactly
        const std::size_t k0 = side_node(ni_, nj_, s, 0), k1 = side_node(ni_, nj_, s, n - 1);
        x[k1] = x[k0];
        y[k1] = y[k0];
    }
    if (wake >= 0) {  // the upper wake holds the lower wake's points exactly
        for (int i = 0; i <= wake; ++i) {
            x[static_cast<std::size_t>(ni_ - 1 - i)] = x[static_cast<std::size_t>(i)];
            y[static_cast<std::size_t>(ni_ - 1 - i)] = y[static_cast<std::size_t>(i)];
        }
        base_connectivity_ = Connectivity(ni_, nj_, Topology::C, wake);
        rebuild_connectivity();
    }
    const int si = static_cast<int>(s);
    read_side(s, x.data(), y.data(), user_x_[si], user_y_[si]);  // after the cut's copies: the ring as set
    sides_set_ |= 1u << si;
}

double Grid::given_x(Side s, int p) const {
    return side_set(s) ? user_x_[static_cast<int>(s)][static_cast<std::size_t>(p)] : x[side_node(ni_, nj_, s, p)];
}

double Grid::given_y(Side s, int p) const {
    return side_set(s) ? user_y_[static_cast<int>(s)][static_cast<std::size_t>(p)] : y[side_node(ni_, nj_, s, p)];
}

void Grid::write_side(Side s, const double *px, const double *py) {
    const int n = side_length(s);
    for (int p = 0; p < n; ++p) {
        const std::size_t k = side_node(ni_, nj_, s, p);
        x[k] = px[p];
        y[k] = py[p];
    }
}

void Grid::read_side(Side s, const double *fx, const double *fy, std::vector<double> &px,
                     std::vector<double> &py) const {
    const int n = side_length(s);
    px.resize(static_cast<std::size_t>(n));
    py.resize(static_cast<std::size_t>(n));
    for (int p = 0; p < n; ++p) {
        const std::size_t k = side_node(ni_, nj_, s, p);
        px[static_cast<std::size_t>(p)] = fx[k];
        py[static_cast<std::size_t>(p)] = fy[k];
    }
}

bool Grid::boundary_is(const double *px, const double *py) const {
    std::vector<double> a, b;
    for (int k = 0; k < 4; ++k) {
        const Side s = static_cast<Side>(k);
        if (!has_side(s)) continue;
        if (!side_set(s)) return false;
        read_side(s, px, py, a, b);
        if (a != user_x_[k] || b != user_y_[k]) return false;
    }
    return true;
}

void Grid::restore_boundary() {
    for (int si = 0; si < 4; ++si)
        if (side_set(static_cast<Side>(si))) write_side(static_cast<Side>(si), user_x_[si].data(), user_y_[si].data());
}

void Grid::set_boundary(const double *px, const double *py) {
    // Validate every side against the others before changing anything.
    std::vector<double> sx[4], sy[4];
    for (int s = 0; s < 4; ++s)
        if (has_side(static_cast<Side>(s))) read_side(static_cast<Side>(s), px, py, sx[s], sy[s]);
    Grid trial(*this);
    trial.sides_set_ = 0;
    for (int s = 0; s < 4; ++s)
        if (has_side(static_cast<Side>(s))) trial.set_side(static_cast<Side>(s), sx[s].data(), sy[s].data());
    *this = std::move(trial);
}

void Grid::set_coordinates(const double *px, const double *py) {
    check_coordinates("x", px, size());
    check_coordinates("y", py, size());
    Grid trial(*this);
    trial.sides_set_ = 0;
    if (connectivity_.periodic_i()) {
        const double L = bounding_diagonal(px, py, size());
        for (int j = 0; j < nj_; ++j) {
            const std::size_t k0 = static_cast<std::size_t>(ni_) * j, k1 = k0 + ni_ - 1;
            if (std::hypot(px[k1] - px[k0], py[k1] - py[k0]) > kCornerTolerance * L)
                fail(Failure::Boundary,
                     format("O-grid cut: node (0, %d) = (%.17g, %.17g) vs node (%d, %d) = (%.17g, %.17g)", j,
                            px[k0], py[k0], ni_ - 1, j, px[k1], py[k1]));
        }
    }
    trial.set_boundary(px, py);
    std::copy(px, px + size(), trial.x.begin());
    std::copy(py, py + size(), trial.y.begin());
    trial.connectivity_.sync(trial.x.data());
    trial.connectivity_.sync(trial.y.data());
    trial.check_interior_lines();  // the lines hold their curves in a user's start grid too
    trial.restore_interior_lines();
    trial.initialized_ = true;
    *this = std::move(trial);
}

void Grid::hold_rows(int rows) {
    if (rows < 0 || rows > nj_ - 3)
        fail(Failure::Argument, format("held rows = %d: must be in [0, nj - 3 = %d]", rows, nj_ - 3));
    held_rows_ = rows;
    rebuild_connectivity();
}

void Grid::rebuild_connectivity() {
    const Connectivity held = held_rows_ > 0 ? base_connectivity_.held_below(held_rows_) : base_connectivity_;
    std::vector<int> columns, rows;
    for (const InteriorLine &l : lines_) (l.xi ? columns : rows).push_back(l.index);
    connectivity_ = held.with_fixed(columns, rows);
}

}  // namespace eg2d
