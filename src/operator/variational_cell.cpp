// One cell's share of V (variational_cell.hpp). Coordinates are taken
// relative to corner 0: every term depends on differences only.
#include "operator/variational_cell.hpp"

#include "operator/smoothness_cell.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

namespace eg2d {

namespace {

// The smallest alpha > 0 at which c0 + c1 alpha + c2 alpha^2 (c0 > 0) is 0, or infinity.
double first_root(double c0, double c1, double c2) {
    const double inf = std::numeric_limits<double>::infinity();
    if (c2 == 0.0) return c1 < 0.0 ? -c0 / c1 : inf;
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc < 0.0) return inf;  // c2 > 0 and no real root: positive for every alpha
    const double s = std::sqrt(disc);
    // Roots without cancellation: q = -(c1 + sign(c1) s)/2, roots q/c2 and c0/q.
    const double q = -0.5 * (c1 + (c1 >= 0.0 ? s : -s));
    double best = inf;
    if (q != 0.0) {
        const double r1 = q / c2, r2 = c0 / q;
        if (r1 > 0.0) best = std::min(best, r1);
        if (r2 > 0.0) best = std::min(best, r2);
    }
    return best;
}

// Adds w f^2 for f with gradient df (8 entries) and constant Hessian hf;
// `id` is the identity on f's two difference vectors (the convex form).
void add_square(CellTerms &t, bool hessians, double w, double f, const double df[8], const double hf[8][8],
                const double id[8][8], double id_weight) {
    t.value += w * f * f;
    for (int k = 0; k < 8; ++k) t.g[k] += 2.0 * w * f * df[k];
    if (!hessians) return;
    const double w2 = 2.0 * w, fi = id_weight * std::fabs(f);
    for (int p = 0; p < 8; ++p)
        for (int q = 0; q < 8; ++q) {
            const double gn = df[p] * df[q];
            t.h[p][q] += w2 * (gn + f * hf[p][q]);
            t.hc[p][q] += w2 * (gn + 0.5 * f * hf[p][q] + fi * id[p][q]);
        }
}

// id += the identity on the difference r_b - r_a (as a quadratic form in r).
void add_difference(double id[8][8], int a, int b) {
    for (int c = 0; c < 2; ++c) {
        id[2 * a + c][2 * a + c] += 1.0;
        id[2 * b + c][2 * b + c] += 1.0;
        id[2 * a + c][2 * b + c] -= 1.0;
        id[2 * b + c][2 * a + c] -= 1.0;
    }
}

}  // namespace

