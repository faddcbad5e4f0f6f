// Point SOR: a lexicographic Gauss-Seidel sweep over the unknown nodes with
// over-relaxation (seed 003; seed 001 Code 1.2 is the omega = 1 case). The
// coefficients are frozen at each node's current neighbours (Picard).
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
    auto relax = [&](int i, int j) {
        const Stencil s = conn.stencil(i, j);
        const NodeEquation eq = node_equation(system, L, s);
        L.x[s.c] += omega * eq.rx / eq.diag;
        L.y[s.c] += omega * eq.ry / eq.diag;
        conn.sync_node(L.x, i, j);
        conn.sync_node(L.y, i, j);
    };
    for (int j = conn.j_begin(); j < conn.j_end(); ++j)
        for (int i = conn.i_begin(); i < conn.i_end(); ++i) relax(i, j);
    for (const Connectivity::Node &n : conn.extra_unknowns()) relax(n.i, n.j);
}

namespace {

class PointSor final : public Solver {
public:
    void iterate(Problem &p) override {
        const Level L = p.level();
        sor_sweep(p.system, L, relaxation_.omega(p.settings, p.system, L.conn->ni(), L.conn->nj()));
    }
    void observe(double residual) override { relaxation_.observe(residual); }
    void reset() override { relaxation_.reset(); }

private:
    AutoRelaxation relaxation_;
};

}  // namespace

std::unique_ptr<Solver> make_psor() { return std::make_unique<PointSor>(); }

}  // namespace eg2d
