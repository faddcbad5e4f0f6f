// Adaptive control from a parameter-space grid (Khattri 2006 eqs 3-7, Table 1):
// the physical grid is made to inherit the distribution of a grid (s, t) on
// the unit square. With T = [s_xi s_eta; t_xi t_eta],
//   P11 = -T^-1 (s_xixi, t_xixi),  P12 = -T^-1 (s_xieta, t_xieta),
//   P22 = -T^-1 (s_etaeta, t_etaeta),
//   C_xi = alpha P11^1 - 2 beta P12^1 + gamma P22^1, C_eta likewise with ^2,
// i.e. a_xi = P11^1, b_xi = -2 P12^1, c_xi = P22^1 and the same for eta
// (Khattri 2006 writes g22, g12, g11 for alpha, beta, gamma; its eq 7 has typos and
// its listing computes g12 as a product: these are the equations, derived so
// that r = (s, t) solves the system when the physical domain is the square).
// Differences are in index units. On an O-grid s runs once round: across the
// cut s jumps by s(ni-1, j) - s(0, j), which is added back.
#include <cmath>

#include "controls/controls.hpp"

namespace eg2d {

namespace {
struct Local {
    double s[9], t[9];  // c, e, w, n, s, ne, nw, se, sw
};

Local gather(const Connectivity &conn, const double *s, const double *t, int i, int j) {
    const Stencil st = conn.stencil(i, j);
    const std::ptrdiff_t idx[9] = {st.c, st.e, st.w, st.n, st.s, st.ne, st.nw, st.se, st.sw};
    Local L;
    for (int k = 0; k < 9; ++k) {
        L.s[k] = s[idx[k]];
        L.t[k] = t[idx[k]];
    }
    if (conn.periodic_i()) {
        const int ni = conn.ni();
        const double jump[3] = {s[static_cast<std::ptrdiff_t>(ni) * (j - 1) + ni - 1] - s[static_cast<std::ptrdiff_t>(ni) * (j - 1)],
                                s[static_cast<std::ptrdiff_t>(ni) * j + ni - 1] - s[static_cast<std::ptrdiff_t>(ni) * j],
                                s[static_cast<std::ptrdiff_t>(ni) * (j + 1) + ni - 1] - s[static_cast<std::ptrdiff_t>(ni) * (j + 1)]};
        if (i == 0) {  // west neighbours are across the cut, one period back
            L.s[2] -= jump[1];
            L.s[6] -= jump[2];
            L.s[8] -= jump[0];
        }
        if (i == ni - 2) {  // east neighbours are column 1, one period on
            L.s[1] += jump[1];
            L.s[5] += jump[2];
            L.s[7] += jump[0];
        }
    }
    return L;
}

double jacobian(const Local &L) {
    return 0.25 * ((L.s[1] - L.s[2]) * (L.t[3] - L.t[4]) - (L.s[3] - L.s[4]) * (L.t[1] - L.t[2]));
}

class ParameterGrid final : public Control {
public:
    ParameterGrid(std::vector<double> s, std::vector<double> t) : s_(std::move(s)), t_(std::move(t)) {}
    std::unique_ptr<Control> clone() const override { return std::make_unique<ParameterGrid>(*this); }
    ControlKind kind() const override { return ControlKind::ParameterGrid; }
    void add_to(const Grid &g, ControlFields &fields) const override {
        const Connectivity &conn = g.connectivity();
        const std::size_t n = g.size();
        std::vector<double> *f[6] = {&fields.at(Term::AXi, n),  &fields.at(Term::BXi, n),
                                     &fields.at(Term::CXi, n),  &fields.at(Term::AEta, n),
                                     &fields.at(Term::BEta, n), &fields.at(Term::CEta, n)};
        for (int j = conn.j_begin(); j < conn.j_end(); ++j)
            for (int i = conn.i_begin(); i < conn.i_end(); ++i) {
                const Local L = gather(conn, s_.data(), t_.data(), i, j);
                const double sx = 0.5 * (L.s[1] - L.s[2]), se = 0.5 * (L.s[3] - L.s[4]);
                const double tx = 0.5 * (L.t[1] - L.t[2]), te = 0.5 * (L.t[3] - L.t[4]);
                const double det = sx * te - se * tx;
                if (det == 0.0) continue;  // refused by the API for the topology it was set on
                const double sxx = L.s[1] - 2.0 * L.s[0] + L.s[2], txx = L.t[1] - 2.0 * L.t[0] + L.t[2];
                const double see = L.s[3] - 2.0 * L.s[0] + L.s[4], tee = L.t[3] - 2.0 * L.t[0] + L.t[4];
                const double sxe = 0.25 * (L.s[5] - L.s[7] - L.s[6] + L.s[8]);
                const double txe = 0.25 * (L.t[5] - L.t[7] - L.t[6] + L.t[8]);
                // -T^-1 (a, b) with T^-1 = [te -se; -tx sx] / det.
                auto solve = [&](double a, double b, double &p1, double &p2) {
                    p1 = -(te * a - se * b) / det;
                    p2 = -(-tx * a + sx * b) / det;
                };
                double p11[2], p12[2], p22[2];
                solve(sxx, txx, p11[0], p11[1]);
                solve(sxe, txe, p12[0], p12[1]);
                solve(see, tee, p22[0], p22[1]);
                const std::ptrdiff_t c = conn.stencil(i, j).c;
                const double v[6] = {p11[0], -2.0 * p12[0], p22[0], p11[1], -2.0 * p12[1], p22[1]};
                for (int k = 0; k < 6; ++k) {
                    (*f[k])[c] += v[k];
                    conn.sync_node(f[k]->data(), i, j);
                }
            }
    }

private:
    std::vector<double> s_, t_;
};
}  // namespace

ParameterFold parameter_grid_fold(const Connectivity &conn, const double *s, const double *t) {
    ParameterFold f;
    double first = 0.0;
    for (int j = conn.j_begin(); j < conn.j_end(); ++j)
        for (int i = conn.i_begin(); i < conn.i_end(); ++i) {
            const double d = jacobian(gather(conn, s, t, i, j));
            if (first == 0.0) first = d;
            if (!(d * first > 0.0)) {
                f.i = i;
                f.j = j;
                return f;
            }
        }
    return f;
}

std::unique_ptr<Control> make_parameter_grid(std::vector<double> s, std::vector<double> t) {
    return std::make_unique<ParameterGrid>(std::move(s), std::move(t));
}

}  // namespace eg2d
