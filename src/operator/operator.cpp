#include "operator/operator.hpp"

#include <algorithm>
#include <cmath>

#include "eg2d.h"

namespace eg2d {

namespace {
const NamedId kSystems[] = {
    {EG2D_SYSTEM_LAPLACE, "laplace", "Laplace"},
    {EG2D_SYSTEM_WINSLOW, "winslow", "Winslow"},
    {EG2D_SYSTEM_VARIATIONAL, "variational", "variational"},
};
}  // namespace

Table<NamedId> system_table() { return table_of(kSystems); }

const char *system_name(System s) { return title_of(system_table(), static_cast<int>(s)); }

ResidualInfo residual(System system, const Level &L, double extent) {
    const Connectivity &conn = *L.conn;
    ResidualInfo r;
    double worst = 0.0;
    bool nan = false;
    auto visit = [&](int i, int j) {
        const NodeEquation eq = node_equation(system, L, conn.stencil(i, j));
        const double v = std::max(std::fabs(eq.rx), std::fabs(eq.ry)) / eq.diag;
        if (std::isnan(v) && !nan) {  // the first NaN decides: report it, not a number
            nan = true;
            worst = v;
            r.i = i;
            r.j = j;
        } else if (!nan && v > worst) {
            worst = v;
            r.i = i;
            r.j = j;
        }
    };
    for (int j = conn.j_begin(); j < conn.j_end(); ++j)
        for (int i = conn.i_begin(); i < conn.i_end(); ++i) visit(i, j);
    for (const Connectivity::Node &n : conn.extra_unknowns()) visit(n.i, n.j);
    r.value = extent > 0.0 ? worst / extent : worst;
    return r;
}

void equivalent_sources(const Level &L, double *P, double *Q) {
    const Connectivity &conn = *L.conn;
    auto visit = [&](int i, int j) {
        const Stencil s = conn.stencil(i, j);
        const Metrics m = node_metrics(L, s);
        const bool singular = !(m.jac2 > 0.0);
        if (P) {
            P[s.c] = singular ? 0.0 : m.cxi / m.jac2;
            conn.sync_node(P, i, j);
        }
        if (Q) {
            Q[s.c] = singular ? 0.0 : m.ceta / m.jac2;
            conn.sync_node(Q, i, j);
        }
    };
    for (int j = conn.j_begin(); j < conn.j_end(); ++j)
        for (int i = conn.i_begin(); i < conn.i_end(); ++i) visit(i, j);
    for (const Connectivity::Node &n : conn.extra_unknowns()) visit(n.i, n.j);
}

}  // namespace eg2d
