/* The swan domain of the elliptic-grid course notes at 65 x 65: Winslow + point SOR to 1e-10.
 * Build: cc swan.c $(pkg-config --cflags --libs eg2d) -o swan */
#include <eg2d.h>
#include <stdio.h>

#define N 65

int main(void) {
    double xb[N], yb[N], xr[N], yr[N], xt[N], yt[N], xl[N], yl[N];
    static double x[N * N], y[N * N];
    eg2d_grid *g;
    double residual, folded;
    int i, iterations, status;

    for (i = 0; i < N; ++i) {
        const double s = (double)i / (N - 1);
        xb[i] = s;                 yb[i] = 0;                      /* bottom  y = 0          */
        xr[i] = 1 + 2 * s - 2 * s * s; yr[i] = s;                  /* right   x = 1+2y-2y^2  */
        xt[i] = s;                 yt[i] = 1 - 2 * s + 2 * s * s;  /* top     y = 1-2x+2x^2  */
        xl[i] = 0;                 yl[i] = s;                      /* left    x = 0          */
    }
    if (eg2d_create(N, N, &g) != EG2D_OK) {
        fprintf(stderr, "%s\n", eg2d_last_error(NULL));
        return 1;
    }
    eg2d_set_side(g, EG2D_SIDE_JMIN, xb, yb);
    eg2d_set_side(g, EG2D_SIDE_IMAX, xr, yr);
    eg2d_set_side(g, EG2D_SIDE_JMAX, xt, yt);
    eg2d_set_side(g, EG2D_SIDE_IMIN, xl, yl);
    eg2d_set_system(g, EG2D_SYSTEM_WINSLOW);
    eg2d_set_solver(g, EG2D_SOLVER_PSOR);
    eg2d_set_tolerance(g, 1e-10);
    status = eg2d_solve(g);
    if (status != EG2D_OK) {
        fprintf(stderr, "eg2d_solve: %s\n", eg2d_last_error(g));
        eg2d_destroy(g);
        return 1;
    }
    eg2d_get_residual(g, &residual);
    eg2d_get_iterations(g, &iterations);
    eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded);
    eg2d_get_coordinates(g, x, y);
    printf("swan %dx%d: %d iterations, residual %.3g, %g folded cells, centre node (%.6f, %.6f)\n", N, N,
           iterations, residual, folded, x[N / 2 + N * (N / 2)], y[N / 2 + N * (N / 2)]);
    eg2d_destroy(g);
    return residual <= 1e-10 && folded == 0 ? 0 : 1;
}
