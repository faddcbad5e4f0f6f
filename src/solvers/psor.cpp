// Point SOR: a lexicographic Gauss-Seidel sweep over the unknown nodes with
// over-relaxation (the elliptic-grid course notes; Code 1.2 of the
// grid-generation lecture notes is the omega = 1 case). The coefficients
// are frozen at each node's current neighbours (Picard).
#include <cmath>

#include "solvers/auto_relaxation.hpp"
#include "solvers/solver.hpp"

namespace eg2d {

double optimal_sor_omega(int n1, int n2) {
    const double pi = 3.14159265358979323846;
    const double c = std::cos(pi / n1) + std::cos(pi / n2);
    return 4.0 / (2.0 + std::sqrt(4.0 - c * c));
}

void sor_sweep(System system, const Level &L, double omega) {
    const Connectivity &conn = *L.conn;
    auto relax = [&](int i, int j) { relax_point(system, L, i, j, omega); };
    for (int j = conn.j_begin(); j < conn.j_end(); ++j)
        for (int i = conn.i_begin(); i < conn.i_end(); ++i) relax(i, j);
    for (const Connectivity::Node &n : conn.extra_unknowns()) relax(n.i, n.j);
}

namespace {

class PointSor final : public Solver {
public:
    void iterate(Problem &p) override {
        const Level L = p.level();
        if (p.settings.relaxation > 0.0) return sor_sweep(p.system, L, p.settings.relaxation);
        // The automatic factor aims at the elliptic-grid course notes' optimum. Winslow's frozen
        // coefficients do not bear it from a TFI start (fixed 1.97 diverges
        // on the valley 257^2 and the NACA0012 O- and C-grids at 129 and 257;
        // the old rule, a start at the optimum of a grid half as fine, 1.988,
        // diverged on the valley 1025^2), but the ramp reaches it safely: no
        // back-off on any bench case up to 513, 1058 sweeps on the valley
        // 257^2 where the best fixed factor (1.95) needs 1534. Laplace is
        // linear (SOR converges for any omega in (0, 2)): no ramp.
        const double target = optimal_sor_omega(L.conn->ni(), L.conn->nj());
        const long ramp = p.system == System::Laplace ? 0 : AutoRelaxation::ramp_for(target);
        relaxation_.sweep(L, ramp, [&] { sor_sweep(p.system, L, relaxation_.omega(target)); });
    }
    void reset() override { relaxation_.reset(); }

private:
    AutoRelaxation relaxation_;
};

}  // namespace

std::unique_ptr<Solver> make_psor() { return std::make_unique<PointSor>(); }

}  // namespace eg2d
