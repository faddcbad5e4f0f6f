// Tridiagonal kernels for the line solvers (LSOR, AF, line smoothers):
// the Thomas algorithm, and the cyclic system of a periodic line solved by
// Sherman-Morrison (Ly & Norrison 2007), so the O-grid cut moves with the interior.
#pragma once
#include <cstddef>
#include <vector>

namespace eg2d {

// Solves a[k] u[k-1] + b[k] u[k] + c[k] u[k+1] = d[k], k = 0..n-1 (a[0], c[n-1]
// unused). The solution overwrites d; c is used as scratch. Needs |b| to
// dominate, as it does for every system eg2d builds. n >= 1.
void solve_tridiagonal(std::size_t n, const double *a, const double *b, double *c, double *d);

// The same matrix for two right-hand sides d1, d2 (x and y of a grid line):
// one elimination serves both. c is scratch; d1, d2 get the solutions.
void solve_tridiagonal2(std::size_t n, const double *a, const double *b, double *c, double *d1, double *d2);

// The periodic version: a[0] couples u[0] to u[n-1] and c[n-1] couples u[n-1]
// to u[0]. n >= 3. `work` is scratch (resized as needed). Overwrites d with
// the solution; a, b, c are left unchanged. False (d is then scratch) when
// the system is singular to rounding.
bool solve_cyclic_tridiagonal(std::size_t n, const double *a, const double *b, const double *c, double *d,
                              std::vector<double> &work);

}  // namespace eg2d
