// Approximate factorisation with false transients (seed 004 eqs 5-13).
//
// A pseudo-time derivative is added to NUMERICS.md's equation,
// r_tau = L(r), and discretised with Warming and Beam's rule (eq 6, a, b).
// The implicit operator is factored into a xi and an eta operator, dropping
// the mixed derivative (eq 10), and the two factors are inverted one after
// the other (eqs 11-13):
//
//   [1 - dt (alpha d_xixi  + C_xi  d_xi )] dr* = a~ (r^n - r^(n-1)) + dt (omega/b) R^n
//   [1 - dt (gamma d_etaeta + C_eta d_eta)] dr  = dr*,        r^(n+1) = r^n + dr
//
// with a~ = a/(1+a) (eq 8) and the coefficients frozen at r^n (lagged, as in
// the seed). The step dt is taken node by node as tau / (2(alpha+gamma))
// (Laplace: tau/4), so tau is dimensionless and the same cycle fits every
// grid scale; tau runs through the cycle of af_cycle() (seed 004: geometric
// with repeated end points). The xi factor is cyclic on an O-grid (solved by
// Sherman-Morrison), so the branch cut moves implicitly with the interior
// (seed 004 figure 2). One iteration = one step = the two line sweeps.
#include <algorithm>
#include <cmath>
#include <vector>

#include "solvers/solver.hpp"
#include "solvers/tridiagonal.hpp"

namespace eg2d {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Automatic cycle: the largest step resolves the smoothest mode of the longest
// grid line (its eigenvalue is about (pi/n)^2 in units of the diagonal); the
// steps grow by at most this ratio. Measured on the seed 003 domains, the
// annulus and an 87x31 O-grid (bench --seed004): ratio 2 beats 3 and 4 on the
// skewed dome (141 vs 237 vs 357 iterations at 65^2) and ties elsewhere; the
// steps ascend through the cycle because large steps first diverge from a TFI
// start on the dome (Winslow's lagged coefficients).
constexpr double kStepRatio = 2.0;

// The steps tau of one cycle for an ni x nj grid, automatic values filled in.
std::vector<double> af_cycle(const Settings &st, int ni, int nj) {
    const double n = std::max(ni, nj) - 1.0;
    const double tmin = st.af_dtau_min;
    const double tmax = st.af_dtau_max > 0.0 ? st.af_dtau_max : std::max(tmin, 4.0 * n * n / (kPi * kPi));
    int steps = static_cast<int>(st.af_steps);
    if (steps <= 0) {
        const int distinct = tmax > tmin ? static_cast<int>(std::ceil(std::log(tmax / tmin) / std::log(kStepRatio))) + 1 : 1;
        steps = std::max(distinct, 2) + 2;
    }
    const int distinct = steps - 2;  // the end points are repeated
    std::vector<double> cycle;
    cycle.reserve(static_cast<std::size_t>(steps));
    cycle.push_back(tmin);
    for (int k = 0; k < distinct; ++k)
        cycle.push_back(distinct > 1 ? tmin * std::pow(tmax / tmin, static_cast<double>(k) / (distinct - 1)) : tmin);
    cycle.push_back(cycle.back());
    return cycle;
}

// Automatic omega = 2b: the right-hand side of eq 7 then carries 2 dt R, the
// Peaceman-Rachford choice, whatever the time rule.
double af_relaxation(const Settings &st) { return st.af_relaxation > 0.0 ? st.af_relaxation : 2.0 * st.af_b; }

class ApproximateFactorisation final : public Solver {
public:
    void reset() override {
        step_ = 0;
        prev_x_.clear();
        prev_y_.clear();
    }

