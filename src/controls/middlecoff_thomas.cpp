// Middlecoff-Thomas orthogonality sources (Petrilli 1989 section 4, eqs 4.7, 4.8;
// the listing's `orthog`): on the eta = const boundaries
//   phi = -(x_xi x_xixi + y_xi y_xixi) / (x_xi^2 + y_xi^2),
// on the xi = const boundaries psi likewise in eta; Phi is interpolated
// linearly in j between the two eta-boundaries, Psi linearly in i. They are
// the a_xi and c_eta terms: alpha (r_xixi + Phi r_xi) + gamma (r_etaeta + Psi r_eta).
// An O-grid has no xi = const boundary: Psi = 0 there.
// As Petrilli (1989) reports, on boundaries made only of straight segments and
// corners phi is zero except next to the corners; EG2D_ORTHO_WALL is the
// method that works there.
#include "controls/controls.hpp"

namespace eg2d {

namespace {
// -(r' . r'') / |r'|^2 at point k of a curve whose neighbours are km, kp.
double mt_source(const Grid &g, std::size_t km, std::size_t k, std::size_t kp) {
    const double xd = 0.5 * (g.x[kp] - g.x[km]), yd = 0.5 * (g.y[kp] - g.y[km]);
    const double xdd = g.x[kp] - 2.0 * g.x[k] + g.x[km], ydd = g.y[kp] - 2.0 * g.y[k] + g.y[km];
    const double d = xd * xd + yd * yd;
    return d > 0.0 ? -(xd * xdd + yd * ydd) / d : 0.0;
}

class MiddlecoffThomas final : public Control {
public:
    std::unique_ptr<Control> clone() const override { return std::make_unique<MiddlecoffThomas>(*this); }
    ControlKind kind() const override { return ControlKind::Orthogonality; }
    void add_to(const Grid &g, ControlFields &fields) const override {
        const Connectivity &conn = g.connectivity();
        const int ni = g.ni(), nj = g.nj();
        const std::size_t n = g.size();
        auto at = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
        std::vector<double> &A = fields.at(Term::AXi, n), &C = fields.at(Term::CEta, n);
        for (int i = conn.i_begin(); i < conn.i_end(); ++i) {
            const Stencil s0 = conn.stencil(i, 0);  // only e, w, c of a boundary row are used
            const double phi0 = mt_source(g, s0.w, s0.c, s0.e);
            const std::ptrdiff_t top = static_cast<std::ptrdiff_t>(ni) * (nj - 1);
            const double phi1 = mt_source(g, s0.w + top, s0.c + top, s0.e + top);
            for (int j = 1; j < nj - 1; ++j) {
                A[at(i, j)] += phi0 + (phi1 - phi0) * j / (nj - 1);
                conn.sync_node(A.data(), i, j);
            }
        }
        if (conn.periodic_i()) return;
        for (int j = 1; j < nj - 1; ++j) {
            const double psi0 = mt_source(g, at(0, j - 1), at(0, j), at(0, j + 1));
            const double psi1 = mt_source(g, at(ni - 1, j - 1), at(ni - 1, j), at(ni - 1, j + 1));
            for (int i = 1; i < ni - 1; ++i) C[at(i, j)] += psi0 + (psi1 - psi0) * i / (ni - 1);
        }
    }
};
}  // namespace

std::unique_ptr<Control> make_middlecoff_thomas() { return std::make_unique<MiddlecoffThomas>(); }

}  // namespace eg2d
