/* The swan grid generated from C (tests/support/domains.c), written as text:
 * "ni nj" then x y of every node in Fortran order, %.17g. The Fortran test
 * test_swan_from_fortran generates the same grid through module eg2d and
 * compares (so do the Python and C++ tests). Usage: swan_write_c FILE */
#include <stdio.h>
#include <stdlib.h>

#include "domains.h"

#define N 33

int main(int argc, char **argv) {
    static double x[N * N], y[N * N];
    eg2d_grid *g;
    FILE *f;
    int k;
    if (argc != 2) return 2;
    if (eg2d_create(N, N, &g) || domain_set(g, "swan") || eg2d_set_system(g, EG2D_SYSTEM_WINSLOW) ||
        eg2d_set_solver(g, EG2D_SOLVER_PSOR) || eg2d_set_tolerance(g, 1e-12) || eg2d_solve(g) ||
        eg2d_get_coordinates(g, x, y)) {
        fprintf(stderr, "swan_write_c: %s\n", eg2d_last_error(g));
        return 1;
    }
    eg2d_destroy(g);
    if (!(f = fopen(argv[1], "w"))) return 1;
    fprintf(f, "%d %d\n", N, N);
    for (k = 0; k < N * N; ++k) fprintf(f, "%.17g %.17g\n", x[k], y[k]);
    return fclose(f) ? 1 : 0;
}
