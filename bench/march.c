/* The hyperbolic march (eg2d_bench --march): NACA 0012 O-grids 257 x 129 to
 * 100 chords with growth <= 1.2, the acceptance case of "Wall-resolved
 * grids" item 1. Printed per row: wall and CPU seconds of eg2d_initialize
 * (medians of 3), folded cells, the far field (nearest outer node's
 * distance from the wall nodes / the distance asked), the first cell (min
 * and max over the wall), the largest height ratio along the j-lines, and
 * two orthogonality measures per cell: the angle between the cell's two
 * mid-lines (the mean of its i-edges against the mean of its j-edges), as
 * its fraction within 0.5 and 5 degrees of 90 and its median and 99th
 * percentile deviation; and EG2D_QUALITY_SKEWNESS (the worst of the four
 * corners) at its median and 99th percentile. Rows with the march's default
 * smoothing, and with less dissipation and more area smoothing. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"

static int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median3(double *v) {
    qsort(v, 3, sizeof *v, by_value);
    return v[1];
}

/* JMIN of an O-grid on NACA 0012: uniform in arc length, or (cluster > 0)
 * each surface from the trailing edge to the leading edge by Vinokur's
 * distribution with both end spacings `cluster` (a fraction of the surface). */
static int set_foil(eg2d_grid *g, int ni, double cluster) {
    eg2d_curve *foil;
    int status = eg2d_set_topology(g, EG2D_TOPO_O);
    if (!status) status = eg2d_curve_naca4("0012", EG2D_NACA_CLOSED_TE, &foil);
    if (status) return status;
    if (cluster <= 0) {
        status = eg2d_set_side_curve(g, EG2D_SIDE_JMIN, foil, EG2D_DIST_UNIFORM, 0, 0, 0);
    } else {
        const int h = (ni + 1) / 2;
        double *u = malloc(sizeof(double) * (size_t)(h + 2 * ni)), *x = u + h, *y = x + ni;
        int k;
        status = eg2d_distribution(EG2D_DIST_VINOKUR, h, cluster, cluster, u);
        for (k = 0; !status && k < h; ++k) {
            eg2d_curve_evaluate(foil, 0.5 * u[k], &x[k], &y[k]);
            eg2d_curve_evaluate(foil, 0.5 + 0.5 * u[k], &x[h - 1 + k], &y[h - 1 + k]);
        }
        if (!status) status = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
        free(u);
    }
    eg2d_curve_destroy(foil);
    return status;
}

