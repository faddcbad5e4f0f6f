// Approximate factorisation with false transients (Ly & Norrison 2007 eqs 5-13).
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
// Ly & Norrison 2007). The step dt is one number for the whole grid, as in eq 10:
// tau / D with D the geometric mean over the unknowns of 2(alpha+gamma)
// (Laplace: 4), so tau is dimensionless and the same cycle fits every grid
// scale. (A step per node, tau / (2(alpha+gamma)), folds the NACA0012 O-grid
// from a TFI start: the small wall cells, where Winslow's grid moves farthest
// from the TFI grid relative to its spacing, then take as large a step in
// index space as the far field, the lagged coefficients there are far off,
// and the first cycle's large steps push row 1 through the wall at the
// leading and trailing edges. The same steps on the coefficients frozen at the
// start converge: the failure is the lagging, not the factorisation. With one
// dt each node moves at the rate of the true transient, slowly where its cells
// are small.) tau runs through the cycle of af_cycle() (Ly & Norrison 2007: geometric
// with repeated end points). The xi factor is cyclic on an O-grid (solved by
// Sherman-Morrison), so the branch cut moves implicitly with the interior
// (Ly & Norrison 2007 figure 2); a C-grid's wake cut is likewise implicit: the cut is a
// xi line of its own and each eta line runs through it from the lower half
// into the upper (relaxed point by point instead, the cut took 195, 362 and
// 1561 steps on the NACA0012 C-grid at 65, 129, 257 points around; solved
// with the lines, 91, 172 and 421). One iteration = one step = the two line sweeps.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "solvers/line_relax.hpp"
#include "solvers/solver.hpp"
#include "base/tridiagonal.hpp"

namespace eg2d {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Automatic cycle: the largest step resolves the smoothest mode of the longest
// grid line (its eigenvalue is about (pi/n)^2 in units of the diagonal); the
// steps grow by at most this ratio. Measured on the elliptic-grid course notes domains, the
// annulus and an 87x31 O-grid (bench --ogrid), with a step per node: ratio
// 2 beats 3 and 4 on the skewed dome (141 vs 237 vs 357 iterations at 65^2)
// and ties elsewhere; the steps ascend through the cycle because large steps
// first diverge from a TFI start on the dome (Winslow's lagged coefficients).
constexpr double kStepRatio = 2.0;

// The automatic largest step is divided by kTopShrink whenever the residual
// rises kRiseFactor times above its best.
// Large steps with lagged coefficients can be unstable: Petrilli's (1989) channel 3
// with wall orthogonality (a control that follows the grid) diverged at step
// 169. The residual of a healthy cycle rises up to ~20x during its largest
// steps (NACA0012 C-grid 257x65), so 10x shrank the cycle needlessly (the
// C-grid then stalled); 100x leaves the test cases' counts as they were.
constexpr double kTopShrink = 4.0, kRiseFactor = 100.0;

// The steps tau of one cycle for an ni x nj grid, automatic values filled in;
// `top` scales the automatic largest step.
std::vector<double> af_cycle(const Settings &st, int ni, int nj, double top) {
    const double n = std::max(ni, nj) - 1.0;
    const double tmin = st.af_dtau_min;
    const double tmax = st.af_dtau_max > 0.0 ? st.af_dtau_max : std::max(tmin, top * 4.0 * n * n / (kPi * kPi));
    // In logarithms: tmax / tmin overflows for a tmin near the least double,
    // which the parameter's range (0, 1e12] allows.
    const double span = std::log(tmax) - std::log(tmin);
    int steps = static_cast<int>(st.af_steps);
    if (steps <= 0) {
        const int distinct = tmax > tmin ? static_cast<int>(std::ceil(span / std::log(kStepRatio))) + 1 : 1;
        steps = std::max(distinct, 2) + 2;
    }
    const int distinct = steps - 2;  // the end points are repeated
    std::vector<double> cycle;
    cycle.reserve(static_cast<std::size_t>(steps));
    cycle.push_back(tmin);
    for (int k = 0; k < distinct; ++k)
        cycle.push_back(distinct > 1 ? std::exp(std::log(tmin) + span * k / (distinct - 1)) : tmin);
    cycle.push_back(cycle.back());
    return cycle;
}

// Automatic omega = 2b: the right-hand side of eq 7 then carries 2 dt R, the
// Peaceman-Rachford choice, whatever the time rule.
double af_relaxation(const Settings &st) { return st.af_relaxation > 0.0 ? st.af_relaxation : 2.0 * st.af_b; }

class ApproximateFactorisation final : public Solver {
public:
    bool marches_in_time() const override { return true; }
    void observe(double residual, double /*control_gap*/) override {
        if (!(residual == residual)) return;  // NaN: the run loop handles divergence
        if (residual > kRiseFactor * best_) {
            top_ /= kTopShrink;
            best_ = residual;
            step_ = 0;  // the new cycle from its smallest step
        } else if (residual < best_) {
            best_ = residual;
        }
    }

