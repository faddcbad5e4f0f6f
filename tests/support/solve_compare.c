#include "solve_compare.h"

#include <math.h>
#include <string.h>

#include "domains.h"
#include "eg2d.h"

#define EG2D_TEST_PI 3.14159265358979323846

int solve_domain(const char *domain, int ni, int nj, int solver, int system, double tol, double *x, double *y) {
    eg2d_grid *g;
    int status, it = 0;
    if ((status = eg2d_create(ni, nj, &g))) return -status;
    status = !strcmp(domain, "annulus") ? domain_set_annulus(g, 3.0, 9.0) : domain_set(g, domain);
    if (!status) status = eg2d_set_solver(g, solver);
    if (!status) status = eg2d_set_system(g, system);
    if (!status) status = eg2d_set_tolerance(g, tol);
    if (!status) status = eg2d_set_parameter(g, EG2D_PARAM_FOLD_CHECK, 0);
    if (!status) status = eg2d_solve(g);
    if (!status) status = eg2d_get_coordinates(g, x, y);
    if (!status) status = eg2d_get_iterations(g, &it);
    eg2d_destroy(g);
    return status ? -status : it;
}

double grid_distance(const double *x1, const double *y1, const double *x2, const double *y2, int n) {
    double d = 0;
    int k;
    for (k = 0; k < n; ++k) d = fmax(d, hypot(x1[k] - x2[k], y1[k] - y2[k]));
    return d;
}

double annulus_exact_error(int ni, int nj, const double *x, const double *y) {
    double err = 0;
    int i, j;
    for (j = 0; j < nj; ++j)
        for (i = 0; i < ni; ++i) {
            const double r = 3.0 * pow(3.0, (double)j / (nj - 1)), t = 2 * EG2D_TEST_PI * i / (ni - 1);
            err = fmax(err, hypot(x[i + ni * j] - r * cos(t), y[i + ni * j] - r * sin(t)));
        }
    return err;
}

int cut_columns_equal(int ni, int nj, const double *x, const double *y) {
    int j;
    for (j = 0; j < nj; ++j)
        if (x[ni * j] != x[ni * j + ni - 1] || y[ni * j] != y[ni * j + ni - 1]) return 0;
    return 1;
}
