// The user's own P, Q per node (the p1/p2 arrays of Petrilli 1989): J^2 (P r_xi + Q r_eta),
// exactly the Pascal listing's jac2*(p1*xdi + p2*xdj) in `xynew`.
#include "controls/controls.hpp"

namespace eg2d {

namespace {
class SourceArrays final : public Control {
public:
    SourceArrays(std::vector<double> p, std::vector<double> q) : p_(std::move(p)), q_(std::move(q)) {}
    std::unique_ptr<Control> clone() const override { return std::make_unique<SourceArrays>(*this); }
    ControlKind kind() const override { return ControlKind::Arrays; }
    void add_to(const Grid &grid, ControlFields &fields) const override {
        const std::size_t n = grid.size();
        auto add = [&](const std::vector<double> &v, Term t) {
            if (v.empty()) return;
            std::vector<double> &f = fields.at(t, n);
            for (std::size_t k = 0; k < n; ++k) f[k] += v[k];
        };
        add(p_, Term::DXi);
        add(q_, Term::DEta);
    }

private:
    std::vector<double> p_, q_;
};
}  // namespace

std::unique_ptr<Control> make_source_arrays(std::vector<double> p, std::vector<double> q) {
    return std::make_unique<SourceArrays>(std::move(p), std::move(q));
}

}  // namespace eg2d
