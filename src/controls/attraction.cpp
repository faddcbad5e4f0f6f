// Thompson's attraction to lines and points (NUMERICS.md "Source terms"):
//   P = -sum_l a_l sign(xi - xi_l) exp(-c_l |xi - xi_l|)
//       -sum_k b_k sign(xi - xi_k) exp(-d_k sqrt((xi-xi_k)^2 + (eta-eta_k)^2)),
// Q likewise in eta. Ly & Norrison (2007) eq 14 is the eta-line part with mu = a, kappa = c.
// P and Q enter as J^2 (P r_xi + Q r_eta): the d_xi, d_eta terms.
#include <cmath>

#include "controls/controls.hpp"

namespace eg2d {

namespace {
double sign(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }
}  // namespace

void AttractionControl::add_to(const Grid &grid, ControlFields &fields) const {
    const int ni = grid.ni(), nj = grid.nj();
    const std::size_t n = grid.size();
    const Connectivity &conn = grid.connectivity();
    const double period = conn.periodic_i() ? conn.i_period() : 0.0;
    // On an O-grid xi is periodic: the distance to a line or point is the
    // shorter way round, so sources near the cut act on both sides of it.
    auto dxi = [&](double a, double b) {
        double d = a - b;
        if (period > 0.0) d -= period * std::round(d / period);
        return d;
    };
    std::vector<double> &P = fields.at(Term::DXi, n), &Q = fields.at(Term::DEta, n);
    for (int j = 0; j < nj; ++j)
        for (int i = 0; i < ni; ++i) {
            const std::size_t k = static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j;
            double p = 0.0, q = 0.0;
            for (const LineSource &l : lines) {
                const double d = l.direction == 0 ? dxi(i, l.line) : j - l.line;
                const double v = -l.amplitude * sign(d) * std::exp(-l.decay * std::fabs(d));
                (l.direction == 0 ? p : q) += v;
            }
            for (const PointSource &s : points) {
                const double a = dxi(i, s.xi), b = j - s.eta;
                const double e = std::exp(-s.decay * std::sqrt(a * a + b * b));
                p -= s.amplitude * sign(a) * e;
                q -= s.amplitude * sign(b) * e;
            }
            P[k] += p;
            Q[k] += q;
        }
}

}  // namespace eg2d
