/* A NACA 4-digit O-grid: the section by arc length (clustered at the leading
 * and trailing edges with a two-sided tanh), a circle of radius 15 chords as
 * the far field, Winslow + the chosen solver to 1e-9.
 * Usage: airfoil [digits [ni nj [solver]]]    e.g. airfoil 0012 257 65 0
 * Build: cc airfoil.c $(pkg-config --cflags --libs eg2d) -lm -o airfoil */
#include <eg2d.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static void far_field(void *user, double t, double *x, double *y) {
    const double R = *(const double *)user, a = 2 * 3.14159265358979323846 * t;
    *x = 0.5 + R * cos(a);
    *y = -R * sin(a); /* clockwise from the trailing-edge side, like the airfoil */
}

int main(int argc, char **argv) {
    const char *digits = argc > 1 ? argv[1] : "0012";
    const int ni = argc > 3 ? atoi(argv[2]) : 129, nj = argc > 3 ? atoi(argv[3]) : 33;
    const int solver = argc > 4 ? atoi(argv[4]) : EG2D_SOLVER_PSOR;
    double R = 15.0, residual, folded, min_area, wall;
    eg2d_curve *foil, *far;
    eg2d_grid *g;
    int iterations, status;
    clock_t t0;

    if (eg2d_curve_naca4(digits, EG2D_NACA_CLOSED_TE, &foil) || eg2d_curve_function(far_field, &R, &far) ||
        eg2d_create(ni, nj, &g)) {
        fprintf(stderr, "%s\n", eg2d_last_error(NULL));
        return 1;
    }
    /* b = 2, c = 1/2: points gather at both ends of the curve (the trailing
     * edge) and thin out at its middle (the leading edge, where arc length
     * already puts them close to the curvature). */
    if (eg2d_set_topology(g, EG2D_TOPO_O) ||
        eg2d_set_side_curve(g, EG2D_SIDE_JMIN, foil, EG2D_DIST_TANH_TWO, 1.0, 0.5, 0) ||
        eg2d_set_side_curve(g, EG2D_SIDE_JMAX, far, EG2D_DIST_UNIFORM, 0, 0, 0) || eg2d_set_solver(g, solver) ||
        eg2d_set_tolerance(g, 1e-9)) {
        fprintf(stderr, "%s\n", eg2d_last_error(g));
        return 1;
    }
    t0 = clock();
    status = eg2d_solve(g);
    if (status != EG2D_OK) {
        fprintf(stderr, "eg2d_solve: %s\n", eg2d_last_error(g));
        return 1;
    }
    eg2d_get_residual(g, &residual);
    eg2d_get_iterations(g, &iterations);
    eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded);
    eg2d_get_quality(g, EG2D_QUALITY_MIN_AREA, &min_area);
    {
        double *x = malloc(sizeof(double) * (size_t)ni * (size_t)nj), *y = malloc(sizeof(double) * (size_t)ni * (size_t)nj);
        int i;
        wall = 1e300;
        eg2d_get_coordinates(g, x, y);
        for (i = 0; i < ni - 1; ++i) wall = fmin(wall, hypot(x[i + ni] - x[i], y[i + ni] - y[i]));
        free(x);
        free(y);
    }
    printf("NACA %s O-grid %dx%d, %s: %d iterations, %.2f s, residual %.3g, %g folded cells, "
           "min cell area %.3g, smallest wall spacing %.3g\n",
           digits, ni, nj, eg2d_solver_name(solver), iterations, (double)(clock() - t0) / CLOCKS_PER_SEC, residual,
           folded, min_area, wall);
    eg2d_destroy(g);
    eg2d_curve_destroy(foil);
    eg2d_curve_destroy(far);
    return folded == 0 ? 0 : 1;
}
