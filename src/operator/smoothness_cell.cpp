// The smoothness term's share of one cell (smoothness_cell.hpp), in each
// corner's z = (u_x, u_y, v_x, v_y): S = |u|^2 + |v|^2, X = u x v, F = S/X.
#include "operator/smoothness_cell.hpp"

#include <initializer_list>
#include <limits>

namespace eg2d {

namespace {

// H (8 x 8, the cell's coordinates) += the corner's h (4 x 4 in z = (u, v),
// u = r_n - r_m, v = r_p - r_m): blocks uu, uv, vu, vv at (n, n), (n, p),
// (p, n), (p, p), their negated row and column sums at m's row and column.
void scatter(const double h[4][4], int n, int p, int m, double H[8][8]) {
    const int node[2] = {n, p};
    double row[2][2][2] = {}, all[2][2] = {};  // row[a]: sum over b of block (a, b); all: sum of the four
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c)
                for (int d = 0; d < 2; ++d) {
                    const double v = h[2 * a + c][2 * b + d];
                    H[2 * node[a] + c][2 * node[b] + d] += v;
                    row[a][c][d] += v;
                    all[c][d] += v;
                }
    for (int a = 0; a < 2; ++a)
        for (int c = 0; c < 2; ++c)
            for (int d = 0; d < 2; ++d) {
                H[2 * node[a] + c][2 * m + d] -= row[a][c][d];  // (a, m): -sum over b of (a, b)
                H[2 * m + d][2 * node[a] + c] -= row[a][c][d];  // symmetric
            }
    for (int c = 0; c < 2; ++c)
        for (int d = 0; d < 2; ++d) H[2 * m + c][2 * m + d] += all[c][d];
}

// Corner m of a cell: its neighbours n (next) and p (previous), z = (u, v),
// u = r_n - r_m, v = r_p - r_m, and X = u x v.
struct Corner {
    int m, n, p;
    double z[4], X;
};

// Corner m of the cell (x, y); false, with `value` made infinite, where
// u x v <= 0 (flat or folded: outside both terms' domain).
bool corner_at(const double x[4], const double y[4], int m, Corner &c, double &value) {
    c.m = m;
    c.n = (m + 1) % 4;
    c.p = (m + 3) % 4;
    c.z[0] = x[c.n] - x[m], c.z[1] = y[c.n] - y[m], c.z[2] = x[c.p] - x[m], c.z[3] = y[c.p] - y[m];
    c.X = c.z[0] * c.z[3] - c.z[1] * c.z[2];
    if (c.X > 0.0) return true;
    value = std::numeric_limits<double>::infinity();
    return false;
}

// body(corner) for each corner of the cell (x, y) with u x v > 0.
template <class Body>
void for_each_corner(const double x[4], const double y[4], CellTerms &t, Body body) {
    for (int m = 0; m < 4; ++m) {
        Corner c;
        if (corner_at(x, y, m, c, t.value)) body(c);
    }
}

// t.g += the gradient g4 in the corner's z, in the cell's coordinates.
void add_gradient(const Corner &c, const double g4[4], CellTerms &t) {
    const int at[4] = {2 * c.n, 2 * c.n + 1, 2 * c.p, 2 * c.p + 1};
    for (int k = 0; k < 4; ++k) {
        t.g[at[k]] += g4[k];
        t.g[2 * c.m + k % 2] -= g4[k];
    }
}

// How much of a corner's share to compute: value and gradient, and the
// convex Hessian, and the exact one (the expensive part: the residual's
// node equations read the convex block only).
enum class Parts { Gradient, Convex, Both };

// One corner's share in its own z: value, gradient g4 and, as `parts` says,
// the convex and the exact Hessians c4, h4 (4 x 4). Computed once a corner and
// used both for the cell's 8 x 8 terms and for a node's 2 x 2 block (the
// residual's node equations need no more: NodeTerms).
struct CornerParts {
    double value, g4[4], h4[4][4], c4[4][4];
};

// Both kernels take 1/X once and fill the upper triangles only (the
// Hessians are symmetric): a division per corner, not one per entry.
void cotangent_corner(double w, const Corner &cr, Parts parts, CornerParts &o) {
    const double *z = cr.z, iX = 1.0 / cr.X;
    // F = p^2/X^2 = q^2, q = p/X the cotangent.
    const double p = z[0] * z[2] + z[1] * z[3], q = p * iX, w2 = 2.0 * w;
    o.value = w * q * q;
    const double gp[4] = {z[2], z[3], z[0], z[1]}, gX[4] = {z[3], -z[2], -z[1], z[0]};
    double gq[4];
    for (int k = 0; k < 4; ++k) {
        gq[k] = (gp[k] - q * gX[k]) * iX;
        o.g4[k] = w2 * q * gq[k];
    }
    if (parts == Parts::Gradient) return;
    // Exact: 2 gq gq^T + 2 q hess q, hess q = (hess p - gq gX^T - gX gq^T - q hess X)/X;
    // convex: 2 gq gq^T (exact at right angles, q = 0). hess p is 1 at
    // (0,2), (1,3); hess X 1 at (0,3), -1 at (1,2) (upper triangle).
    for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b) o.c4[a][b] = o.c4[b][a] = w2 * gq[a] * gq[b];
    if (parts != Parts::Both) return;
    const double r = w2 * q * iX;
    for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b) {
            double hq = -(gq[a] * gX[b] + gX[a] * gq[b]);
            if (b == a + 2) hq += 1.0;
            if (a + b == 3) hq -= (a == 0 ? 1.0 : -1.0) * q;
            o.h4[a][b] = o.h4[b][a] = o.c4[a][b] + r * hq;
        }
}