void cell_terms(const Functional &F, double mean, const double x[4], const double y[4], bool hessians,
                CellTerms &t) {
    const bool full = hessians;
    t = CellTerms{};
    double rx[4], ry[4];
    for (int m = 0; m < 4; ++m) {
        rx[m] = x[m] - x[0];
        ry[m] = y[m] - y[0];
    }
    // S: half of each edge's |r_q - r_p|^2 (linear in its square: no f^2 form).
    const double ws = 0.5 * F.spacing;
    for (int p = 0; p < 4; ++p) {
        const int q = (p + 1) % 4;
        const double dx = rx[q] - rx[p], dy = ry[q] - ry[p];
        t.value += ws * (dx * dx + dy * dy);
        t.g[2 * q] += 2.0 * ws * dx;
        t.g[2 * q + 1] += 2.0 * ws * dy;
        t.g[2 * p] -= 2.0 * ws * dx;
        t.g[2 * p + 1] -= 2.0 * ws * dy;
        if (full)
            for (int c = 0; c < 2; ++c)
                for (auto *h : {t.h, t.hc}) {
                    h[2 * p + c][2 * p + c] += 2.0 * ws;
                    h[2 * q + c][2 * q + c] += 2.0 * ws;
                    h[2 * p + c][2 * q + c] -= 2.0 * ws;
                    h[2 * q + c][2 * p + c] -= 2.0 * ws;
                }
    }
    if (F.area != 0.0) {
        // area = (d1 x d2)/2, d1 = r2 - r0, d2 = r3 - r1.
        const double d1x = rx[2] - rx[0], d1y = ry[2] - ry[0], d2x = rx[3] - rx[1], d2y = ry[3] - ry[1];
        const double f = 0.5 * (d1x * d2y - d1y * d2x) - mean;
        double df[8] = {}, hf[8][8] = {}, id[8][8] = {};
        const double a1x = 0.5 * d2y, a1y = -0.5 * d2x, a2x = -0.5 * d1y, a2y = 0.5 * d1x;  // df/dd1, df/dd2
        df[0] = -a1x, df[1] = -a1y, df[4] = a1x, df[5] = a1y;
        df[2] = -a2x, df[3] = -a2y, df[6] = a2x, df[7] = a2y;
        if (full) {
            add_difference(id, 0, 2);
            add_difference(id, 1, 3);
            const int p1[2] = {0, 2}, q1[2] = {1, 3};
            const double s[2] = {-1.0, 1.0};
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b) {
                    const int p = p1[a], q = q1[b];
                    const double v = 0.5 * s[a] * s[b];
                    hf[2 * p][2 * q + 1] = hf[2 * q + 1][2 * p] = v;        // d1x d2y
                    hf[2 * p + 1][2 * q] = hf[2 * q][2 * p + 1] = -v;       // -d1y d2x
                }
        }
        add_square(t, hessians, F.area, f, df, hf, id, 0.25);
    }
    if (F.orthogonality != 0.0) {
        for (int m = 0; m < 4; ++m) {
            // The corner at m: u = r_next - r_m, v = r_prev - r_m, f = u.v.
            const int n = (m + 1) % 4, p = (m + 3) % 4;
            const double ux = rx[n] - rx[m], uy = ry[n] - ry[m], vx = rx[p] - rx[m], vy = ry[p] - ry[m];
            const double f = ux * vx + uy * vy;
            double df[8] = {}, hf[8][8] = {}, id[8][8] = {};
            df[2 * n] = vx, df[2 * n + 1] = vy;
            df[2 * p] = ux, df[2 * p + 1] = uy;
            df[2 * m] = -(ux + vx), df[2 * m + 1] = -(uy + vy);
            if (full) {
                add_difference(id, m, n);
                add_difference(id, m, p);
            }
            if (full)
                for (int c = 0; c < 2; ++c) {
                    hf[2 * n + c][2 * p + c] = hf[2 * p + c][2 * n + c] = 1.0;
                    hf[2 * m + c][2 * m + c] = 2.0;
                    hf[2 * m + c][2 * n + c] = hf[2 * n + c][2 * m + c] = -1.0;
                    hf[2 * m + c][2 * p + c] = hf[2 * p + c][2 * m + c] = -1.0;
                }
            add_square(t, hessians, F.orthogonality, f, df, hf, id, 0.5);
        }
    }
    if (has_corner_terms(F)) add_corner_terms(F, rx, ry, hessians, t);
}

double cell_value(const Functional &F, double mean, const double x[4], const double y[4]) {
    double s = 0.0, o = 0.0;
    for (int m = 0; m < 4; ++m) {
        const int n = (m + 1) % 4, p = (m + 3) % 4;
        const double ux = x[n] - x[m], uy = y[n] - y[m], vx = x[p] - x[m], vy = y[p] - y[m];
        s += ux * ux + uy * uy;
        const double f = ux * vx + uy * vy;
        o += f * f;
    }
    const double area = 0.5 * ((x[2] - x[0]) * (y[3] - y[1]) - (y[2] - y[0]) * (x[3] - x[1])) - mean;
    double smooth = 0.0;
    if (has_corner_terms(F)) smooth = corner_terms_value(F, x, y);
    return 0.5 * F.spacing * s + F.area * area * area + F.orthogonality * o + smooth;
}

double cell_fold_limit(const double x[4], const double y[4], const double dx[4], const double dy[4], int orientation) {
    double limit = std::numeric_limits<double>::infinity();
    // Each corner's turn (next - m) x (prev - m) along the step is
    // quadratic in alpha; a corner already flat or folded sets no limit.
    for (int m = 0; m < 4; ++m) {
        const int n = (m + 1) % 4, p = (m + 3) % 4;
        const double ax = x[n] - x[m], ay = y[n] - y[m], bx = x[p] - x[m], by = y[p] - y[m];
        const double dax = dx[n] - dx[m], day = dy[n] - dy[m], dbx = dx[p] - dx[m], dby = dy[p] - dy[m];
        const double c0 = orientation * (ax * by - ay * bx);
        if (!(c0 > 0.0)) continue;
        const double c1 = orientation * (ax * dby - ay * dbx + dax * by - day * bx);
        const double c2 = orientation * (dax * dby - day * dbx);
        limit = std::min(limit, first_root(c0, c1, c2));
    }
    return limit;
}

}  // namespace eg2d