    void reset() override {
        step_ = 0;
        top_ = 1.0;
        best_ = std::numeric_limits<double>::infinity();
        scale_ = 0.0;
        prev_x_.clear();
        prev_y_.clear();
    }

    void iterate(Problem &p) override {
        const Level L = p.level();
        const Connectivity &conn = *L.conn;
        const int ni = conn.ni(), nj = conn.nj();
        const std::size_t size = static_cast<std::size_t>(ni) * nj;
        const std::vector<double> cycle = af_cycle(p.settings, ni, nj, top_);
        const double tau = cycle[static_cast<std::size_t>(step_) % cycle.size()];
        const double a = p.settings.af_a, b = p.settings.af_b;
        Step st;
        st.a_tilde = a / (1.0 + a);
        st.gain = af_relaxation(p.settings) / b;
        st.three_level = st.a_tilde != 0.0 && prev_x_.size() == size;

        dx_.assign(size, 0.0);
        dy_.assign(size, 0.0);
        lo_.assign(size, 0.0);
        di_.assign(size, 1.0);
        up_.assign(size, 0.0);
        if (!(scale_ > 0.0)) scale_ = diagonal_scale(p.system, L);
        st.dt = tau / scale_;

        const double log_sum = xi_factor(p.system, L, st);
        eta_factor(conn);
        apply(L);
        // The next step's scale, from this step's diagonals: one pass over the nodes, not two.
        const int n = conn.i_end() - conn.i_begin();
        scale_ = std::exp(log_sum / (static_cast<double>(n) * (conn.j_end() - conn.j_begin())));
        if (st.a_tilde != 0.0) {
            prev_x_.swap(dx_);
            prev_y_.swap(dy_);
        }
        ++step_;
    }

private:
    // One step's numbers: dt = tau / D, omega/b, a~ and whether r^n - r^(n-1) is known.
    struct Step {
        double dt = 0.0, gain = 0.0, a_tilde = 0.0;
        bool three_level = false;
    };

    // Node (i, j) as entry r of its xi line (row_*); its eta coefficients
    // (lo_, di_, up_) and right-hand side (dx_, dy_) in place. Returns the
    // node's diagonal 2(alpha+gamma).
    double assemble(System system, const Level &L, const Step &st, int i, int j, int r) {
        const Stencil s = L.conn->stencil(i, j);
        const double dt = st.dt;
        Metrics m;
        const NodeEquation eq = node_equation(system, L, s, &m);
        const double alpha = m.alpha, gamma = m.gamma, cxi = m.cxi, ceta = m.ceta;
        row_lo_[r] = -dt * (alpha - 0.5 * cxi);
        row_di_[r] = 1.0 + 2.0 * dt * alpha;
        row_up_[r] = -dt * (alpha + 0.5 * cxi);
        lo_[s.c] = -dt * (gamma - 0.5 * ceta);
        di_[s.c] = 1.0 + 2.0 * dt * gamma;
        up_[s.c] = -dt * (gamma + 0.5 * ceta);
        dx_[s.c] = dt * st.gain * eq.rx;
        dy_[s.c] = dt * st.gain * eq.ry;
        if (st.three_level) {
            dx_[s.c] += st.a_tilde * prev_x_[s.c];
            dy_[s.c] += st.a_tilde * prev_y_[s.c];
        }
        return eq.diag;
    }

    // The xi factor, line by line (eq 11); the eta coefficients are kept for
    // eq 12. Returns the sum of log(diagonal) over the unknowns.
    double xi_factor(System system, const Level &L, const Step &st) {
        const Connectivity &conn = *L.conn;
        const int ni = conn.ni(), ib = conn.i_begin(), ie = conn.i_end(), n = ie - ib;
        row_lo_.resize(n); row_di_.resize(n); row_up_.resize(n); row_c_.resize(n);
        double log_sum = 0.0;
        for (int j = conn.j_begin(); j < conn.j_end(); ++j) {
            for (int i = ib; i < ie; ++i) log_sum += std::log(assemble(system, L, st, i, j, i - ib));
            double *rx = dx_.data() + static_cast<std::size_t>(ni) * j + ib;
            double *ry = dy_.data() + static_cast<std::size_t>(ni) * j + ib;
            solve_row(conn.periodic_i(), n, rx);
            solve_row(conn.periodic_i(), n, ry);
        }
        // A C-grid's wake cut is a xi line too, between the outflow and the
        // trailing edge (both fixed): its nodes are solved with the interior,
        // as Ly & Norrison (2007) does with the O-grid's branch cut, not relaxed after it.
        const int wake = conn.wake();  // 0 unless a C-grid
        if (wake > 1) {
            for (int i = 1; i < wake; ++i) assemble(system, L, st, i, 0, i - 1);
            solve_row(false, wake - 1, dx_.data() + 1);
            solve_row(false, wake - 1, dy_.data() + 1);
        }
        return log_sum;
    }