void smoothness_corner(double w, const Corner &cr, Parts parts, CornerParts &o) {
    const double *z = cr.z, iX = 1.0 / cr.X, iX2 = iX * iX;
    const double S = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] + z[3] * z[3];
    o.value = w * S * iX;
    const double gX[4] = {z[3], -z[2], -z[1], z[0]};
    for (int k = 0; k < 4; ++k) o.g4[k] = w * (2.0 * z[k] * iX - S * gX[k] * iX2);
    if (parts == Parts::Gradient) return;
    // Exact: 2I/X - (grad S gX^T + gX grad S^T)/X^2 + 2S gX gX^T/X^3 - (S/X^2) hess X,
    // hess X = 1 at (0,3), (3,0) and -1 at (1,2), (2,1).
    const double e[2] = {(z[0] - z[3]) * iX, (z[1] + z[2]) * iX};  // e/X
    const double ge[2][4] = {{1, 0, 0, -1}, {0, 1, 1, 0}};
    double c[2][4];
    for (int q = 0; q < 2; ++q)
        for (int k = 0; k < 4; ++k) c[q][k] = ge[q][k] - e[q] * gX[k];
    const double wc = 2.0 * w * iX;
    for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b) o.c4[a][b] = o.c4[b][a] = wc * (c[0][a] * c[0][b] + c[1][a] * c[1][b]);
    if (parts != Parts::Both) return;
    const double d = 2.0 * w * iX, m = 2.0 * w * iX2, t = 2.0 * w * S * iX2 * iX, k = w * S * iX2;
    for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b) {
            double h = -m * (z[a] * gX[b] + gX[a] * z[b]) + t * gX[a] * gX[b];
            if (a == b) h += d;
            if (a + b == 3) h -= (a == 0 ? 1.0 : -1.0) * k;
            o.h4[a][b] = o.h4[b][a] = h;
        }
}

using CornerFn = void (*)(double, const Corner &, Parts, CornerParts &);

// A mirrored corner's parts (x -> -x) back in (x, y): the x-components of
// z (0 and 2) change the sign of the gradient's and of every Hessian entry
// with one x index.
void mirror(CornerParts &o, bool hessians) {
    o.g4[0] = -o.g4[0], o.g4[2] = -o.g4[2];
    if (!hessians) return;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            if ((a + b) % 2) o.h4[a][b] = -o.h4[a][b], o.c4[a][b] = -o.c4[a][b];
}

// w times corner_fn's term summed over the cell's corners, into t; the
// corner's parts are mirrored back (sense s = -1: x -> -x) before they are
// scattered, so nothing is summed twice.
void add_cell_terms(CornerFn corner_fn, double w, double s, const double x[4], const double y[4], bool hessians,
                    CellTerms &t) {
    for_each_corner(x, y, t, [&](const Corner &cr) {
        CornerParts o;
        corner_fn(w, cr, hessians ? Parts::Both : Parts::Gradient, o);
        t.value += o.value;
        if (s < 0.0) mirror(o, hessians);
        add_gradient(cr, o.g4, t);
        if (!hessians) return;
        scatter(o.h4, cr.n, cr.p, cr.m, t.h);
        scatter(o.c4, cr.n, cr.p, cr.m, t.hc);
    });
}

