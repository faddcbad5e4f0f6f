/* Solving a test domain and comparing grids, shared by the solver tests. */
#ifndef EG2D_TEST_SOLVE_COMPARE_H
#define EG2D_TEST_SOLVE_COMPARE_H

#ifdef __cplusplus
extern "C" {
#endif

/* Solves a domain of domains.h ("annulus": 3 <= r <= 9 as an O-grid) from
 * TFI with `solver` and `system` to `tol`, fold check off. Returns the
 * iteration count and fills x, y (ni*nj each), or returns -status. */
int solve_domain(const char *domain, int ni, int nj, int solver, int system, double tol, double *x, double *y);

/* The largest distance between corresponding nodes of two grids of n nodes. */
double grid_distance(const double *x1, const double *y1, const double *x2, const double *y2, int n);

/* The largest distance of an annulus grid (3 <= r <= 9) from Winslow's
 * solution r = 3 * 3^eta, theta = 2 pi xi (NUMERICS.md). */
double annulus_exact_error(int ni, int nj, const double *x, const double *y);

/* 1 if the O-grid's columns 0 and ni-1 hold bitwise the same points. */
int cut_columns_equal(int ni, int nj, const double *x, const double *y);

#ifdef __cplusplus
}
#endif
#endif
