#include "solvers/line_relax.hpp"

#include <algorithm>
#include <cmath>

#include "base/tridiagonal.hpp"

namespace eg2d {

void LineWork::reserve(int n) {
    const std::size_t m = static_cast<std::size_t>(std::max(n, 1));
    if (a.size() >= m) return;
    a.resize(m);
    b.resize(m);
    c.resize(m);
    dx.resize(m);
    dy.resize(m);
    cyclic.resize(5 * m);
}

namespace {

// One row of a line system: a d[k-1] + b d[k] + c d[k+1] = -(rx, ry).
struct Row {
    double a, b, c, rx, ry;
};

// The row at the node of stencil s. `along_xi` picks which second difference
// (and first-difference control term) is implicit.
inline Row line_row(System system, const Level &L, const Stencil &s, bool along_xi) {
    Metrics m;
    const NodeEquation eq = node_equation(system, L, s, &m);  // Laplace: alpha = gamma = 1, C = 0
    const double second = along_xi ? m.alpha : m.gamma;
    const double first = 0.5 * (along_xi ? m.cxi : m.ceta);
    const double diag = -2.0 * (m.alpha + m.gamma);
    if (diag < 0.0) return Row{second - first, diag, second + first, eq.rx, eq.ry};
    return Row{0.0, -1.0, 0.0, eq.rx, eq.ry};  // all neighbours coincide (R = 0 too): stay
}

// A periodic xi-line (an O-grid's ring j) moves as a whole: its uniform mode
// is held only by 2*gamma in the line matrix, while a strong eta source
// (Ly & Norrison's 2007 eq. 14 control, mu >= 12, next to the wall) enters
// through the explicit eta-neighbours, and the ring's correction can carry
// it onto the next ring; the sweep then folds the rings one after another
// and diverges. The correction is scaled so that no node moves more than
// kRingStep of the way toward its neighbours on the rings j-1 and j+1; moves
// along the ring, and the smooth corrections of a converging iteration, are
// far smaller and are not changed. 3106e6a: Ly & Norrison's 87x31 O-grid
// then converges at mu = 12, 20, 40, 100 with every solver, and the bench's
// annulus, naca0012 and naca0012-c keep their iteration counts.
constexpr double kRingStep = 0.5;
inline double ring_step_limit(const Level &L, int j, const LineWork &w) {
    const Connectivity &conn = *L.conn;
    double scale = 1.0;
    for (int i = 0; i < conn.i_end(); ++i) {
        const Stencil s = conn.stencil(i, j);
        const double dx = w.dx[static_cast<std::size_t>(i)], dy = w.dy[static_cast<std::size_t>(i)];
        for (const std::ptrdiff_t o : {s.n, s.s}) {
            const double ex = L.x[o] - L.x[s.c], ey = L.y[o] - L.y[s.c];
            // The fraction of the way to neighbour o: (d . e) / |e|^2.
            const double toward = (dx * ex + dy * ey) * scale, room = kRingStep * (ex * ex + ey * ey);
            if (toward > room) scale *= room / toward;
        }
    }
    return scale;
}

// The stencil of an interior node k (not across the O-grid cut), computed
// directly so that row loops need no per-node topology test.
inline Stencil plain_stencil(std::ptrdiff_t k, std::ptrdiff_t ni) {
    return Stencil{k, k + 1, k - 1, k + ni, k - ni, k + ni + 1, k + ni - 1, k - ni + 1, k - ni - 1};
}

}  // namespace

void relax_xi_line(System system, const Level &L, int j, double omega, LineWork &w) {
    const Connectivity &conn = *L.conn;
    const int i0 = conn.i_begin(), i1 = conn.i_end();
    const std::size_t n = static_cast<std::size_t>(i1 - i0);
    const std::ptrdiff_t ni = conn.ni(), row = ni * j;
    w.reserve(conn.ni());
    auto put = [&](std::size_t k, const Row &r) {
        w.a[k] = r.a;
        w.b[k] = r.b;
        w.c[k] = r.c;
        w.dx[k] = -r.rx;
        w.dy[k] = -r.ry;
    };
    int first = i0;
    if (conn.periodic_i()) {  // i = 0: its west neighbour is across the cut
        put(0, line_row(system, L, conn.stencil(0, j), true));
        first = 1;
    }
    for (int i = first; i < i1; ++i)
        put(static_cast<std::size_t>(i - i0), line_row(system, L, plain_stencil(row + i, ni), true));
    if (conn.periodic_i()) {
        // Unknowns i = 0..ni-2 form a ring: the west of 0 is ni-2.
        if (!solve_cyclic_tridiagonal(n, w.a.data(), w.b.data(), w.c.data(), w.dx.data(), w.cyclic) ||
            !solve_cyclic_tridiagonal(n, w.a.data(), w.b.data(), w.c.data(), w.dy.data(), w.cyclic)) {
            w.singular = true;
            return;
        }
    } else {
        solve_tridiagonal2(n, w.a.data(), w.b.data(), w.c.data(), w.dx.data(), w.dy.data());
    }
    double *x = L.x + row + i0, *y = L.y + row + i0;
    const double step = omega * (conn.periodic_i() && w.limit_ring_steps ? ring_step_limit(L, j, w) : 1.0);
    for (std::size_t k = 0; k < n; ++k) {
        x[k] += step * w.dx[k];
        y[k] += step * w.dy[k];
    }
    conn.sync_node(L.x, 0, j);
    conn.sync_node(L.y, 0, j);
}

void relax_eta_line(System system, const Level &L, int i, double omega, LineWork &w) {
    const Connectivity &conn = *L.conn;
    const int j0 = conn.j_begin(), j1 = conn.j_end();
    const std::size_t n = static_cast<std::size_t>(j1 - j0);
    const std::ptrdiff_t ni = conn.ni();
    w.reserve(conn.nj());
    for (int j = j0; j < j1; ++j) {
        const std::size_t k = static_cast<std::size_t>(j - j0);
        const Row r = line_row(system, L, i == 0 ? conn.stencil(i, j) : plain_stencil(i + ni * j, ni), false);
        w.a[k] = r.a;
        w.b[k] = r.b;
        w.c[k] = r.c;
        w.dx[k] = -r.rx;
        w.dy[k] = -r.ry;
    }
    solve_tridiagonal2(n, w.a.data(), w.b.data(), w.c.data(), w.dx.data(), w.dy.data());
    for (std::size_t k = 0; k < n; ++k) {
        const std::ptrdiff_t at = i + ni * (j0 + static_cast<std::ptrdiff_t>(k));
        L.x[at] += omega * w.dx[k];
        L.y[at] += omega * w.dy[k];
    }
    if (i == 0)
        for (int j = j0; j < j1; ++j) {
            conn.sync_node(L.x, 0, j);
            conn.sync_node(L.y, 0, j);
        }
}

// All eta-lines of one colour (i = first, first+2, ...) solved together,
// row by row: the Thomas elimination runs across the lines with unit-stride
// memory access, where one line at a time would stride by ni. The lines of
// one colour do not couple (their neighbours are the other colour), so this
// is exactly line Gauss-Seidel in zebra order.
static void relax_eta_colour(System system, const Level &L, int first, int i1, double omega, LineWork &w) {
    const Connectivity &conn = *L.conn;
    const int j0 = conn.j_begin(), j1 = conn.j_end();
    const std::ptrdiff_t ni = conn.ni();
    const std::size_t size = static_cast<std::size_t>(ni) * conn.nj();
    if (w.grid_c.size() < size) {
        w.grid_c.resize(size);
        w.grid_dx.resize(size);
        w.grid_dy.resize(size);
    }
    double *cp = w.grid_c.data(), *dx = w.grid_dx.data(), *dy = w.grid_dy.data();
    for (int j = j0; j < j1; ++j) {
        const std::ptrdiff_t row = ni * j;
        for (int i = first; i < i1; i += 2) {
            const std::ptrdiff_t k = row + i;
            const Row r = line_row(system, L, i == 0 ? conn.stencil(i, j) : plain_stencil(k, ni), false);
            if (j == j0) {
                const double inv = 1.0 / r.b;
                cp[k] = r.c * inv;
                dx[k] = -r.rx * inv;
                dy[k] = -r.ry * inv;
            } else {
                const double inv = 1.0 / (r.b - r.a * cp[k - ni]);
                cp[k] = r.c * inv;
                dx[k] = (-r.rx - r.a * dx[k - ni]) * inv;
                dy[k] = (-r.ry - r.a * dy[k - ni]) * inv;
            }
        }
    }
    for (int j = j1 - 1; j >= j0; --j) {
        const std::ptrdiff_t row = ni * j;
        const bool last = j == j1 - 1;
        for (int i = first; i < i1; i += 2) {
            const std::ptrdiff_t k = row + i;
            if (!last) {
                dx[k] -= cp[k] * dx[k + ni];
                dy[k] -= cp[k] * dy[k + ni];
            }
            L.x[k] += omega * dx[k];
            L.y[k] += omega * dy[k];
        }
        conn.sync_node(L.x, 0, j);
        conn.sync_node(L.y, 0, j);
    }
}

// A C-grid's eta-line through the wake cut: the upper column ni-1-i from
// the far field down to row 1, the cut node (i, 0), the lower column i from
// row 1 out: one grid line of the physical plane, 2(nj-2)+1 unknowns. As two
// halves with the cut node held and relaxed pointwise after, the cut lagged:
// the cycle's slowest error was the wake nodes sliding along the cut, largest
// next to the trailing edge (measured on bench naca0012-c).
static void relax_wake_eta_line(System system, const Level &L, int i, double omega, LineWork &w) {
    const Connectivity &conn = *L.conn;
    const WakeLine line(conn, i);
    const std::size_t n = static_cast<std::size_t>(line.length());
    w.reserve(line.length());
    for (int t = 0; t < line.length(); ++t) {
        const NodeIJ p = line.at(t);
        const Row r = line_row(system, L, conn.stencil(p.i, p.j), false);
        const bool reversed = line.reversed(t);
        const std::size_t k = static_cast<std::size_t>(t);
        w.a[k] = reversed ? r.c : r.a;
        w.b[k] = r.b;
        w.c[k] = reversed ? r.a : r.c;
        w.dx[k] = -r.rx;
        w.dy[k] = -r.ry;
    }
    solve_tridiagonal2(n, w.a.data(), w.b.data(), w.c.data(), w.dx.data(), w.dy.data());
    for (int t = 0; t < line.length(); ++t) {
        const std::size_t k = line.node(t);
        L.x[k] += omega * w.dx[static_cast<std::size_t>(t)];
        L.y[k] += omega * w.dy[static_cast<std::size_t>(t)];
    }
    conn.sync_node(L.x, i, 0);
    conn.sync_node(L.y, i, 0);
}

void relax_extra_unknowns(System system, const Level &L, double omega) {
    const Connectivity &conn = *L.conn;
    for (const Connectivity::Node &p : conn.extra_unknowns()) relax_point(system, L, p.i, p.j, omega);
}

namespace {
// Calls relax(k) for k in [begin, end) in the given order.
template <class Relax>
void visit_lines(int begin, int end, LineOrder order, Relax &&relax) {
    switch (order) {
    case LineOrder::Forward:
        for (int k = begin; k < end; ++k) relax(k);
        break;
    case LineOrder::Backward:
        for (int k = end - 1; k >= begin; --k) relax(k);
        break;
    case LineOrder::Zebra:
        for (int k = begin | 1; k < end; k += 2) relax(k);
        for (int k = (begin + 1) & ~1; k < end; k += 2) relax(k);
        break;
    }
}
}  // namespace

void sweep_xi_lines(System system, const Level &L, double omega, LineWork &w, LineOrder order) {
    const Connectivity &conn = *L.conn;
    visit_lines(conn.j_begin(), conn.j_end(), order, [&](int j) { relax_xi_line(system, L, j, omega, w); });
}

void sweep_eta_lines(System system, const Level &L, double omega, LineWork &w, LineOrder order) {
    const Connectivity &conn = *L.conn;
    if (order == LineOrder::Zebra) {
        const int begin = conn.i_begin(), wake = conn.wake();
        if (wake > 0 && conn.nj() > 2) {
            // C-grid: the columns between the cut's ends in colour passes,
            // then columns 1..wake-1 of the same colour as lines through the
            // cut. Line i couples only with lines i-1, i+1 and the columns
            // next to the ends, so this stays Gauss-Seidel by lines for any
            // ni (the partner ni-1-i may have the other parity).
            for (int colour = 1; colour >= 0; --colour) {
                int first = wake;
                if ((first & 1) != colour) ++first;
                relax_eta_colour(system, L, first, conn.ni() - wake, omega, w);
                for (int i = colour ? 1 : 2; i < wake; i += 2) relax_wake_eta_line(system, L, i, omega, w);
            }
            return;
        }
        relax_eta_colour(system, L, begin | 1, conn.i_end(), omega, w);
        relax_eta_colour(system, L, (begin + 1) & ~1, conn.i_end(), omega, w);
        return;
    }
    visit_lines(conn.i_begin(), conn.i_end(), order, [&](int i) { relax_eta_line(system, L, i, omega, w); });
}

LineOmega optimal_line_sor_omega(const Connectivity &conn) {
    const double pi = 3.14159265358979323846;
    const double ci = conn.periodic_i() ? 1.0 : std::cos(pi / (conn.ni() - 1));
    const double cj = std::cos(pi / (conn.nj() - 1));
    auto omega = [](double mu) { return 2.0 / (1.0 + std::sqrt(std::max(0.0, 1.0 - mu * mu))); };
    return LineOmega{omega(cj / (2.0 - ci)), omega(ci / (2.0 - cj))};
}

}  // namespace eg2d