    void iterate(Problem &p) override {
        const Level L = p.level();
        const Connectivity &conn = *L.conn;
        const int ni = conn.ni(), nj = conn.nj();
        const std::size_t size = static_cast<std::size_t>(ni) * nj;
        const std::vector<double> cycle = af_cycle(p.settings, ni, nj);
        const double tau = cycle[static_cast<std::size_t>(step_) % cycle.size()];
        const double a = p.settings.af_a, b = p.settings.af_b;
        const double a_tilde = a / (1.0 + a), gain = af_relaxation(p.settings) / b;
        const bool three_level = a_tilde != 0.0 && prev_x_.size() == size;

        dx_.assign(size, 0.0);
        dy_.assign(size, 0.0);
        lo_.assign(size, 0.0);
        di_.assign(size, 1.0);
        up_.assign(size, 0.0);

        // The xi factor, line by line (eq 11); the eta coefficients are kept for eq 12.
        const int ib = conn.i_begin(), ie = conn.i_end(), n = ie - ib;
        row_lo_.resize(n); row_di_.resize(n); row_up_.resize(n); row_c_.resize(n);
        for (int j = conn.j_begin(); j < conn.j_end(); ++j) {
            for (int i = ib; i < ie; ++i) {
                const Stencil s = conn.stencil(i, j);
                Metrics m;
                const NodeEquation eq = node_equation(p.system, L, s, &m);
                const double alpha = m.alpha, gamma = m.gamma, cxi = m.cxi, ceta = m.ceta;
                const double dt = tau / eq.diag;
                const int r = i - ib;
                row_lo_[r] = -dt * (alpha - 0.5 * cxi);
                row_di_[r] = 1.0 + 2.0 * dt * alpha;
                row_up_[r] = -dt * (alpha + 0.5 * cxi);
                lo_[s.c] = -dt * (gamma - 0.5 * ceta);
                di_[s.c] = 1.0 + 2.0 * dt * gamma;
                up_[s.c] = -dt * (gamma + 0.5 * ceta);
                dx_[s.c] = dt * gain * eq.rx;
                dy_[s.c] = dt * gain * eq.ry;
                if (three_level) {
                    dx_[s.c] += a_tilde * prev_x_[s.c];
                    dy_[s.c] += a_tilde * prev_y_[s.c];
                }
            }
            double *rx = dx_.data() + static_cast<std::size_t>(ni) * j + ib;
            double *ry = dy_.data() + static_cast<std::size_t>(ni) * j + ib;
            solve_row(conn.periodic_i(), n, rx);
            solve_row(conn.periodic_i(), n, ry);
        }

        // The eta factor (eq 12): all columns at once, row after row, so
        // memory is walked in storage order (Thomas algorithm in place).
        const int jb = conn.j_begin(), je = conn.j_end();
        for (int j = jb; j < je; ++j) {
            const std::size_t row = static_cast<std::size_t>(ni) * j;
            for (int i = ib; i < ie; ++i) {
                const std::size_t k = row + i;
                double m = di_[k];
                if (j > jb) {
                    const std::size_t below = k - ni;
                    m -= lo_[k] * up_[below];
                    dx_[k] -= lo_[k] * dx_[below];
                    dy_[k] -= lo_[k] * dy_[below];
                }
                up_[k] /= m;
                dx_[k] /= m;
                dy_[k] /= m;
            }
        }
        for (int j = je - 2; j >= jb; --j) {
            const std::size_t row = static_cast<std::size_t>(ni) * j;
            for (int i = ib; i < ie; ++i) {
                const std::size_t k = row + i;
                dx_[k] -= up_[k] * dx_[k + ni];
                dy_[k] -= up_[k] * dy_[k + ni];
            }
        }

        // eq 13, and the cut column follows column 0.
        for (int j = jb; j < je; ++j)
            for (int i = ib; i < ie; ++i) {
                const std::size_t k = static_cast<std::size_t>(ni) * j + i;
                L.x[k] += dx_[k];
                L.y[k] += dy_[k];
                conn.sync_node(L.x, i, j);
                conn.sync_node(L.y, i, j);
            }
        // Unknowns off the rectangle (a C-grid's cut) take a point step.
        for (const Connectivity::Node &nd : conn.extra_unknowns()) {
            const Stencil s = conn.stencil(nd.i, nd.j);
            const NodeEquation eq = node_equation(p.system, L, s);
            L.x[s.c] += eq.rx / eq.diag;
            L.y[s.c] += eq.ry / eq.diag;
        }
        if (a_tilde != 0.0) {
            prev_x_.swap(dx_);
            prev_y_.swap(dy_);
        }
        ++step_;
    }

private:
    // Solves the xi factor of one row for one right-hand side (in place).
    void solve_row(bool periodic, int n, double *rhs) {
        if (!periodic) {
            std::copy(row_up_.begin(), row_up_.end(), row_c_.begin());
            solve_tridiagonal(n, row_lo_.data(), row_di_.data(), row_c_.data(), rhs);
        } else {  // an O-grid has ni >= 4: at least three distinct columns
            solve_cyclic_tridiagonal(n, row_lo_.data(), row_di_.data(), row_up_.data(), rhs, work_);
        }
    }

    long step_ = 0;
    std::vector<double> prev_x_, prev_y_;      // r^n - r^(n-1), for a != 0
    std::vector<double> dx_, dy_, lo_, di_, up_;  // corrections and the eta factor
    std::vector<double> row_lo_, row_di_, row_up_, row_c_, work_;
};

}  // namespace

std::unique_ptr<Solver> make_af() { return std::make_unique<ApproximateFactorisation>(); }

}  // namespace eg2d
