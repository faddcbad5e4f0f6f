/* Wall-resolved grids side by side (eg2d_bench --wall): NACA 0012 with a
 * sharp trailing edge, O-grids inside a circle and C-grids
 * (domain_set_airfoil_c_graded), first cells of 4.46e-6 (y+ 1 at Re 6e6)
 * to 1e-7 chord.
 * Per case three ways to the grid, each from the same boundary:
 *   control  EG2D_ORTHO_WALL with eg2d_set_wall_spacing, the default solver
 *            (the Sorenson-type control; one run, at most 10000 iterations);
 *   hybrid   the same with EG2D_PARAM_WALL_LAYER = 2 (median of 3);
 *   march    EG2D_INIT_HYPERBOLIC alone to the far field's least distance,
 *            first cell h, growth <= 3 (its own outer boundary; median of 3);
 *   default  EG2D_ORTHO_WALL and the height, nothing else set (the automatic
 *            EG2D_PARAM_WALL_LAYER 3; median of 3).
 * Columns: status, CPU seconds, iterations (multigrid: cycles), first cell
 * (min and max over the wall), the largest growth of consecutive cell
 * heights over the first 30 cells of every column, the largest deviation of
 * the wall's grid lines from 90 degrees, EG2D_QUALITY_SKEWNESS (the worst
 * corner, the trailing edge's own 82 degrees included), folded cells and
 * the run's first note (eg2d_get_run_event; truncated). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "domains.h"
#include "measure.h"

typedef struct {
    int ni, nj;
    double h, radius;
    int wake; /* > 0: a C-grid (domain_set_airfoil_c_graded) with this many cut nodes a side */
} wall_case;

typedef enum { CONTROL, HYBRID, MARCH, DEFAULT } method;
static const char *const method_name[] = {"control", "hybrid", "march", "default"};

static int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The least distance of a JMAX node from a JMIN node (the march's distance). */
static double outer_distance(const double *x, const double *y, int ni, int nj) {
    double d = INFINITY;
    for (int a = 0; a < ni; ++a)
        for (int b = 0; b < ni; ++b)
            d = fmin(d, hypot(x[a + ni * (nj - 1)] - x[b], y[a + ni * (nj - 1)] - y[b]));
    return d;
}

static void run(const wall_case *w, method m) {
    const int ni = w->ni, nj = w->nj, repeats = m == CONTROL ? 1 : 3;
    double cpu[3], *x = malloc(sizeof(double) * (size_t)(2 * ni * nj)), *y = x + ni * nj;
    double dev = NAN, hmin = NAN, hmax = NAN, skew = NAN, folds = NAN, growth = NAN;
    int it = 0, status = EG2D_OK;
    char note[120] = "";
    for (int r = 0; r < repeats; ++r) {
        eg2d_grid *g;
        eg2d_create(ni, nj, &g);
        if (w->wake > 0)
            domain_set_airfoil_c_graded(g, "0012", w->wake, w->radius, 1e-3, 2e-3);
        else
            domain_set_airfoil_o(g, "0012", w->radius);
        double t0;
        if (m == MARCH) {
            eg2d_initialize(g, EG2D_INIT_TFI);
            eg2d_get_coordinates(g, x, y);
            eg2d_set_parameter(g, EG2D_PARAM_MARCH_DISTANCE, outer_distance(x, y, ni, nj));
            eg2d_set_parameter(g, EG2D_PARAM_MARCH_FIRST_HEIGHT, w->h);
            eg2d_set_parameter(g, EG2D_PARAM_MARCH_GROWTH, 3);
            t0 = bench_cpu();
            status = eg2d_initialize(g, EG2D_INIT_HYPERBOLIC);
        } else {
            eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, w->h);
            eg2d_set_orthogonality(g, EG2D_ORTHO_WALL);
            if (m != DEFAULT) eg2d_set_parameter(g, EG2D_PARAM_WALL_LAYER, m == HYBRID ? 2 : 0);
            eg2d_set_parameter(g, EG2D_PARAM_MAX_ITERATIONS, 10000);
            eg2d_set_tolerance(g, 1e-10);
            t0 = bench_cpu();
            status = eg2d_solve(g);
            eg2d_get_iterations(g, &it);
        }
        cpu[r] = bench_cpu() - t0;
        int events = 0;
        if (r == repeats - 1 && eg2d_get_run_info(g, EG2D_RUN_EVENTS, &events) == EG2D_OK && events > 0)
            eg2d_get_run_event(g, 0, NULL, note, sizeof note);
        if (r == repeats - 1 && status == EG2D_OK && eg2d_get_coordinates(g, x, y) == EG2D_OK) {
            /* the body's nodes: an O-grid's all, a C-grid's between the cut's */
            const int b0 = w->wake, b1 = w->wake > 0 ? ni - w->wake : ni - 1;
            measure_wall(x, y, ni, nj, EG2D_SIDE_JMIN, w->wake == 0, b0, b1, &dev, &hmin, &hmax);
            eg2d_get_quality(g, EG2D_QUALITY_SKEWNESS, &skew);
            if (w->wake > 0) { /* the wake's cells only: the body's own corners are the O-grids' 81.8 */
                double *cells = malloc(sizeof(double) * (size_t)((ni - 1) * (nj - 1)));
                eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, cells);
                skew = 0;
                for (int k = 0; k < (ni - 1) * (nj - 1); ++k)
                    if (k % (ni - 1) < w->wake || k % (ni - 1) >= ni - 1 - w->wake) skew = fmax(skew, cells[k]);
                free(cells);
            }
            eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folds);
            growth = 0;
            for (int i = b0; i < b1; ++i)
                for (int j = 1; j < 30 && j < nj - 1; ++j) {
                    const double a = measure_distance(x, y, ni, i, j, i, j + 1), b = measure_distance(x, y, ni, i, j - 1, i, j);
                    growth = fmax(growth, a / b);
                }
        }
        eg2d_destroy(g);
    }
    qsort(cpu, (size_t)repeats, sizeof *cpu, by_value);
    printf("| %s %dx%d, %g, R %g | %s | %s | %.3f | %d | %.4g-%.4g | %.3f | %.3f | %.1f | %g | %s |\n",
           w->wake > 0 ? "C" : "O", ni, nj, w->h,
           w->radius, method_name[m], status == EG2D_OK ? "ok" : eg2d_status_string(status), cpu[repeats / 2], it, hmin,
           hmax, growth, dev, skew, folds, note);
    free(x);
}

void bench_walls(void) {
    static const wall_case cases[] = {
        {250, 100, 1.04e-5, 15, 0}, {300, 80, 1e-5, 15, 0},   {250, 100, 1e-7, 15, 0}, {257, 129, 1e-6, 100, 0},
        {385, 97, 1e-5, 100, 0},    {385, 97, 4.46e-6, 100, 80}, {769, 193, 4.46e-6, 500, 160},
    };
    printf("NACA 0012 with a sharp trailing edge; O-grids inside a circle of radius R chords, C-grids (the section\n"
           "clustered at its edges, the cut growing from the trailing edge's spacing) with the far field R chords out;\n"
           "residual 1e-10. C-grid rows: first cell, growth and angle over the body, skewness over the wake's cells.\n\n");
    printf("| case (size, first cell, R) | method | status | CPU s | iterations | first cell | growth (30 cells) | "
           "wall angle deg | skewness deg | folds | the run's first note |\n|---|---|---|---:|---:|---|---:|---:|---:|---:|---|\n");
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k)
        for (int m = CONTROL; m <= DEFAULT; ++m) {
            run(&cases[k], (method)m);
            fflush(stdout);
        }
}