// The same, but only what lands on the cell's corner 0: its gradient and
// its 2 x 2 blocks, summed exactly as add_gradient and scatter sum them
// (the same round-off), the exact blocks only with `exact`. Corner 2 does
// not move with corner 0.
void add_node_terms(CornerFn corner_fn, double w, const double x[4], const double y[4], bool exact, NodeTerms &t) {
    double sink = 0.0;  // corner_at's infinite value on a flat corner: not wanted here
    for (int m : {0, 1, 3}) {
        Corner cr;
        if (!corner_at(x, y, m, cr, sink)) continue;
        CornerParts o;
        corner_fn(w, cr, exact ? Parts::Both : Parts::Convex, o);
        // Corner 0 is this corner's m (m = 0), its p (m = 1) or its n (m = 3).
        const int at = m == 1 ? 2 : 0;
        if (m == 0) {
            t.g[0] -= o.g4[0], t.g[1] -= o.g4[1];
            t.g[0] -= o.g4[2], t.g[1] -= o.g4[3];
        } else {
            t.g[0] += o.g4[at], t.g[1] += o.g4[at + 1];
        }
        for (int c = 0; c < 2; ++c)
            for (int d = 0; d < 2; ++d) {
                if (m != 0) {
                    if (exact) t.h[c][d] += o.h4[at + c][at + d];
                    t.hc[c][d] += o.c4[at + c][at + d];
                    continue;
                }
                double h = 0.0, hc = 0.0;  // scatter's `all`: the four blocks in its order
                for (int a = 0; a < 2; ++a)
                    for (int b = 0; b < 2; ++b) {
                        if (exact) h += o.h4[2 * a + c][2 * b + d];
                        hc += o.c4[2 * a + c][2 * b + d];
                    }
                t.h[c][d] += h;
                t.hc[c][d] += hc;
            }
    }
}

// value += w times corner_fn's value at each of the cell's corners, in
// add_cell_terms's order (the same round-off); infinite on a flat or folded one.
void add_cell_value(CornerFn corner_fn, double w, const double x[4], const double y[4], double &value) {
    for (int m = 0; m < 4; ++m) {
        Corner cr;
        if (!corner_at(x, y, m, cr, value)) return;  // infinite: the rest adds nothing
        CornerParts o;
        corner_fn(w, cr, Parts::Gradient, o);
        value += o.value;
    }
}

}  // namespace

void add_cotangent_terms(double w, const double x[4], const double y[4], bool hessians, CellTerms &t) {
    add_cell_terms(cotangent_corner, w, 1.0, x, y, hessians, t);
}

void add_smoothness_terms(double w, const double x[4], const double y[4], bool hessians, CellTerms &t) {
    add_cell_terms(smoothness_corner, w, 1.0, x, y, hessians, t);
}

void add_corner_terms(const Functional &F, const double x[4], const double y[4], bool hessians, CellTerms &t) {
    const double s = F.sense < 0 ? -1.0 : 1.0;
    const double xs[4] = {s * x[0], s * x[1], s * x[2], s * x[3]};
    if (F.smoothness != 0.0) add_cell_terms(smoothness_corner, F.smoothness, s, xs, y, hessians, t);
    if (F.cotangent != 0.0) add_cell_terms(cotangent_corner, F.cotangent, s, xs, y, hessians, t);
}

double corner_terms_value(const Functional &F, const double x[4], const double y[4]) {
    const double s = F.sense < 0 ? -1.0 : 1.0;
    const double xs[4] = {s * x[0], s * x[1], s * x[2], s * x[3]};
    double value = 0.0;
    if (F.smoothness != 0.0) add_cell_value(smoothness_corner, F.smoothness, xs, y, value);
    if (F.cotangent != 0.0) add_cell_value(cotangent_corner, F.cotangent, xs, y, value);
    return value;
}

NodeTerms corner_node_terms(const Functional &F, const double x[4], const double y[4], bool exact) {
    const double s = F.sense < 0 ? -1.0 : 1.0;
    const double xs[4] = {s * x[0], s * x[1], s * x[2], s * x[3]};
    NodeTerms u;
    if (F.smoothness != 0.0) add_node_terms(smoothness_corner, F.smoothness, xs, y, exact, u);
    if (F.cotangent != 0.0) add_node_terms(cotangent_corner, F.cotangent, xs, y, exact, u);
    // Back to (x, y) as add_corner_terms does.
    NodeTerms t;
    t.g[0] = s * u.g[0], t.g[1] = u.g[1];
    for (int p = 0; p < 2; ++p)
        for (int q = 0; q < 2; ++q) {
            const double sign = (p == 0 ? s : 1.0) * (q == 0 ? s : 1.0);
            t.h[p][q] = sign * u.h[p][q];
            t.hc[p][q] = sign * u.hc[p][q];
        }
    return t;
}

}  // namespace eg2d
