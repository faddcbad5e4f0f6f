#include "base/tridiagonal.hpp"

namespace eg2d {

void solve_tridiagonal(std::size_t n, const double *a, const double *b, double *c, double *d) {
    double m = b[0];
    c[0] = n > 1 ? c[0] / m : 0.0;
    d[0] /= m;
    for (std::size_t k = 1; k < n; ++k) {
        m = b[k] - a[k] * c[k - 1];
        if (k + 1 < n) c[k] /= m;
        d[k] = (d[k] - a[k] * d[k - 1]) / m;
    }
    for (std::size_t k = n - 1; k-- > 0;) d[k] -= c[k] * d[k + 1];
}

void solve_tridiagonal2(std::size_t n, const double *a, const double *b, double *c, double *d1, double *d2) {
    double inv = 1.0 / b[0];
    c[0] = n > 1 ? c[0] * inv : 0.0;
    d1[0] *= inv;
    d2[0] *= inv;
    for (std::size_t k = 1; k < n; ++k) {
        inv = 1.0 / (b[k] - a[k] * c[k - 1]);
        if (k + 1 < n) c[k] *= inv;
        d1[k] = (d1[k] - a[k] * d1[k - 1]) * inv;
        d2[k] = (d2[k] - a[k] * d2[k - 1]) * inv;
    }
    for (std::size_t k = n - 1; k-- > 0;) {
        d1[k] -= c[k] * d1[k + 1];
        d2[k] -= c[k] * d2[k + 1];
    }
}

bool solve_cyclic_tridiagonal(std::size_t n, const double *a, const double *b, const double *c, double *d,
                              std::vector<double> &work) {
    // A = T + u v^T with T tridiagonal: u = (g, 0, .., 0, c[n-1]),
    // v = (1, 0, .., 0, a[0]/g). Solve T y = d and T z = u, then
    // x = y - (v.y / (1 + v.z)) z.
    work.resize(5 * n);
    double *bb = work.data(), *cy = bb + n, *cz = cy + n, *z = cz + n, *aa = z + n;
    const double g = -b[0];  // any nonzero value; -b[0] keeps T well conditioned
    for (std::size_t k = 0; k < n; ++k) {
        aa[k] = a[k];
        bb[k] = b[k];
        cy[k] = c[k];
        cz[k] = c[k];
        z[k] = 0.0;
    }
    bb[0] -= g;
    bb[n - 1] -= c[n - 1] * a[0] / g;
    z[0] = g;
    z[n - 1] = c[n - 1];
    solve_tridiagonal(n, aa, bb, cy, d);
    solve_tridiagonal(n, aa, bb, cz, z);
    // 1 + v.z = 0: A is singular to rounding (a coarse ring of cells 1e13
    // times longer than wide): no solution is defined, and dividing would
    // raise FE_DIVBYZERO.
    const double den = 1.0 + z[0] + a[0] * z[n - 1] / g;
    if (den == 0.0) return false;
    const double fact = (d[0] + a[0] * d[n - 1] / g) / den;
    for (std::size_t k = 0; k < n; ++k) d[k] -= fact * z[k];
    return true;
}

}  // namespace eg2d
