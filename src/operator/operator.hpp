// The discrete operator of NUMERICS.md at one node: central differences
// (Petrilli 1989 eqs 5.1a-e), the metric coefficients alpha, beta, gamma, J and the
// control terms. Every solver and the residual use this one definition.
#pragma once
#include <cstddef>

#include "operator/control_fields.hpp"
#include "base/connectivity.hpp"
#include "operator/system.hpp"
#include "operator/variational.hpp"

namespace eg2d {

// What the operator needs of one grid level: coordinates, neighbours,
// control fields (nullptr = none) and an optional right-hand side f
// (nullptr = 0; multigrid's FAS coarse levels solve L(r) = f). The
// variational system reads its weights from `functional` (nullptr: b = 1
// alone, the spacing functional).
struct Level {
    const Connectivity *conn = nullptr;
    double *x = nullptr;
    double *y = nullptr;
    const ControlFields *controls = nullptr;
    const double *fx = nullptr;
    const double *fy = nullptr;
    const Functional *functional = nullptr;
};

// The equation at a node: R = L(r) - f for x and y, and the magnitude of the
// coefficient of r at the node itself, 2(alpha+gamma) (Laplace: 4). A point
// Jacobi/Gauss-Seidel step is r += R/diag.
struct NodeEquation {
    double rx, ry, diag;
};

// The local metric coefficients, for solvers that build line systems.
struct Metrics {
    double alpha, beta, gamma, jac2, cxi, ceta;
};

// Adds the control fields' C_xi = alpha a_xi + beta b_xi + gamma c_xi + J^2 d_xi
// (likewise C_eta) at node c into m.cxi, m.ceta, from m's metric coefficients.
inline void add_control_terms(const ControlFields &cf, std::ptrdiff_t c, Metrics &m) {
    auto add = [&](Term t, double weight, double &into) {
        if (const double *f = cf.data(t)) into += weight * f[c];
    };
    add(Term::AXi, m.alpha, m.cxi);
    add(Term::BXi, m.beta, m.cxi);
    add(Term::CXi, m.gamma, m.cxi);
    add(Term::DXi, m.jac2, m.cxi);
    add(Term::AEta, m.alpha, m.ceta);
    add(Term::BEta, m.beta, m.ceta);
    add(Term::CEta, m.gamma, m.ceta);
    add(Term::DEta, m.jac2, m.ceta);
}

inline Metrics node_metrics(const Level &L, const Stencil &s) {
    const double *x = L.x, *y = L.y;
    const double xxi = 0.5 * (x[s.e] - x[s.w]), yxi = 0.5 * (y[s.e] - y[s.w]);
    const double xeta = 0.5 * (x[s.n] - x[s.s]), yeta = 0.5 * (y[s.n] - y[s.s]);
    Metrics m;
    m.alpha = xeta * xeta + yeta * yeta;
    m.beta = xxi * xeta + yxi * yeta;
    m.gamma = xxi * xxi + yxi * yxi;
    const double jac = xxi * yeta - xeta * yxi;
    m.jac2 = jac * jac;
    m.cxi = m.ceta = 0.0;
    if (const ControlFields *cf = L.controls) add_control_terms(*cf, s.c, m);
    return m;
}

// The variational system's equation at a node (variational.cpp): L(r) =
// -(dV/dr)/2, diag = trace(H)/4; f is not applied here.
NodeEquation variational_equation(const Level &L, const Stencil &s);

// `metrics`, if given, receives the coefficients used (Laplace: alpha = gamma
// = 1, beta = C = 0), for line solvers that need both (not the variational
// system, whose equation has no such form).
// Forced inline: the sweeps call it once per node, and since the variational
// branch (a call) GCC keeps it out of line even at -O3 (ilu_sweep then pays a
// call, a Metrics through memory and no scheduling across it: swan 1025x1025
// multigrid about 20% slower; bench/RESULTS.md).
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline NodeEquation node_equation(System system, const Level &L, const Stencil &s, Metrics *metrics = nullptr) {
    if (L.conn && L.conn->fixed_node(s.c)) {  // a node of a fixed interior line: an identity row, R = 0
        if (metrics) *metrics = Metrics{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        return NodeEquation{0.0, 0.0, 1.0};
    }
    const double *x = L.x, *y = L.y;
    NodeEquation eq;
    if (system == System::Variational) {
        eq = variational_equation(L, s);
        if (metrics) *metrics = Metrics{1.0, 0.0, 1.0, 1.0, 0.0, 0.0};
    } else if (system == System::Laplace) {
        eq.rx = x[s.e] + x[s.w] + x[s.n] + x[s.s] - 4.0 * x[s.c];
        eq.ry = y[s.e] + y[s.w] + y[s.n] + y[s.s] - 4.0 * y[s.c];
        eq.diag = 4.0;
        if (metrics) *metrics = Metrics{1.0, 0.0, 1.0, 1.0, 0.0, 0.0};
    } else {
        const Metrics m = node_metrics(L, s);
        if (metrics) *metrics = m;
        const double xxixi = x[s.e] - 2.0 * x[s.c] + x[s.w], yxixi = y[s.e] - 2.0 * y[s.c] + y[s.w];
        const double xetaeta = x[s.n] - 2.0 * x[s.c] + x[s.s], yetaeta = y[s.n] - 2.0 * y[s.c] + y[s.s];
        const double xxieta = 0.25 * (x[s.ne] - x[s.se] - x[s.nw] + x[s.sw]);
        const double yxieta = 0.25 * (y[s.ne] - y[s.se] - y[s.nw] + y[s.sw]);
        eq.rx = m.alpha * xxixi - 2.0 * m.beta * xxieta + m.gamma * xetaeta;
        eq.ry = m.alpha * yxixi - 2.0 * m.beta * yxieta + m.gamma * yetaeta;
        if (m.cxi != 0.0 || m.ceta != 0.0) {
            eq.rx += 0.5 * (m.cxi * (x[s.e] - x[s.w]) + m.ceta * (x[s.n] - x[s.s]));
            eq.ry += 0.5 * (m.cxi * (y[s.e] - y[s.w]) + m.ceta * (y[s.n] - y[s.s]));
        }
        eq.diag = 2.0 * (m.alpha + m.gamma);
        if (!(eq.diag > 0.0)) eq.diag = 1.0;  // all neighbours coincide: R is 0 too
    }
    if (L.fx) {
        eq.rx -= L.fx[s.c];
        eq.ry -= L.fy[s.c];
    }
    return eq;
}

// The variational system's point step at node (i, j) (variational.cpp):
// omega times the Newton step of its 2x2 equations; under the functional's
// fold guard at most kToFold of the way to the nearest corner round the node
// turning flat (Limited: the guard shortened it); with O, halved up to
// kStepHalvings times until it lowers the node's energy (else NoDescent: the
// node stays).
enum class NodeStep { Moved, Limited, NoDescent };
constexpr double kToFold = 0.5;
constexpr int kStepHalvings = 8;
NodeStep relax_variational(const Level &L, int i, int j, double omega);

// One point Gauss-Seidel/SOR step at node (i, j): r += omega R/diag (the
// variational system: relax_variational), then the node's copies
// (conn.sync_node) follow.
inline void relax_point(System system, const Level &L, int i, int j, double omega) {
    if (system == System::Variational) {
        relax_variational(L, i, j, omega);
        return;
    }
    const Connectivity &conn = *L.conn;
    const Stencil s = conn.stencil(i, j);
    const NodeEquation eq = node_equation(system, L, s);
    L.x[s.c] += omega * eq.rx / eq.diag;
    L.y[s.c] += omega * eq.ry / eq.diag;
    conn.sync_node(L.x, i, j);
    conn.sync_node(L.y, i, j);
}

struct ResidualInfo {
    double value = 0.0;  // NUMERICS.md's residual
    int i = -1, j = -1;  // where its maximum is
};

// max over unknown nodes of max(|R_x|, |R_y|)/diag, divided by `extent` (L).
ResidualInfo residual(System system, const Level &L, double extent);

// The control terms at every unknown node as Thompson's P, Q: C_xi/J^2,
// C_eta/J^2 (0 where J = 0), each node's copies synced; P and Q (either may
// be null) hold ni*nj values and are left untouched at the other nodes.
void equivalent_sources(const Level &L, double *P, double *Q);

}  // namespace eg2d
