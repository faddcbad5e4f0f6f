// Weight-function control (the grid-generation lecture notes: "P and Q specified from a weight
// function ... used in adaptive methods"). Larger w = denser grid: along each
// index direction the spacing equidistributes w, w ds = const, whose
// one-dimensional form (w r_xi)_xi = 0 is r_xixi + (w_xi / w) r_xi = 0. We
// discretise w_xi / w so that the discrete 1-D solution is exact with
// midpoint weights w_{i+1/2} = (w_i + w_{i+1}) / 2:
//   Phi = 2 (w_e - w_w) / (w_w + 2 w_c + w_e),   Psi likewise in eta,
// which also keeps |Phi| < 2 (the central differences stay monotone) for
// any positive w. Phi, Psi are the a_xi, c_eta terms (NUMERICS.md).
#include "controls/controls.hpp"

#include <algorithm>

namespace eg2d {

namespace {
// 2 (b - a) / (a + 2c + b) with a, b, c divided by the largest of them first:
// the same ratio, but weights near DBL_MAX no longer overflow the sum to Inf
// (a NaN control then, found by fuzz_api); the denominator stays >= 1.
double weight_ratio(double a, double c, double b) {
    const double m = std::max(a, std::max(b, c));
    a /= m;
    b /= m;
    c /= m;
    return 2.0 * (b - a) / (a + 2.0 * c + b);
}

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
                A[s.c] += weight_ratio(w[s.w], w[s.c], w[s.e]);
                C[s.c] += weight_ratio(w[s.s], w[s.c], w[s.n]);
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
