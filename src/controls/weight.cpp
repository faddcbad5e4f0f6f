// Weight-function control (seed 001: "P and Q specified from a weight
// function ... used in adaptive methods"). Larger w = denser grid: along each
// index direction the spacing equidistributes w, w ds = const, whose
// one-dimensional form (w r_xi)_xi = 0 is r_xixi + (w_xi / w) r_xi = 0. We
// discretise w_xi / w so that the discrete 1-D solution is exact with
// midpoint weights w_{i+1/2} = (w_i + w_{i+1}) / 2:
//   Phi = 2 (w_e - w_w) / (w_w + 2 w_c + w_e),   Psi likewise in eta,
// which also keeps |Phi| < 2 (the central differences stay monotone) for
// any positive w. Phi, Psi are the a_xi, c_eta terms (NUMERICS.md).
#include "controls/controls.hpp"

namespace eg2d {

namespace {
class WeightControl final : public Control {
public:
    explicit WeightControl(std::vector<double> w) : w_(std::move(w)) {}
    std::unique_ptr<Control> clone() const override { return std::make_unique<WeightControl>(*this); }
    ControlKind kind() const override { return ControlKind::Weight; }
    void add_to(const Grid &g, ControlFields &fields) const override {
        const Connectivity &conn = g.connectivity();
        const std::size_t n = g.size();
        std::vector<double> &A = fields.at(Term::AXi, n), &C = fields.at(Term::CEta, n);
        const double *w = w_.data();
        for (int j = conn.j_begin(); j < conn.j_end(); ++j)
            for (int i = conn.i_begin(); i < conn.i_end(); ++i) {
                const Stencil s = conn.stencil(i, j);
                A[s.c] += 2.0 * (w[s.e] - w[s.w]) / (w[s.w] + 2.0 * w[s.c] + w[s.e]);
                C[s.c] += 2.0 * (w[s.n] - w[s.s]) / (w[s.s] + 2.0 * w[s.c] + w[s.n]);
                conn.sync_node(A.data(), i, j);
                conn.sync_node(C.data(), i, j);
            }
    }

private:
    std::vector<double> w_;
};
}  // namespace

std::unique_ptr<Control> make_weight_control(std::vector<double> w) {
    return std::make_unique<WeightControl>(std::move(w));
}

}  // namespace eg2d
