// Line relaxation: the kernel of line SOR and of the multigrid smoother.
// A line's unknowns are solved together, with the line's own couplings
// implicit and everything else taken from the current grid (Gauss-Seidel
// across lines). The system is in correction form: at each node of the line
//   a d[k-1] + b d[k] + c d[k+1] = -R   (R = L(r) - f of operator.hpp)
// with, on a xi-line,  a = alpha - C_xi/2, b = -2(alpha+gamma), c = alpha + C_xi/2
// and on an eta-line  a = gamma - C_eta/2, b = -2(alpha+gamma), c = gamma + C_eta/2
// (Laplace: 1, -4, 1), the coefficients frozen at the current grid (Picard).
// The grid moves by omega*d. On an O-grid a xi-line is periodic and solved
// as a cyclic system (Sherman-Morrison; Ly & Norrison 2007), so the cut moves with it.
#pragma once
#include <vector>

#include "base/grid.hpp"
#include "operator/operator.hpp"
#include "operator/system.hpp"

namespace eg2d {

// Scratch for one line; sized once (reserve) so sweeps never allocate.
struct LineWork {
    std::vector<double> a, b, c, dx, dy, cyclic;
    std::vector<double> grid_c, grid_dx, grid_dy;  // zebra eta sweeps: all lines of a colour at once
    // Scale an O-grid ring's correction so that no node moves more than half
    // way to the next ring (line_relax.cpp, ring_step_limit). Off while the
    // wall control is updated between iterations: its ramp moves the first
    // rings by about their spacing per iteration, and limiting that slowed
    // it 3x (test_controls_wall); the wall layer's redesign will revisit it.
    bool limit_ring_steps = true;
    // An O-grid ring's system was singular to rounding (solve_cyclic_tridiagonal):
    // the ring was left where it was; multigrid drops such a coarse level.
    bool singular = false;
    void reserve(int n);
};

void relax_xi_line(System system, const Level &L, int j, double omega, LineWork &w);
void relax_eta_line(System system, const Level &L, int i, double omega, LineWork &w);
// A point update of every node in conn.extra_unknowns() (the C-grid cut).
void relax_extra_unknowns(System system, const Level &L, double omega);

// A C-grid's eta line through wake node (i, 0), 1 <= i < conn.wake(): the
// upper column ni-1-i from row nj-2 down to row 1, the cut node (i, 0), the
// lower column i from row 1 to row nj-2: one grid line of the physical
// plane, 2(nj-2)+1 nodes. On the upper half eta runs against the line (north
// is the previous node, south the next), so a row's a and c swap there. AF's
// eta factor and line relaxation both solve the wake's eta lines this way.
struct WakeLine {
    WakeLine(const Connectivity &conn, int column) : ni(conn.ni()), half(conn.nj() - 2), i(column) {}
    int length() const { return 2 * half + 1; }
    bool reversed(int t) const { return t < half; }
    NodeIJ at(int t) const { return t < half ? NodeIJ{ni - 1 - i, half - t} : NodeIJ{i, t - half}; }
    std::size_t node(int t) const {
        const NodeIJ p = at(t);
        return static_cast<std::size_t>(p.i) + static_cast<std::size_t>(ni) * static_cast<std::size_t>(p.j);
    }
    int ni, half, i;
};

// The order in which a sweep visits its lines. Zebra (odd lines, then even)
// smooths better than lexicographic order when the coupling along the lines
// is strong (stretched cells): for the anisotropic model problem its
// smoothing factor stays below 1/4 where lexicographic order tends to 1/sqrt(5).
enum class LineOrder { Forward, Backward, Zebra };

// All xi-lines (over j), likewise all eta-lines (over i), in the given order.
void sweep_xi_lines(System system, const Level &L, double omega, LineWork &w,
                    LineOrder order = LineOrder::Forward);
void sweep_eta_lines(System system, const Level &L, double omega, LineWork &w,
                     LineOrder order = LineOrder::Forward);

// Automatic line-SOR factors: the optimum 2/(1 + sqrt(1 - mu^2)) for the
// Laplace model problem on the grid's size, where mu is the line-Jacobi
// spectral radius: for xi-lines mu = cos(pi/(nj-1)) / (2 - cos(pi/(ni-1)))
// (on the periodic direction the constant mode makes that cosine 1).
struct LineOmega {
    double xi, eta;
};
LineOmega optimal_line_sor_omega(const Connectivity &conn);

}  // namespace eg2d