    // The eta factor (eq 12): all columns at once, row after row, so memory
    // is walked in storage order (Thomas algorithm in place). The C-grid's
    // wake columns i and ni-1-i are one eta line through the cut
    // (solve_wake_line); the others run from row 1 to row nj-2.
    void eta_factor(const Connectivity &conn) {
        const int ni = conn.ni(), wake = conn.wake();
        const int jb = conn.j_begin(), je = conn.j_end();
        const int i0 = wake > 1 ? wake : conn.i_begin(), i1 = wake > 1 ? ni - wake : conn.i_end();
        for (int j = jb; j < je; ++j) {
            const std::size_t row = static_cast<std::size_t>(ni) * j;
            for (int i = i0; i < i1; ++i) {
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
            for (int i = i0; i < i1; ++i) {
                const std::size_t k = row + i;
                dx_[k] -= up_[k] * dx_[k + ni];
                dy_[k] -= up_[k] * dy_[k + ni];
            }
        }
        for (int i = 1; i < wake; ++i) solve_wake_line(conn, i);
    }

    // eq 13, and the cut column follows column 0; then the wake cut's nodes
    // and their copies on the upper wake.
    void apply(const Level &L) const {
        const Connectivity &conn = *L.conn;
        const int ni = conn.ni();
        auto move = [&](int i, int j) {
            const std::size_t k = static_cast<std::size_t>(ni) * j + i;
            L.x[k] += dx_[k];
            L.y[k] += dy_[k];
            conn.sync_node(L.x, i, j);
            conn.sync_node(L.y, i, j);
        };
        for (int j = conn.j_begin(); j < conn.j_end(); ++j)
            for (int i = conn.i_begin(); i < conn.i_end(); ++i) move(i, j);
        for (const Connectivity::Node &nd : conn.extra_unknowns()) move(nd.i, nd.j);
    }

    // The eta factor on the C-grid's line through wake node (i, 0)
    // (WakeLine, line_relax.hpp: up the upper column, through the cut node,
    // out along the lower column).
    void solve_wake_line(const Connectivity &conn, int i) {
        const WakeLine line(conn, i);
        const int len = line.length();
        line_k_.resize(len);
        line_a_.resize(len); line_b_.resize(len); line_c_.resize(len);
        line_x_.resize(len); line_y_.resize(len);
        for (int t = 0; t < len; ++t) {
            const bool upper = line.reversed(t);
            const std::size_t k = line.node(t);
            line_k_[t] = k;
            line_a_[t] = upper ? up_[k] : lo_[k];
            line_b_[t] = di_[k];
            line_c_[t] = upper ? lo_[k] : up_[k];
            line_x_[t] = dx_[k];
            line_y_[t] = dy_[k];
        }
        line_s_.assign(line_c_.begin(), line_c_.end());
        solve_tridiagonal(len, line_a_.data(), line_b_.data(), line_s_.data(), line_x_.data());
        line_s_.assign(line_c_.begin(), line_c_.end());
        solve_tridiagonal(len, line_a_.data(), line_b_.data(), line_s_.data(), line_y_.data());
        for (int t = 0; t < len; ++t) {
            dx_[line_k_[t]] = line_x_[t];
            dy_[line_k_[t]] = line_y_[t];
        }
    }

    // Solves the xi factor of one row for one right-hand side (in place).
    void solve_row(bool periodic, int n, double *rhs) {
        if (!periodic) {
            std::copy(row_up_.begin(), row_up_.end(), row_c_.begin());
            solve_tridiagonal(n, row_lo_.data(), row_di_.data(), row_c_.data(), rhs);
        } else {  // an O-grid has ni >= 4: at least three distinct columns
            solve_cyclic_tridiagonal(n, row_lo_.data(), row_di_.data(), row_up_.data(), rhs, work_);
        }
    }

    // D of the step dt = tau / D: the geometric mean over the unknowns of
    // 2(alpha+gamma) (the scale of L's diagonal, insensitive to the few
    // largest cells), from the previous step's coefficients (0: not known).
    static double diagonal_scale(System system, const Level &L) {
        const Connectivity &conn = *L.conn;
        double log_sum = 0.0;
        for (int j = conn.j_begin(); j < conn.j_end(); ++j)
            for (int i = conn.i_begin(); i < conn.i_end(); ++i)
                log_sum += std::log(node_equation(system, L, conn.stencil(i, j)).diag);
        const double count = static_cast<double>(conn.i_end() - conn.i_begin()) * (conn.j_end() - conn.j_begin());
        return std::exp(log_sum / count);
    }

    long step_ = 0;
    double scale_ = 0.0;
    double top_ = 1.0;  // scales the automatic dtau_max (observe)
    double best_ = std::numeric_limits<double>::infinity();
    std::vector<double> prev_x_, prev_y_;      // r^n - r^(n-1), for a != 0
    std::vector<double> dx_, dy_, lo_, di_, up_;  // corrections and the eta factor
    std::vector<double> row_lo_, row_di_, row_up_, row_c_, work_;
    std::vector<double> line_a_, line_b_, line_c_, line_s_, line_x_, line_y_;  // a C-grid's wake line
    std::vector<std::size_t> line_k_;
};

}  // namespace

std::unique_ptr<Solver> make_af() { return std::make_unique<ApproximateFactorisation>(); }

}  // namespace eg2d
