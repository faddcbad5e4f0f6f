// The variational system's node equations and its point Newton step
// (variational.hpp). Everything is written relative to the node itself
// (edge vectors), so a domain far from the origin loses no digits.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "operator/operator.hpp"
#include "operator/smoothness_cell.hpp"

namespace eg2d {

namespace {

// The node's neighbours round it: the four edge ends e, n, w, s (the fifth
// repeats e) and the four cell corners opposite the node, ne, nw, sw, se.
// Cell k round the node is (node, q[k], d[k], q[k+1]), counter-clockwise in
// index space like every cell's own order (i,j), (i+1,j), (i+1,j+1), (i,j+1).
struct Ring {
    double ex[5], ey[5];  // q[k] - node
    double fx[4], fy[4];  // d[k] - node
};

Ring ring(const double *x, const double *y, const Stencil &s) {
    const std::ptrdiff_t q[4] = {s.e, s.n, s.w, s.s}, d[4] = {s.ne, s.nw, s.sw, s.se};
    const double px = x[s.c], py = y[s.c];
    Ring r;
    for (int k = 0; k < 4; ++k) {
        r.ex[k] = x[q[k]] - px;
        r.ey[k] = y[q[k]] - py;
        r.fx[k] = x[d[k]] - px;
        r.fy[k] = y[d[k]] - py;
    }
    r.ex[4] = r.ex[0];
    r.ey[4] = r.ey[0];
    return r;
}

// dV/dr at the node, the Gauss-Newton part of the node's Hessian block (sum
// of 2 w g g^T over the squared terms, and 8b I from S), which is the exact
// block of S and A (linear in the node), and O's second-order rest (the
// exact block is h + o).
struct NodeGradient {
    double gx = 0.0, gy = 0.0, hxx = 0.0, hxy = 0.0, hyy = 0.0;
    double oxx = 0.0, oxy = 0.0, oyy = 0.0;
    void add(double w, double value, double dx, double dy) {  // w value^2 with d value/dr = (dx, dy)
        gx += 2.0 * w * value * dx;
        gy += 2.0 * w * value * dy;
        hxx += 2.0 * w * dx * dx;
        hxy += 2.0 * w * dx * dy;
        hyy += 2.0 * w * dy * dy;
    }
    // w dot^2 with the derivatives of dot in the node: dot is linear in it
    // except at the node's own corner, whose dot has the second derivative
    // 2 I (`own`), which adds 4 w dot I to the exact block.
    void add_dot(double w, double dot, double ddx, double ddy, bool own) {
        add(w, dot, ddx, ddy);
        if (own) {
            oxx += 4.0 * w * dot;
            oyy += 4.0 * w * dot;
        }
    }
};

// Cell k round the node, (node, q[k], d[k], q[k+1]), with the node moved by
// (dx, dy), in coordinates relative to the node's old place.
void ring_cell(const Ring &r, int k, double dx, double dy, double x[4], double y[4]) {
    x[0] = dx, y[0] = dy;
    x[1] = r.ex[k], y[1] = r.ey[k];
    x[2] = r.fx[k], y[2] = r.fy[k];
    x[3] = r.ex[k + 1], y[3] = r.ey[k + 1];
}

// The corner terms (W and O's cotangent form, not quadratic in the node:
// smoothness_cell.hpp) from the four cells round it: their convex block into
// h, and with `exact` the rest into o (the node's equation reads g and h only).
void add_corners(const Functional &F, const Ring &r, bool exact, NodeGradient &g) {
    double x[4], y[4];
    for (int k = 0; k < 4; ++k) {
        ring_cell(r, k, 0.0, 0.0, x, y);
        const NodeTerms t = corner_node_terms(F, x, y, exact);
        g.gx += t.g[0];
        g.gy += t.g[1];
        g.hxx += t.hc[0][0];
        g.hxy += t.hc[0][1];
        g.hyy += t.hc[1][1];
        if (!exact) continue;
        g.oxx += t.h[0][0] - t.hc[0][0];
        g.oxy += t.h[0][1] - t.hc[0][1];
        g.oyy += t.h[1][1] - t.hc[1][1];
    }
}

// With `exact` false the corner terms' o is left out (their exact block
// costs most, and the node equation reads g, hxx and hyy only).
NodeGradient node_gradient(const Functional &F, const Ring &r, bool exact = true) {
    NodeGradient g;
    if (has_corner_terms(F)) add_corners(F, r, exact, g);
    const double b2 = 2.0 * F.spacing;  // S: sum over the four edges of |q - r|^2
    g.gx -= b2 * (r.ex[0] + r.ex[1] + r.ex[2] + r.ex[3]);
    g.gy -= b2 * (r.ey[0] + r.ey[1] + r.ey[2] + r.ey[3]);
    g.hxx += 4.0 * b2;
    g.hyy += 4.0 * b2;
    const double wa = F.area, wc = F.orthogonality;
    if (wa == 0.0 && wc == 0.0) return g;
    for (int k = 0; k < 4; ++k) {
        const double e1x = r.ex[k], e1y = r.ey[k], e3x = r.ex[k + 1], e3y = r.ey[k + 1], fx = r.fx[k], fy = r.fy[k];
        if (wa != 0.0) {
            // area = (p2 - p0) x (p3 - p1) / 2, linear in p0.
            const double area = 0.5 * (fx * (e3y - e1y) - fy * (e3x - e1x));
            g.add(wa, area, 0.5 * (e1y - e3y), 0.5 * (e3x - e1x));
        }
        if (wc != 0.0) {
            // The corner at the node, (p1 - p0).(p3 - p0), and at its two
            // neighbours on the cell, (p2 - p1).(p0 - p1) and (p0 - p3).(p2 - p3).
            const double f1x = fx - e1x, f1y = fy - e1y, f3x = fx - e3x, f3y = fy - e3y;
            g.add_dot(wc, e1x * e3x + e1y * e3y, -(e1x + e3x), -(e1y + e3y), true);
            g.add_dot(wc, -(f1x * e1x + f1y * e1y), f1x, f1y, false);
            g.add_dot(wc, -(f3x * e3x + f3y * e3y), f3x, f3y, false);
        }
    }
    return g;
}

// How far the node may move along (dx, dy) before a corner round it turns
// flat: the corners at the node and at its edge neighbours of the four cells
// round it (the fourth corner of each cell does not move) have cross
// products linear in the move, t(s) = t + s t'. The smallest s > 0 at which
// one that turns with `orientation` comes down to kFlat times its edges'
// squared lengths (a sine of 1e-12: below it round-off decides the sign),
// or 0 for one already below that; infinity if none. A corner already
// folded sets no limit.
double step_limit(const Ring &r, double dx, double dy, int orientation) {
    constexpr double kFlat = 1e-12;
    double limit = std::numeric_limits<double>::infinity();
    auto corner = [&](double t, double slope, double ax, double ay, double bx, double by) {
        if (t * orientation < 0.0 || slope * orientation >= 0.0) return;
        const double flat = kFlat * (ax * ax + ay * ay + bx * bx + by * by);
        limit = std::min(limit, std::max(0.0, (std::fabs(t) - flat) / std::fabs(slope)));
    };
    for (int k = 0; k < 4; ++k) {
        const double e1x = r.ex[k], e1y = r.ey[k], e3x = r.ex[k + 1], e3y = r.ey[k + 1];
        const double f1x = r.fx[k] - e1x, f1y = r.fy[k] - e1y, f3x = r.fx[k] - e3x, f3y = r.fy[k] - e3y;
        corner(e1x * e3y - e1y * e3x, -((e1x - e3x) * dy - (e1y - e3y) * dx), e1x, e1y, e3x, e3y);  // at the node
        corner(e1x * f1y - e1y * f1x, -(dx * f1y - dy * f1x), e1x, e1y, f1x, f1y);                    // at q[k]
        corner(f3x * e3y - f3y * e3x, -(f3x * dy - f3y * dx), e3x, e3y, f3x, f3y);                    // at q[k+1]
    }
    return limit;
}

// The terms of V that move with the node, with the node moved by (dx, dy):
// its four edges, the areas of the four cells round it and their corners at
// the node and at its edge neighbours.
double node_energy(const Functional &F, const Ring &r, double dx, double dy) {
    double spacing = 0.0, area = 0.0, ortho = 0.0;
    auto sq = [](double v) { return v * v; };
    for (int k = 0; k < 4; ++k) {
        const double e1x = r.ex[k] - dx, e1y = r.ey[k] - dy, e3x = r.ex[k + 1] - dx, e3y = r.ey[k + 1] - dy;
        const double fx = r.fx[k] - dx, fy = r.fy[k] - dy;
        spacing += e1x * e1x + e1y * e1y;
        if (F.area != 0.0) {
            const double a = 0.5 * (fx * (e3y - e1y) - fy * (e3x - e1x));
            area += a * a;
        }
        if (F.orthogonality != 0.0) {
            const double f1x = fx - e1x, f1y = fy - e1y, f3x = fx - e3x, f3y = fy - e3y;
            ortho += sq(e1x * e3x + e1y * e3y) + sq(f1x * e1x + f1y * e1y) + sq(f3x * e3x + f3y * e3y);
        }
    }
    double smooth = 0.0;
    if (has_corner_terms(F)) {
        double x[4], y[4];
        for (int k = 0; k < 4; ++k) {
            ring_cell(r, k, dx, dy, x, y);
            smooth += corner_terms_value(F, x, y);
        }
    }
    return F.spacing * spacing + F.area * area + F.orthogonality * ortho + smooth;
}

}  // namespace

NodeEquation variational_equation(const Level &L, const Stencil &s) {
    static const Functional kSpacingOnly;
    const NodeGradient g = node_gradient(L.functional ? *L.functional : kSpacingOnly, ring(L.x, L.y, s), false);
    NodeEquation eq{-0.5 * g.gx, -0.5 * g.gy, 0.25 * (g.hxx + g.hyy)};
    if (!(eq.diag > 0.0)) eq.diag = 1.0;  // no term depends on the node: R is 0 too
    return eq;
}

NodeStep relax_variational(const Level &L, int i, int j, double omega) {
    static const Functional kSpacingOnly;
    const Functional &F = L.functional ? *L.functional : kSpacingOnly;
    const Connectivity &conn = *L.conn;
    if (conn.fixed(i, j)) return NodeStep::Moved;  // a fixed interior line's node: Dirichlet
    const Stencil s = conn.stencil(i, j);
    const Ring r = ring(L.x, L.y, s);
    const NodeGradient g = node_gradient(F, r);
    double rx = -0.5 * g.gx, ry = -0.5 * g.gy, fx = 0.0, fy = 0.0;
    if (L.fx) {
        fx = L.fx[s.c];
        fy = L.fy[s.c];
        rx -= fx;
        ry -= fy;
    }
    // Newton on R = 0, dR/dr = -H/2: the step is 2 H^-1 R, with the exact
    // block where it is positive definite, else its Gauss-Newton part.
    double hxx = g.hxx + g.oxx, hyy = g.hyy + g.oyy, hxy = g.hxy + g.oxy;
    if (!(hxx > 0.0 && hxx * hyy - hxy * hxy > 0.0)) {
        hxx = g.hxx;
        hyy = g.hyy;
        hxy = g.hxy;
    }
    const double det = hxx * hyy - hxy * hxy, trace = hxx + hyy;
    double dx, dy;
    if (det > 1e-12 * trace * trace) {
        dx = 2.0 * (hyy * rx - hxy * ry) / det;
        dy = 2.0 * (hxx * ry - hxy * rx) / det;
    } else {  // a singular block (b = 0 on a degenerate neighbourhood): a Jacobi step
        const double diag = trace > 0.0 ? 0.25 * trace : 1.0;
        dx = rx / diag;
        dy = ry / diag;
    }
    dx *= omega;
    dy *= omega;
    // Under the fold guard the step goes at most kToFold of the way to the
    // nearest corner turning flat (linear in the step: step_limit), so no
    // step folds a cell; then it is halved until it lowers the node's
    // energy, V + 2 f.r (R = 0 is its stationary point). S and A alone are
    // quadratic in the node, and any part of the Newton step lowers it.
    NodeStep result = NodeStep::Moved;
    if (F.orientation != 0) {
        const double limit = kToFold * step_limit(r, dx, dy, F.orientation);
        if (limit < 1.0) {
            dx *= limit;
            dy *= limit;
            result = NodeStep::Limited;
        }
    }
    if (F.orthogonality != 0.0 || has_corner_terms(F)) {
        const double e0 = node_energy(F, r, 0.0, 0.0);
        for (int halvings = 0; !(node_energy(F, r, dx, dy) + 2.0 * (fx * dx + fy * dy) <= e0); ++halvings) {
            if (halvings == kStepHalvings) return NodeStep::NoDescent;
            dx *= 0.5;
            dy *= 0.5;
        }
    }
    L.x[s.c] += dx;
    L.y[s.c] += dy;
    conn.sync_node(L.x, i, j);
    conn.sync_node(L.y, i, j);
    return result;
}

}  // namespace eg2d
