// The control of the rows above a held wall layer (grid/wall_layer.hpp):
// Psi from each column's one-dimensional distribution, the layer's geometric
// growth continued to the far side, and Phi from the along-row distributions
// of the layer's last row and of JMAX, blended linearly across (Thomas &
// Middlecoff 1980's construction of the control from boundary data). Both
// depend only on held rows and boundary, so they are fixed for a run, and
// multigrid converges the solve as fast as an uncontrolled one.
//
// In NUMERICS.md's form alpha (r_xixi + Phi r_xi) - 2 beta r_xieta +
// gamma (r_etaeta + Psi r_eta) = 0, a column whose nodes t_j (arc length)
// satisfy t_etaeta + Psi t_eta = 0 at the discrete level has
//   Psi_j = -(t_{j+1} - 2 t_j + t_{j-1}) / ((t_{j+1} - t_{j-1}) / 2),
// and likewise Phi from a row's arc lengths in xi.
#include <cmath>
#include <vector>

#include "controls/controls.hpp"
#include "grid/wall_layer.hpp"

namespace eg2d {

namespace {

double dist(const Grid &g, std::size_t a, std::size_t b) { return std::hypot(g.x[b] - g.x[a], g.y[b] - g.y[a]); }

// Phi along row j: from the row's arc lengths, central (periodic on an O-grid).
std::vector<double> row_phi(const Grid &g, int j) {
    const int ni = g.ni();
    const bool ring = g.topology() == Topology::O;
    std::vector<double> phi(static_cast<std::size_t>(ni), 0.0);
    const std::size_t row = static_cast<std::size_t>(ni) * j;
    for (int i = 0; i < ni; ++i) {
        int a = i - 1, b = i + 1;
        if (ring) {
            if (a < 0) a = ni - 2;
            if (b > ni - 1) b = 1;
        } else if (a < 0 || b > ni - 1) {
            continue;
        }
        const double back = dist(g, row + a, row + i), ahead = dist(g, row + i, row + b);
        if (back + ahead > 0.0) phi[static_cast<std::size_t>(i)] = -2.0 * (ahead - back) / (ahead + back);
    }
    return phi;
}

}  // namespace

void add_wall_layer_fields(const Grid &g, double growth, ControlFields &fields) {
    const int ni = g.ni(), nj = g.nj(), rows = g.held_rows();
    if (rows <= 0) return;
    std::vector<double> &psi = fields.at(Term::CEta, g.size());
    std::vector<double> &phi = fields.at(Term::AXi, g.size());
    const std::vector<double> phi_low = row_phi(g, rows), phi_high = row_phi(g, nj - 1);
    auto at = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
    const int m = nj - 1 - rows;
    std::vector<double> t(static_cast<std::size_t>(m) + 1);
    for (int i = 0; i < ni; ++i) {
        const double last = dist(g, at(i, rows - 1), at(i, rows)), length = dist(g, at(i, rows), at(i, nj - 1));
        const double first = last * growth, r = geometric_ratio(first, length, m);
        t[0] = 0.0;
        double cell = first;
        for (int k = 1; k <= m; ++k, cell *= r) t[static_cast<std::size_t>(k)] = t[static_cast<std::size_t>(k - 1)] + cell;
        for (int k = 1; k < m; ++k) {
            const double tm = t[static_cast<std::size_t>(k - 1)], t0 = t[static_cast<std::size_t>(k)],
                         tp = t[static_cast<std::size_t>(k + 1)];
            const double f = t0 / t[static_cast<std::size_t>(m)];
            psi[at(i, rows + k)] += -(tp - 2.0 * t0 + tm) / (0.5 * (tp - tm));
            phi[at(i, rows + k)] += (1.0 - f) * phi_low[static_cast<std::size_t>(i)] + f * phi_high[static_cast<std::size_t>(i)];
        }
    }
}

}  // namespace eg2d
