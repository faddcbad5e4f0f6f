// The smoothness term's share of one cell (smoothness_cell.hpp), in each
// corner's z = (u_x, u_y, v_x, v_y): S = |u|^2 + |v|^2, X = u x v, F = S/X.
#include "operator/smoothness_cell.hpp"

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

// Corner m of the cell (x, y); false, with t's value made infinite, where
// u x v <= 0 (flat or folded: outside both terms' domain).
bool corner_at(const double x[4], const double y[4], int m, Corner &c, CellTerms &t) {
    c.m = m;
    c.n = (m + 1) % 4;
    c.p = (m + 3) % 4;
    c.z[0] = x[c.n] - x[m], c.z[1] = y[c.n] - y[m], c.z[2] = x[c.p] - x[m], c.z[3] = y[c.p] - y[m];
    c.X = c.z[0] * c.z[3] - c.z[1] * c.z[2];
    if (c.X > 0.0) return true;
    t.value = std::numeric_limits<double>::infinity();
    return false;
}

// body(corner) for each corner of the cell (x, y) with u x v > 0.
template <class Body>
void for_each_corner(const double x[4], const double y[4], CellTerms &t, Body body) {
    for (int m = 0; m < 4; ++m) {
        Corner c;
        if (corner_at(x, y, m, c, t)) body(c);
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

}  // namespace

void add_cotangent_terms(double w, const double x[4], const double y[4], bool hessians, CellTerms &t) {
    for_each_corner(x, y, t, [&](const Corner &cr) {
        const double *z = cr.z, X = cr.X;
        // F = p^2/X^2 = q^2, q = p/X the cotangent.
        const double p = z[0] * z[2] + z[1] * z[3], q = p / X;
        t.value += w * q * q;
        const double gp[4] = {z[2], z[3], z[0], z[1]}, gX[4] = {z[3], -z[2], -z[1], z[0]};
        double gq[4], g4[4];
        for (int k = 0; k < 4; ++k) {
            gq[k] = (gp[k] - q * gX[k]) / X;
            g4[k] = 2.0 * w * q * gq[k];
        }
        add_gradient(cr, g4, t);
        if (!hessians) return;
        // Exact: 2 gq gq^T + 2 q hess q, hess q = (hess p - gq gX^T - gX gq^T - q hess X)/X;
        // convex: 2 gq gq^T (exact at right angles, q = 0).
        double h4[4][4], c4[4][4];
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) {
                double hq = -(gq[a] * gX[b] + gX[a] * gq[b]);
                if (a == (b + 2) % 4) hq += 1.0;
                if (a + b == 3) hq -= (a == 0 || a == 3 ? 1.0 : -1.0) * q;
                c4[a][b] = 2.0 * w * gq[a] * gq[b];
                h4[a][b] = c4[a][b] + 2.0 * w * q * hq / X;
            }
        scatter(h4, cr.n, cr.p, cr.m, t.h);
        scatter(c4, cr.n, cr.p, cr.m, t.hc);
    });
}

void add_corner_terms(const Functional &F, const double x[4], const double y[4], bool hessians, CellTerms &t) {
    const double s = F.sense < 0 ? -1.0 : 1.0;
    const double xs[4] = {s * x[0], s * x[1], s * x[2], s * x[3]};
    CellTerms u;
    if (F.smoothness != 0.0) add_smoothness_terms(F.smoothness, xs, y, hessians, u);
    if (F.cotangent != 0.0) add_cotangent_terms(F.cotangent, xs, y, hessians, u);
    // Back to (x, y): every x-component of the gradient, and every Hessian
    // entry with one x index, changes sign.
    t.value += u.value;
    for (int p = 0; p < 8; ++p) {
        const double sp = p % 2 ? 1.0 : s;
        t.g[p] += sp * u.g[p];
        if (!hessians) continue;
        for (int q = 0; q < 8; ++q) {
            const double sq = q % 2 ? 1.0 : s;
            t.h[p][q] += sp * sq * u.h[p][q];
            t.hc[p][q] += sp * sq * u.hc[p][q];
        }
    }
}

void add_smoothness_terms(double w, const double x[4], const double y[4], bool hessians, CellTerms &t) {
    for_each_corner(x, y, t, [&](const Corner &cr) {
        const double *z = cr.z, X = cr.X;
        const double S = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] + z[3] * z[3];
        t.value += w * S / X;
        const double gX[4] = {z[3], -z[2], -z[1], z[0]};
        double g4[4];
        for (int k = 0; k < 4; ++k) g4[k] = w * (2.0 * z[k] / X - S * gX[k] / (X * X));
        add_gradient(cr, g4, t);
        if (!hessians) return;
        // Exact: 2I/X - (grad S gX^T + gX grad S^T)/X^2 + 2S gX gX^T/X^3 - (S/X^2) hess X,
        // hess X = 1 at (0,3), (3,0) and -1 at (1,2), (2,1).
        const double e[2] = {z[0] - z[3], z[1] + z[2]};
        const double ge[2][4] = {{1, 0, 0, -1}, {0, 1, 1, 0}};
        double c[2][4];
        for (int q = 0; q < 2; ++q)
            for (int k = 0; k < 4; ++k) c[q][k] = ge[q][k] - e[q] / X * gX[k];
        double h4[4][4], c4[4][4];
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) {
                double h = (a == b ? 2.0 / X : 0.0) - 2.0 * (z[a] * gX[b] + gX[a] * z[b]) / (X * X) +
                           2.0 * S * gX[a] * gX[b] / (X * X * X);
                if (a + b == 3) h -= (a == 0 || a == 3 ? 1.0 : -1.0) * S / (X * X);
                h4[a][b] = w * h;
                c4[a][b] = 2.0 * w / X * (c[0][a] * c[0][b] + c[1][a] * c[1][b]);
            }
        scatter(h4, cr.n, cr.p, cr.m, t.h);
        scatter(c4, cr.n, cr.p, cr.m, t.hc);
    });
}

}  // namespace eg2d