static void row(const char *label, double cluster, double first, double smoothing, double area) {
    const int ni = 257, nj = 129, nc = (ni - 1) * (nj - 1);
    const double distance = 100;
    double wall[3], cpu[3], folds = -1;
    double *x = malloc(sizeof(double) * (size_t)(2 * ni * nj + 2 * nc)), *y = x + ni * nj, *c = y + ni * nj,
           *sk = c + nc;
    eg2d_grid *g = NULL;
    int r, i, j, status = 0;
    for (r = 0; r < 3 && !status; ++r) {
        eg2d_destroy(g);
        status = eg2d_create(ni, nj, &g);
        if (!status) status = set_foil(g, ni, cluster);
        if (!status) status = eg2d_set_parameter(g, EG2D_PARAM_MARCH_DISTANCE, distance);
        if (!status) status = eg2d_set_parameter(g, EG2D_PARAM_MARCH_FIRST_HEIGHT, first);
        if (!status) status = eg2d_set_parameter(g, EG2D_PARAM_MARCH_GROWTH, 1.2);
        if (!status && smoothing >= 0) status = eg2d_set_parameter(g, EG2D_PARAM_MARCH_SMOOTHING, smoothing);
        if (!status && area >= 0) status = eg2d_set_parameter(g, EG2D_PARAM_MARCH_AREA_SMOOTHING, area);
        const double w0 = bench_wall(), c0 = bench_cpu();
        if (!status) status = eg2d_initialize(g, EG2D_INIT_HYPERBOLIC);
        wall[r] = bench_wall() - w0;
        cpu[r] = bench_cpu() - c0;
    }
    if (status) {
        printf("| %s | failed: %s |\n", label, eg2d_last_error(g));
        eg2d_destroy(g);
        free(x);
        return;
    }
    eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folds);
    eg2d_get_coordinates(g, x, y);
    eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, sk);
    double near = INFINITY, h_min = INFINITY, h_max = 0, growth = 0;
    int within05 = 0, within5 = 0, m = 0;
    for (i = 0; i < ni - 1; ++i) {
        double d = INFINITY;
        int k;
        for (k = 0; k < ni - 1; ++k) d = fmin(d, hypot(x[i + ni * (nj - 1)] - x[k], y[i + ni * (nj - 1)] - y[k]));
        near = fmin(near, d);
        const double h = hypot(x[i + ni] - x[i], y[i + ni] - y[i]);
        h_min = fmin(h_min, h);
        h_max = fmax(h_max, h);
        for (j = 1; j + 1 < nj; ++j) {
            const int k0 = i + ni * (j - 1), k1 = k0 + ni, k2 = k1 + ni;
            growth = fmax(growth, hypot(x[k2] - x[k1], y[k2] - y[k1]) / hypot(x[k1] - x[k0], y[k1] - y[k0]));
        }
    }
    for (j = 0; j < nj - 1; ++j)
        for (i = 0; i < ni - 1; ++i) {
            const int k = i + ni * j, e = k + 1, n = k + ni, ne = n + 1;
            const double ax = x[e] - x[k] + x[ne] - x[n], ay = y[e] - y[k] + y[ne] - y[n];
            const double bx = x[n] - x[k] + x[ne] - x[e], by = y[n] - y[k] + y[ne] - y[e];
            const double dev = fabs(90 - acos((ax * bx + ay * by) / (hypot(ax, ay) * hypot(bx, by))) * 180 / M_PI);
            within05 += dev <= 0.5;
            within5 += dev <= 5;
            c[m++] = dev;
        }
    qsort(c, (size_t)nc, sizeof *c, by_value);
    qsort(sk, (size_t)nc, sizeof *sk, by_value);
    printf("| %s | %.4f | %.4f | %.0f | %.3f | %.3g-%.3g | %.3f | %.1f%% | %.2f%% | %.3f | %.2f | %.2f | %.2f |\n", label,
           median3(wall), median3(cpu), folds, near / distance, h_min, h_max, growth, 100.0 * within05 / nc,
           100.0 * within5 / nc, c[nc / 2], c[(int)(0.99 * nc)], sk[nc / 2], sk[(int)(0.99 * nc)]);
    eg2d_destroy(g);
    free(x);
}

void bench_march(void) {
    printf("NACA 0012 O-grid 257 x 129, hyperbolic march to 100 chords, growth <= 1.2\n\n");
    printf("| surface, first cell | wall s | CPU s | folds | far / asked | first cell | max growth | "
           "mid-line <= 0.5 deg | <= 5 deg | median deg | p99 deg | skewness median | p99 |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    /* the march's defaults (smoothing 0.5, 20 area-smoothing passes) */
    row("uniform, 1e-5", 0, 1e-5, -1, -1);
    row("uniform, 1e-4", 0, 1e-4, -1, -1);
    row("uniform, automatic", 0, 0, -1, -1);
    row("LE/TE clustered 0.002, 1e-5", 0.002, 1e-5, -1, -1);
    /* less dissipation, more area smoothing */
    row("uniform, 1e-5; smoothing 0.25, area 50", 0, 1e-5, 0.25, 50);
    row("uniform, 1e-4; smoothing 0.25, area 50", 0, 1e-4, 0.25, 50);
    row("LE/TE clustered 0.002, 1e-5; smoothing 0.25, area 50", 0.002, 1e-5, 0.25, 50);
}
