/* Failure behaviour: every bad input of the table below returns its code and
 * message, changes nothing (runs excepted: they keep or restore their work as
 * eg2d.h says), and leaves the handle usable: the good sequence run on it
 * afterwards gives bitwise the same grid as on a fresh handle. Allocations
 * that cannot be satisfied are provoked under setrlimit(RLIMIT_AS) in a child
 * process, so nothing big is ever touched and the OOM killer never acts.
 *
 * The table is also docs/BAD_INPUTS.md: `test_failures --table` prints it and
 * the ctest bad_inputs_doc checks the committed page against it. A new bad
 * input is one row (and, if it needs one, a small run function). */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#include "domains.h"
#include "fp_traps.h"
#include "eg2d.h"

#define N 9 /* the size of the table's grids */

/* Sanitizers and valgrind replace the allocator: a failing operator new
 * aborts there instead of throwing, so the memory-limit rows cannot run. */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define ALLOCATOR_REPLACED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define ALLOCATOR_REPLACED 1
#endif
#endif
#ifndef ALLOCATOR_REPLACED
#define ALLOCATOR_REPLACED 0
#endif

/*---------------------------------------------------------------------
 * Inputs
 *-------------------------------------------------------------------*/
/* Side `side` of the unit square, N points in increasing index. */
static void unit_side(int side, double *x, double *y) {
    int p;
    for (p = 0; p < N; ++p) {
        const double t = (double)p / (N - 1);
        x[p] = side == EG2D_SIDE_IMAX ? 1 : side == EG2D_SIDE_IMIN ? 0 : t;
        y[p] = side == EG2D_SIDE_JMAX ? 1 : side == EG2D_SIDE_JMIN ? 0 : t;
    }
}

/* The unit square scaled by s, set side by side; returns the first failure. */
static int set_square(eg2d_grid *g, double s) {
    double x[N], y[N];
    int side, p, rc;
    for (side = 0; side < 4; ++side) {
        unit_side(side, x, y);
        for (p = 0; p < N; ++p) {
            x[p] *= s;
            y[p] *= s;
        }
        if ((rc = eg2d_set_side(g, side, x, y)) != EG2D_OK) return rc;
    }
    return EG2D_OK;
}

/* A triangle: IMIN has zero length (all its points at (0, 0)), JMAX is
 * the diagonal from (0, 0) to (1, 1). */
static int set_triangle(eg2d_grid *g) {
    double x[N], y[N];
    int p, rc;
    unit_side(EG2D_SIDE_JMIN, x, y);
    rc = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    unit_side(EG2D_SIDE_IMAX, x, y);
    rc = rc ? rc : eg2d_set_side(g, EG2D_SIDE_IMAX, x, y);
    unit_side(EG2D_SIDE_JMAX, x, y);
    for (p = 0; p < N; ++p) y[p] = x[p];
    rc = rc ? rc : eg2d_set_side(g, EG2D_SIDE_JMAX, x, y);
    for (p = 0; p < N; ++p) x[p] = y[p] = 0;
    return rc ? rc : eg2d_set_side(g, EG2D_SIDE_IMIN, x, y);
}

/* JMIN of the unit square with point p set to (px, py). */
static int jmin_with(eg2d_grid *g, int p, double px, double py) {
    double x[N], y[N];
    unit_side(EG2D_SIDE_JMIN, x, y);
    x[p] = px;
    y[p] = py;
    return eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
}

static int create_into(int ni, int nj) {
    eg2d_grid *g = NULL;
    const int rc = eg2d_create(ni, nj, &g);
    eg2d_destroy(g);
    return rc;
}

/* Stops at the first call after an iteration (the set-up's calls, before
 * iteration 1, have no residual: +infinity). */
static int stop_after_iteration(void *user, int iteration, double residual) {
    (void)user;
    (void)iteration;
    return isfinite(residual);
}
static int stop_at_once(void *user, int iteration, double residual) {
    (void)user;
    (void)iteration;
    (void)residual;
    return 1;
}

/* One function per bad call; the setup of its row ran before. */
static int r_create_ni_2(eg2d_grid *g) { (void)g; return create_into(2, N); }
static int r_create_nj_neg(eg2d_grid *g) { (void)g; return create_into(N, -5); }
static int r_create_int_min(eg2d_grid *g) { (void)g; return create_into(INT_MIN, N); }
static int r_create_over_int(eg2d_grid *g) { (void)g; return create_into(46341, 46341); }
static int r_create_wraps_32(eg2d_grid *g) { (void)g; return create_into(65536, 65536); }
static int r_create_int_max(eg2d_grid *g) { (void)g; return create_into(INT_MAX, INT_MAX); }
static int r_create_null(eg2d_grid *g) { (void)g; return eg2d_create(N, N, NULL); }
static int r_create_huge(eg2d_grid *g) { (void)g; return create_into(46340, 46341); }
static int r_null_handle(eg2d_grid *g) { (void)g; return eg2d_solve(NULL); }
static int r_side_4(eg2d_grid *g) { double x[N], y[N]; unit_side(0, x, y); return eg2d_set_side(g, 4, x, y); }
static int r_side_null(eg2d_grid *g) { double y[N] = {0}; return eg2d_set_side(g, EG2D_SIDE_JMIN, NULL, y); }
static int r_side_nan(eg2d_grid *g) { return jmin_with(g, 3, NAN, 0); }
static int r_side_inf(eg2d_grid *g) { return jmin_with(g, 3, 0.375, -INFINITY); }
static int r_side_corner(eg2d_grid *g) { return jmin_with(g, 0, 0.25, 0); }
static int r_side_reversed(eg2d_grid *g) {
    double x[N], y[N];
    int p;
    unit_side(EG2D_SIDE_IMAX, x, y);
    for (p = 0; p < N; ++p) y[p] = 1 - y[p];
    return eg2d_set_side(g, EG2D_SIDE_IMAX, x, y);
}
static int r_boundary_nan(eg2d_grid *g) {
    double x[N * N], y[N * N];
    int k;
    for (k = 0; k < N * N; ++k) {
        x[k] = (double)(k % N) / (N - 1);
        y[k] = (double)(k / N) / (N - 1);
    }
    x[N * 4] = NAN; /* IMIN, point 4 */
    return eg2d_set_boundary(g, x, y);
}
static int r_ogrid_open(eg2d_grid *g) { double x[N], y[N]; unit_side(0, x, y); return eg2d_set_side(g, EG2D_SIDE_JMIN, x, y); }
static int r_ogrid_imin(eg2d_grid *g) { double x[N], y[N]; unit_side(3, x, y); return eg2d_set_side(g, EG2D_SIDE_IMIN, x, y); }
static int r_coords_nan(eg2d_grid *g) {
    double x[N * N], y[N * N];
    eg2d_get_coordinates(g, x, y);
    y[4 + N * 4] = NAN;
    return eg2d_set_coordinates(g, x, y);
}
/* The row j = 4 of the unit square, straight, with point p moved up by dy. */
static int line_with(eg2d_grid *g, int direction, int index, int p, double dy) {
    double x[N], y[N];
    int k;
    for (k = 0; k < N; ++k) {
        x[k] = (double)k / (N - 1);
        y[k] = 0.5;
    }
    y[p] += dy;
    return eg2d_set_interior_line(g, direction, index, x, y);
}
static int r_line_direction(eg2d_grid *g) { return line_with(g, 2, 4, 0, 0); }
static int r_line_index(eg2d_grid *g) { return line_with(g, EG2D_ETA, N - 1, 0, 0); }
static int r_line_null(eg2d_grid *g) { double y[N] = {0}; return eg2d_set_interior_line(g, EG2D_ETA, 4, NULL, y); }
static int r_line_nan(eg2d_grid *g) { return line_with(g, EG2D_ETA, 4, 2, NAN); }
static int r_line_end(eg2d_grid *g) { return line_with(g, EG2D_ETA, 4, 0, 0.01); }
static int r_line_ogrid_column(eg2d_grid *g) { return line_with(g, EG2D_XI, 4, 0, 0); }
static int r_line_march(eg2d_grid *g) {  /* the line is cleared again: only the failing call is observed */
    int rc = line_with(g, EG2D_ETA, 4, 0, 0);
    rc = rc ? rc : eg2d_initialize(g, EG2D_INIT_HYPERBOLIC);
    eg2d_clear_interior_lines(g);
    return rc;
}
static int r_hermite_side(eg2d_grid *g) { return eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SIDES, 16); }
static int r_hermite_height(eg2d_grid *g) { return eg2d_set_parameter(g, EG2D_PARAM_HERMITE_HEIGHT_JMIN, -0.1); }
static int r_init_no_boundary(eg2d_grid *g) { return eg2d_initialize(g, EG2D_INIT_TFI); }
static int r_init_method(eg2d_grid *g) { return eg2d_initialize(g, 77); }
static int r_system_3(eg2d_grid *g) { return eg2d_set_system(g, 3); }
static int r_weights_zero(eg2d_grid *g) { return eg2d_set_parameter(g, EG2D_PARAM_VARIATIONAL_SPACING, 0); }
static int r_weight_neg(eg2d_grid *g) { return eg2d_set_parameter(g, EG2D_PARAM_VARIATIONAL_AREA, -1); }
static int r_variational_fold(eg2d_grid *g) { eg2d_set_system(g, EG2D_SYSTEM_VARIATIONAL); return eg2d_solve(g); }
static int r_solver_99(eg2d_grid *g) { return eg2d_set_solver(g, 99); }
static int r_solver_neg(eg2d_grid *g) { return eg2d_set_solver(g, -1); }
static int r_topology_7(eg2d_grid *g) { return eg2d_set_topology(g, 7); }
static int r_omega_2(eg2d_grid *g) { return eg2d_set_relaxation(g, 2.0); }
static int r_omega_nan(eg2d_grid *g) { return eg2d_set_relaxation(g, NAN); }
static int r_tolerance_0(eg2d_grid *g) { return eg2d_set_tolerance(g, 0.0); }
static int r_tolerance_inf(eg2d_grid *g) { return eg2d_set_tolerance(g, INFINITY); }
static int r_maxit_0(eg2d_grid *g) { return eg2d_set_max_iterations(g, 0); }
static int r_maxit_frac(eg2d_grid *g) { return eg2d_set_parameter(g, EG2D_PARAM_MAX_ITERATIONS, 2.5); }
static int r_divfactor(eg2d_grid *g) { return eg2d_set_parameter(g, EG2D_PARAM_DIVERGENCE_FACTOR, 5); }
static int r_param_999(eg2d_grid *g) { return eg2d_set_parameter(g, 999, 1); }
static int r_march_no_jmin(eg2d_grid *g) { return eg2d_initialize(g, EG2D_INIT_HYPERBOLIC); }
static int r_march_out_of_reach(eg2d_grid *g) {
    /* 8 layers from 1e-3 cannot reach 100 at growth <= 1.2; the parameters are
     * put back so that only the failing call is observed. */
    int rc;
    eg2d_set_parameter(g, EG2D_PARAM_MARCH_DISTANCE, 100);
    eg2d_set_parameter(g, EG2D_PARAM_MARCH_FIRST_HEIGHT, 1e-3);
    rc = eg2d_initialize(g, EG2D_INIT_HYPERBOLIC);
    eg2d_set_parameter(g, EG2D_PARAM_MARCH_DISTANCE, 0);
    eg2d_set_parameter(g, EG2D_PARAM_MARCH_FIRST_HEIGHT, 0);
    return rc;
}
static int r_march_growth(eg2d_grid *g) { return eg2d_set_parameter(g, EG2D_PARAM_MARCH_GROWTH, 0.9); }
static int r_march_end(eg2d_grid *g) { return eg2d_set_parameter(g, EG2D_PARAM_MARCH_END_IMIN, 4); }
static int r_bounds_neg(eg2d_grid *g) { double a, b, c; (void)g; return eg2d_parameter_bounds(-7, &a, &b, &c); }
static int r_iterate_neg(eg2d_grid *g) { return eg2d_iterate(g, -1, NULL); }
static int r_iterate_early(eg2d_grid *g) { return eg2d_iterate(g, 1, NULL); }
static int r_coords_early(eg2d_grid *g) { double x[N * N], y[N * N]; return eg2d_get_coordinates(g, x, y); }
static int r_coords_null(eg2d_grid *g) { return eg2d_get_coordinates(g, NULL, NULL); }
static int r_quality_999(eg2d_grid *g) { double v; return eg2d_get_quality(g, 999, &v); }
static int r_wall_what(eg2d_grid *g) { double v; return eg2d_get_wall_layer(g, EG2D_SIDE_JMIN, 7, &v); }
static int r_wall_side(eg2d_grid *g) { double v; return eg2d_get_wall_layer(g, 4, EG2D_WALL_GROWTH, &v); }
static int r_wall_early(eg2d_grid *g) { double v; return eg2d_get_wall_layer(g, EG2D_SIDE_JMIN, EG2D_WALL_GROWTH, &v); }
static int r_not_converged(eg2d_grid *g) {
    eg2d_set_solver(g, EG2D_SOLVER_PSOR); /* the rows name their solver: the default may change */
    eg2d_set_max_iterations(g, 1);
    return eg2d_solve(g);
}
static int r_interrupted(eg2d_grid *g) {
    eg2d_set_monitor(g, stop_after_iteration, NULL);
    return eg2d_iterate(g, 5, NULL);
}
static int r_interrupted_set_up(eg2d_grid *g) {
    eg2d_set_parameter(g, EG2D_PARAM_MONITOR_SET_UP, 1);
    eg2d_set_monitor(g, stop_at_once, NULL);
    return eg2d_iterate(g, 5, NULL);
}
static int r_diverged(eg2d_grid *g) {
    eg2d_set_solver(g, EG2D_SOLVER_PSOR);
    eg2d_set_relaxation(g, 1.99);
    eg2d_set_parameter(g, EG2D_PARAM_DIVERGENCE_FACTOR, 10);
    return eg2d_solve(g);
}
static int r_huge_coords(eg2d_grid *g) { return set_square(g, 1e200); }
static int r_solve(eg2d_grid *g) { return eg2d_solve(g); }
static int r_folded(eg2d_grid *g) { eg2d_set_system(g, EG2D_SYSTEM_LAPLACE); return eg2d_solve(g); }
static int r_self_intersecting(eg2d_grid *g) {
    double x[N], y[N];
    int p;
    set_square(g, 1);
    unit_side(EG2D_SIDE_JMAX, x, y);
    for (p = 1; p < N - 1; ++p) y[p] = -0.5; /* JMAX dips below JMIN */
    eg2d_set_side(g, EG2D_SIDE_JMAX, x, y);
    return eg2d_solve(g);
}
static int r_init_oom(eg2d_grid *g) { return eg2d_initialize(g, EG2D_INIT_TFI); }
static int r_subnormal_curve(eg2d_grid *g) {
    double x[13], y[13];
    eg2d_curve *c = NULL;
    int p, rc;
    (void)g;
    for (p = 0; p < 13; ++p) { /* JMAX of a square of side 1.235e-314, as fuzz_api made it */
        x[p] = 1.2350678622161905e-314 * ((double)p / 12);
        y[p] = 1.2350678622161905e-314;
    }
    rc = eg2d_curve_polyline(13, x, y, &c);
    eg2d_curve_destroy(c);
    return rc;
}
static int r_huge_parameter_grid(eg2d_grid *g) {
    double ps[N * N], pt[N * N];
    int k;
    for (k = 0; k < N * N; ++k) {
        ps[k] = (double)(k % N) / (N - 1);
        pt[k] = (double)(k / N) / (N - 1);
    }
    int traps, rc;
    pt[N * N - 1] = DBL_MAX; /* a corner: the fold check does not see it */
    eg2d_set_parameter_grid(g, ps, pt);
    traps = fp_traps_pause(); /* the control's coefficients overflow (parameter_grid.cpp) before the refusal */
    rc = eg2d_solve(g);
    fp_traps_resume(traps);
    return rc;
}
static int r_tanh_subnormal(eg2d_grid *g) {
    double s[N];
    int k, rc;
    (void)g;
    rc = eg2d_distribution(EG2D_DIST_TANH_ONE, N, 4.9406564584124654e-324, 0, s);
    for (k = 0; rc == EG2D_OK && k < N; ++k)
        if (s[k] != (double)k / (N - 1)) return -1; /* the uniform limit, not NaN */
    return rc;
}
static int r_yplus_underflow(eg2d_grid *g) {
    double h;
    (void)g;
    return eg2d_first_cell_height(4.9406564584124654e-324, 1e6, 1, &h);
}
/* Unreachable first spacings: *p1 must be left as it was. */
static int parameter_untouched(int dist, double first) {
    double p1 = 42;
    const int rc = eg2d_distribution_parameter(dist, N, first, 0, &p1);
    return p1 == 42 ? rc : -1;
}
static int r_dparam_above(eg2d_grid *g) { (void)g; return parameter_untouched(EG2D_DIST_TANH_ONE, 0.2); }
static int r_dparam_uniform(eg2d_grid *g) { (void)g; return parameter_untouched(EG2D_DIST_EXPONENTIAL, 0.125); }
static int r_dparam_beyond(eg2d_grid *g) { (void)g; return parameter_untouched(EG2D_DIST_EXPONENTIAL, 1e-300); }
static int r_controls_early(eg2d_grid *g) { double P[N * N], Q[N * N]; return eg2d_get_controls(g, P, Q); }
static int r_huge_weight(eg2d_grid *g) {
    double w[N * N];
    int k;
    for (k = 0; k < N * N; ++k) w[k] = 1;
    w[40] = DBL_MAX;
    eg2d_set_weight(g, w);
    return eg2d_iterate(g, 3, NULL);
}

/* Files: `content` in a scratch file, then the call, then the file removed. */
static char scratch[4096];
static const char *scratch_file(const char *content) {
    const char *dir = getenv("TMPDIR");
    FILE *f;
    int fd;
    snprintf(scratch, sizeof scratch, "%s/eg2d-bad-input-XXXXXX", dir && *dir ? dir : "/tmp");
    fd = mkstemp(scratch);
    if (fd < 0 || !(f = fdopen(fd, "w"))) return "/nonexistent";
    fputs(content, f);
    fclose(f);
    return scratch;
}
static int done_with_file(int rc) {
    unlink(scratch);
    return rc;
}
static int r_plot3d_missing(eg2d_grid *g) {
    int ni;
    (void)g;
    return eg2d_read_plot3d("/nonexistent/grid.x", 0, NULL, NULL, &ni, NULL, NULL, NULL);
}
static int r_plot3d_truncated(eg2d_grid *g) {
    int ni;
    (void)g;
    return done_with_file(eg2d_read_plot3d(scratch_file("3 3\n0 1 2\n"), 0, NULL, NULL, &ni, NULL, NULL, NULL));
}
static int r_plot3d_block(eg2d_grid *g) {
    int ni;
    (void)g;
    return done_with_file(
        eg2d_read_plot3d(scratch_file("3 3\n0 1 2 0 1 2 0 1 2\n0 0 0 1 1 1 2 2 2\n"), 1, NULL, NULL, &ni, NULL, NULL, NULL));
}
/* A binary scratch file of n 32-bit words. */
static const char *scratch_words(const int *words, size_t n) {
    const char *dir = getenv("TMPDIR");
    int fd;
    snprintf(scratch, sizeof scratch, "%s/eg2d-bad-input-XXXXXX", dir && *dir ? dir : "/tmp");
    fd = mkstemp(scratch);
    if (fd < 0) return "/nonexistent";
    if (write(fd, words, n * sizeof *words) != (ssize_t)(n * sizeof *words)) {
        close(fd);
        return "/nonexistent";
    }
    close(fd);
    return scratch;
}
/* Headers that claim far more than the file holds: read under an
 * address-space limit, so a reader that believed them would fail with
 * EG2D_ERR_MEMORY (or be killed) instead of the format error. */
static int r_plot3d_huge_header(eg2d_grid *g) {
    /* 40000 x 40000 nodes (25.6 GB of coordinates), then a 16-byte record */
    const int words[] = {8, 40000, 40000, 8, 16, 0, 0, 0, 0, 16};
    int ni;
    (void)g;
    return done_with_file(eg2d_read_plot3d(scratch_words(words, 10), 0, NULL, NULL, &ni, NULL, NULL, NULL));
}
static int r_plot3d_huge_block_count(eg2d_grid *g) {
    /* a multi-grid file claiming 2^31-1 grids */
    const int words[] = {4, 2147483647, 4, 16, 3, 3, 3, 3, 16};
    int ni;
    (void)g;
    return done_with_file(eg2d_read_plot3d(scratch_words(words, 9), 0, NULL, NULL, &ni, NULL, NULL, NULL));
}
static int r_plot3d_ascii_huge(eg2d_grid *g) {
    int ni;
    (void)g;
    return done_with_file(eg2d_read_plot3d(scratch_file("40000 40000\n0 1 2 3\n"), 0, NULL, NULL, &ni, NULL, NULL, NULL));
}
/* A valid 1350 x 1350 binary Plot3D file (29.2 MB of coordinates), written
 * in small pieces, read under the 64 MB margin: the reader holds at most
 * 2.2 times the data (the file's bytes and the block's coordinates; 1500 x
 * 1500, 36 MB, does not fit). */
static int r_plot3d_big_valid(eg2d_grid *g) {
    enum { NI = 1350, NJ = 1350 };
    static double chunk[NI];
    const char *dir = getenv("TMPDIR");
    const int head[] = {8, NI, NJ, 8}, mark = 2 * NI * NJ * 8;
    int fd, k, ni = 0, nj = 0, rc;
    FILE *f;
    (void)g;
    snprintf(scratch, sizeof scratch, "%s/eg2d-bad-input-XXXXXX", dir && *dir ? dir : "/tmp");
    fd = mkstemp(scratch);
    if (fd < 0 || !(f = fdopen(fd, "wb"))) return -1;
    for (k = 0; k < NI; ++k) chunk[k] = k;
    fwrite(head, sizeof head, 1, f);
    fwrite(&mark, sizeof mark, 1, f);
    for (k = 0; k < 2 * NJ; ++k) fwrite(chunk, sizeof chunk, 1, f);
    fwrite(&mark, sizeof mark, 1, f);
    fclose(f);
    rc = done_with_file(eg2d_read_plot3d(scratch, 0, NULL, NULL, &ni, &nj, NULL, NULL));
    return rc == EG2D_OK && (ni != NI || nj != NJ) ? -1 : rc;
}
static int r_points_bad_line(eg2d_grid *g) {
    int n;
    (void)g;
    return done_with_file(eg2d_read_points(scratch_file("0 0\n1 0.5 # fine\nabc 2\n"), 0, &n, NULL, NULL));
}
static int r_points_capacity(eg2d_grid *g) {
    double x[2], y[2];
    int n;
    (void)g;
    return done_with_file(eg2d_read_points(scratch_file("0 0\n1 0\n2 0\n"), 2, &n, x, y));
}
static int r_side_from_file(eg2d_grid *g) {
    return done_with_file(eg2d_set_side_from_file(g, EG2D_SIDE_JMIN, scratch_file("0 0\n1 0\n2 0\n")));
}
static int r_lednicer_count(eg2d_grid *g) {
    eg2d_curve *c = NULL;
    (void)g;
    return done_with_file(eg2d_curve_read_airfoil(
        scratch_file("NACA\n3e33 2\n0 0\n0.5 0.1\n1 0\n0 0\n0.5 -0.1\n1 0\n"), &c));
}
static int r_write_no_dir(eg2d_grid *g) { return eg2d_write(g, "/nonexistent/grid.x", EG2D_FORMAT_PLOT3D); }
static int r_write_format(eg2d_grid *g) { return eg2d_write(g, "/nonexistent/grid.x", 99); }
static int r_cell_quality(eg2d_grid *g) {
    double v[(N - 1) * (N - 1)];
    return eg2d_get_cell_quality(g, EG2D_QUALITY_ORTHO_MAX_JMIN, v);
}

static int r_patch_overlap(eg2d_grid *g) {
    int rc = eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, 4, EG2D_PATCH_WALL, "plate");
    return rc ? rc : eg2d_set_patch(g, EG2D_SIDE_JMIN, 2, 6, EG2D_PATCH_INFLOW, "inlet");
}
static int r_patch_name(eg2d_grid *g) { return eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, 8, EG2D_PATCH_WALL, "my wall"); }
static int r_patch_ogrid_imin(eg2d_grid *g) { return eg2d_set_patch(g, EG2D_SIDE_IMIN, 0, 8, EG2D_PATCH_WALL, "x"); }
static int r_patch_cut_type(eg2d_grid *g) { return eg2d_set_patch(g, EG2D_SIDE_IMAX, 0, 8, EG2D_PATCH_CUT, "x"); }
static int r_patch_range(eg2d_grid *g) { return eg2d_set_patch(g, EG2D_SIDE_JMAX, 3, 9, EG2D_PATCH_WALL, "x"); }

/* Sets of blocks: the row's grid is block 0 of a set; block 1 is the unit
 * square moved right by `shift`. The set's message is the row's message. */
static char set_message[1024];
static eg2d_grid *second;
static eg2d_blocks *square_pair(eg2d_grid *g, double shift) {
    eg2d_blocks *set = NULL;
    double x[N], y[N];
    int side, p, b;
    if (eg2d_create(N, N, &second) != EG2D_OK) return NULL;
    for (side = 0; side < 4; ++side) {
        unit_side(side, x, y);
        for (p = 0; p < N; ++p) x[p] += shift;
        if (eg2d_set_side(second, side, x, y) != EG2D_OK) return NULL;
    }
    if (eg2d_blocks_create(&set) || eg2d_blocks_add(set, g, &b) || eg2d_blocks_add(set, second, &b)) return NULL;
    return set;
}
static int set_done(eg2d_blocks *set, int rc) {
    snprintf(set_message, sizeof set_message, "%s", eg2d_blocks_last_error(set));
    eg2d_blocks_destroy(set);
    eg2d_destroy(second);
    return rc;
}
static int r_blocks_create_null(eg2d_grid *g) {
    (void)g;
    return eg2d_blocks_create(NULL);
}
static int r_blocks_counts(eg2d_grid *g) {
    eg2d_blocks *set = square_pair(g, 1.0);
    return set_done(set, eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, 8, 1, EG2D_SIDE_IMIN, 0, 7));
}
static int r_blocks_twice(eg2d_grid *g) {
    eg2d_blocks *set = square_pair(g, 1.0);
    eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, 8, 1, EG2D_SIDE_IMIN, 0, 8);
    return set_done(set, eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 4, 6, 1, EG2D_SIDE_JMIN, 4, 6));
}
static int r_blocks_apart(eg2d_grid *g) {
    eg2d_blocks *set = square_pair(g, 1.5);
    eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, 8, 1, EG2D_SIDE_IMIN, 0, 8);
    return set_done(set, eg2d_blocks_check(set));
}
static int r_blocks_unconnected(eg2d_grid *g) {
    eg2d_blocks *set = square_pair(g, 1.0);
    return set_done(set, eg2d_blocks_solve(set));
}
static int r_blocks_controls(eg2d_grid *g) {
    eg2d_blocks *set = square_pair(g, 1.0);
    eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, 8, 1, EG2D_SIDE_IMIN, 0, 8);
    eg2d_set_system(g, EG2D_SYSTEM_LAPLACE);
    eg2d_set_system(second, EG2D_SYSTEM_LAPLACE);
    eg2d_set_wall_spacing(second, EG2D_SIDE_JMIN, 1e-3);
    return set_done(set, eg2d_blocks_solve(set));
}
static int r_blocks_destroyed(eg2d_grid *g) {
    eg2d_blocks *set = square_pair(g, 1.0);
    eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, 8, 1, EG2D_SIDE_IMIN, 0, 8);
    eg2d_destroy(second);
    if (eg2d_create(N, N, &second) != EG2D_OK) return -1;  /* for set_done to free */
    return set_done(set, eg2d_blocks_solve(set));
}

/*---------------------------------------------------------------------
 * The table
 *-------------------------------------------------------------------*/
typedef enum {
    S_NONE,   /* no handle: eg2d_create, a NULL handle; the message is eg2d_last_error(NULL) */
    S_FRESH,  /* a new N x N grid */
    S_SQUARE, /* the unit square's boundary */
    S_INIT,   /* the unit square, initialised by TFI */
    S_VALLEY, /* the elliptic-grid course notes' valley, 9 x 9 */
    S_SWAN,   /* the elliptic-grid course notes' swan, 33 x 33 */
    S_OGRID,  /* a fresh N x N grid with the O topology */
    S_TINY,   /* the square of side 1e-100 */
    S_POINT,  /* the square of side 0: every boundary point at (0, 0) */
    S_TRIANGLE, /* set_triangle */
    S_DUPLICATE, /* the unit square with JMIN's points 3 and 4 the same */
    S_VAR_LSOR, /* the unit square, EG2D_SYSTEM_VARIATIONAL, EG2D_SOLVER_LSOR */
    S_BIG     /* a 1000 x 1000 grid with the quad boundary */
} setup_kind;

#define KEEPS_WORK 1   /* a run: it keeps or restores its iterations, so "unchanged" is not asked */
#define MEMORY_LIMIT 2 /* the call runs in a child under an address-space limit */

typedef struct {
    const char *input;   /* the bad input, in words */
    const char *call;    /* the failing call */
    setup_kind setup;
    int (*run)(eg2d_grid *g);
    int code;
    const char *message; /* fnmatch pattern of the message; '*' where the numerics decide a value */
    int flags;
} bad_input;

static const bad_input rows[] = {
    {"ni below 3", "eg2d_create(2, 9, &g)", S_NONE, r_create_ni_2, EG2D_ERR_ARGUMENT,
     "eg2d_create: ni = 2: need at least 3", 0},
    {"negative nj", "eg2d_create(9, -5, &g)", S_NONE, r_create_nj_neg, EG2D_ERR_ARGUMENT,
     "eg2d_create: nj = -5: need at least 3", 0},
    {"ni = INT_MIN", "eg2d_create(INT_MIN, 9, &g)", S_NONE, r_create_int_min, EG2D_ERR_ARGUMENT,
     "eg2d_create: ni = -2147483648: need at least 3", 0},
    {"ni*nj just above INT_MAX", "eg2d_create(46341, 46341, &g)", S_NONE, r_create_over_int, EG2D_ERR_ARGUMENT,
     "eg2d_create: ni*nj = 46341*46341 overflows the node count", 0},
    {"ni*nj = 2^32 (wraps to 0 in 32 bits)", "eg2d_create(65536, 65536, &g)", S_NONE, r_create_wraps_32,
     EG2D_ERR_ARGUMENT, "eg2d_create: ni*nj = 65536*65536 overflows the node count", 0},
    {"ni = nj = INT_MAX", "eg2d_create(INT_MAX, INT_MAX, &g)", S_NONE, r_create_int_max, EG2D_ERR_ARGUMENT,
     "eg2d_create: ni*nj = 2147483647*2147483647 overflows the node count", 0},
    {"NULL result pointer", "eg2d_create(9, 9, NULL)", S_NONE, r_create_null, EG2D_ERR_ARGUMENT,
     "eg2d_create: grid is NULL", 0},
    {"2.1e9 nodes (17 GB per array) under a 64 MB address-space margin", "eg2d_create(46340, 46341, &g)", S_NONE,
     r_create_huge, EG2D_ERR_MEMORY, "eg2d_create: cannot allocate 2147441940 nodes", MEMORY_LIMIT},
    {"NULL handle (any call)", "eg2d_solve(NULL)", S_NONE, r_null_handle, EG2D_ERR_ARGUMENT,
     "eg2d_solve: grid is NULL", 0},
    {"side id out of range", "eg2d_set_side(g, 4, x, y)", S_FRESH, r_side_4, EG2D_ERR_ARGUMENT,
     "eg2d_set_side: side = 4: not one of EG2D_SIDE_JMIN (0), IMAX (1), JMAX (2), IMIN (3)", 0},
    {"NULL coordinate array", "eg2d_set_side(g, JMIN, NULL, y)", S_FRESH, r_side_null, EG2D_ERR_ARGUMENT,
     "eg2d_set_side: x is NULL", 0},
    {"NaN in a side", "eg2d_set_side(g, JMIN, x, y), x[3] = NaN", S_FRESH, r_side_nan, EG2D_ERR_ARGUMENT,
     "eg2d_set_side: JMIN x[3] = nan: coordinates must be finite", 0},
    {"-Inf in a side", "eg2d_set_side(g, JMIN, x, y), y[3] = -Inf", S_FRESH, r_side_inf, EG2D_ERR_ARGUMENT,
     "eg2d_set_side: JMIN y[3] = -inf: coordinates must be finite", 0},
    {"corner disagrees with the adjacent side", "eg2d_set_side(g, JMIN, x, y), x[0] = 0.25", S_SQUARE,
     r_side_corner, EG2D_ERR_BOUNDARY, "eg2d_set_side: corner JMIN/IMIN: (0.25, 0) vs (0, 0)", 0},
    {"reversed side (points in decreasing index)", "eg2d_set_side(g, IMAX, x, y), y = 1 - t", S_SQUARE,
     r_side_reversed, EG2D_ERR_BOUNDARY, "eg2d_set_side: corner JMIN/IMAX: (1, 0) vs (1, 1)", 0},
    {"NaN on the boundary ring", "eg2d_set_boundary(g, x, y), IMIN x[4] = NaN", S_FRESH, r_boundary_nan,
     EG2D_ERR_ARGUMENT, "eg2d_set_boundary: IMIN x[4] = nan: coordinates must be finite", 0},
    {"open curve on an O-grid", "eg2d_set_side(g, JMIN, x, y), first != last", S_OGRID, r_ogrid_open,
     EG2D_ERR_BOUNDARY, "eg2d_set_side: O-grid side JMIN is not closed: first point (0, 0) vs last (1, 0)", 0},
    {"a side the O-grid does not have", "eg2d_set_side(g, IMIN, x, y)", S_OGRID, r_ogrid_imin,
     EG2D_ERR_ARGUMENT, "eg2d_set_side: side IMIN: an O-grid has only the sides JMIN (inner) and JMAX (outer); IMIN/IMAX is its "
     "periodic cut", 0},
    {"NaN inside a start grid", "eg2d_set_coordinates(g, x, y), y[40] = NaN", S_INIT, r_coords_nan,
     EG2D_ERR_ARGUMENT, "eg2d_set_coordinates: y[40] = nan: coordinates must be finite", 0},
    {"initialise before the boundary", "eg2d_initialize(g, EG2D_INIT_TFI)", S_FRESH, r_init_no_boundary,
     EG2D_ERR_STATE, "eg2d_initialize: the boundary is not complete: side JMIN, IMAX, JMAX, IMIN not set", 0},
    {"unknown initialisation method", "eg2d_initialize(g, 77)", S_SQUARE, r_init_method, EG2D_ERR_ARGUMENT,
     "eg2d_initialize: initialisation method 77: no such method", 0},
    {"interior line: unknown direction", "eg2d_set_interior_line(g, 2, 4, x, y)", S_SQUARE, r_line_direction,
     EG2D_ERR_ARGUMENT, "eg2d_set_interior_line: direction = 2: not EG2D_XI (0, a column) or EG2D_ETA (1, a row)", 0},
    {"interior line on the boundary", "eg2d_set_interior_line(g, EG2D_ETA, 8, x, y)", S_SQUARE, r_line_index,
     EG2D_ERR_ARGUMENT, "eg2d_set_interior_line: eta line 8: the index must be in [1, 7] (an interior row)", 0},
    {"interior line: NULL points", "eg2d_set_interior_line(g, EG2D_ETA, 4, NULL, y)", S_SQUARE, r_line_null,
     EG2D_ERR_ARGUMENT, "eg2d_set_interior_line: x is NULL", 0},
    {"NaN in an interior line", "eg2d_set_interior_line(g, EG2D_ETA, 4, x, y), y[2] = NaN", S_SQUARE, r_line_nan,
     EG2D_ERR_ARGUMENT, "eg2d_set_interior_line: interior line y[2] = nan: coordinates must be finite", 0},
    {"interior line's end off the boundary", "eg2d_set_interior_line(g, EG2D_ETA, 4, x, y), y[0] = 0.51", S_SQUARE,
     r_line_end, EG2D_ERR_BOUNDARY,
     "eg2d_set_interior_line: eta line 4: its first point (0, 0.51000000000000001) is not side IMIN's node 4 (0, 0.5)",
     0},
    {"interior column on an O-grid", "eg2d_set_interior_line(g, EG2D_XI, 4, x, y)", S_OGRID, r_line_ogrid_column,
     EG2D_ERR_UNSUPPORTED,
     "eg2d_set_interior_line: a xi line (column 4) on the O-grid topology: interior columns are supported on single "
     "blocks only (rows on all three)", 0},
    {"hyperbolic march with an interior line", "eg2d_initialize(g, EG2D_INIT_HYPERBOLIC)", S_SQUARE, r_line_march,
     EG2D_ERR_STATE, "eg2d_initialize: hyperbolic writes every node: it cannot pass through the interior lines set "
     "(eg2d_clear_interior_lines, or a TFI method)", 0},
    {"Hermite sides: a mask above 15", "eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SIDES, 16)", S_FRESH, r_hermite_side,
     EG2D_ERR_ARGUMENT, "eg2d_set_parameter: hermite_sides = 16: must be in [0, 15]", 0},
    {"Hermite sides: a negative height", "eg2d_set_parameter(g, EG2D_PARAM_HERMITE_HEIGHT_JMIN, -0.1)", S_FRESH,
     r_hermite_height, EG2D_ERR_ARGUMENT, "eg2d_set_parameter: hermite_height_jmin = -0.1: must be in [0, 1e+30]", 0},
    {"unknown system", "eg2d_set_system(g, 3)", S_FRESH, r_system_3, EG2D_ERR_ARGUMENT,
     "eg2d_set_system: system = 3: not EG2D_SYSTEM_LAPLACE (0), EG2D_SYSTEM_WINSLOW (1) or "
     "EG2D_SYSTEM_VARIATIONAL (2)", 0},
    {"variational weights all 0", "eg2d_set_parameter(g, EG2D_PARAM_VARIATIONAL_SPACING, 0)", S_FRESH,
     r_weights_zero, EG2D_ERR_ARGUMENT,
     "eg2d_set_parameter: variational_area, variational_spacing, variational_orthogonality and "
     "variational_smoothness would all be 0: V = 0 has no minimiser (set the new weight before zeroing the old "
     "one)", 0},
    {"negative variational weight", "eg2d_set_parameter(g, EG2D_PARAM_VARIATIONAL_AREA, -1)", S_FRESH,
     r_weight_neg, EG2D_ERR_ARGUMENT, "eg2d_set_parameter: variational_area = -1: must be in [0, 1e+06]", 0},
    {"variational system with a line solver", "eg2d_solve(g), EG2D_SYSTEM_VARIATIONAL, EG2D_SOLVER_LSOR",
     S_VAR_LSOR, r_solve, EG2D_ERR_STATE,
     "eg2d_solve: the lsor solver does not solve the variational system (its line systems are Winslow's form); "
     "use one of: psor, multigrid, nested", 0},
    {"solver id not built in", "eg2d_set_solver(g, 99)", S_FRESH, r_solver_99, EG2D_ERR_UNSUPPORTED,
     "eg2d_set_solver: solver 99 is not built into this library", 0},
    {"negative solver id", "eg2d_set_solver(g, -1)", S_FRESH, r_solver_neg, EG2D_ERR_ARGUMENT,
     "eg2d_set_solver: solver = -1: no such solver id", 0},
    {"unknown topology", "eg2d_set_topology(g, 7)", S_FRESH, r_topology_7, EG2D_ERR_ARGUMENT,
     "eg2d_set_topology: topology = 7: not one of EG2D_TOPO_SINGLE, EG2D_TOPO_O, EG2D_TOPO_C", 0},
    {"relaxation at the bound 2", "eg2d_set_relaxation(g, 2.0)", S_FRESH, r_omega_2, EG2D_ERR_ARGUMENT,
     "eg2d_set_relaxation: relaxation = 2: must be in (0, 2) (or 0 for automatic)", 0},
    {"relaxation NaN", "eg2d_set_relaxation(g, NaN)", S_FRESH, r_omega_nan, EG2D_ERR_ARGUMENT,
     "eg2d_set_relaxation: relaxation = nan: must be finite", 0},
    {"tolerance 0", "eg2d_set_tolerance(g, 0)", S_FRESH, r_tolerance_0, EG2D_ERR_ARGUMENT,
     "eg2d_set_tolerance: tolerance = 0: must be in (0, 1)", 0},
    {"tolerance Inf", "eg2d_set_tolerance(g, Inf)", S_FRESH, r_tolerance_inf, EG2D_ERR_ARGUMENT,
     "eg2d_set_tolerance: tolerance = inf: must be finite", 0},
    {"iteration limit 0", "eg2d_set_max_iterations(g, 0)", S_FRESH, r_maxit_0, EG2D_ERR_ARGUMENT,
     "eg2d_set_max_iterations: max_iterations = 0: must be in [1, 1e+09]", 0},
    {"fractional integer parameter", "eg2d_set_parameter(g, EG2D_PARAM_MAX_ITERATIONS, 2.5)", S_FRESH,
     r_maxit_frac, EG2D_ERR_ARGUMENT, "eg2d_set_parameter: max_iterations = 2.5: must be a whole number", 0},
    {"divergence factor below 10", "eg2d_set_parameter(g, EG2D_PARAM_DIVERGENCE_FACTOR, 5)", S_FRESH,
     r_divfactor, EG2D_ERR_ARGUMENT, "eg2d_set_parameter: divergence_factor = 5: must be in [10, 1e+12]", 0},
    {"unknown parameter id", "eg2d_set_parameter(g, 999, 1)", S_FRESH, r_param_999, EG2D_ERR_ARGUMENT,
     "eg2d_set_parameter: parameter 999: no such parameter", 0},
    {"march without the curve to march from", "eg2d_initialize(g, EG2D_INIT_HYPERBOLIC)", S_FRESH, r_march_no_jmin,
     EG2D_ERR_STATE, "eg2d_initialize: hyperbolic: side JMIN, the curve to march from, is not set", 0},
    {"march schedule that cannot reach its distance", "MARCH_DISTANCE 100, MARCH_FIRST_HEIGHT 1e-3, 8 layers",
     S_SQUARE, r_march_out_of_reach, EG2D_ERR_ARGUMENT,
     "eg2d_initialize: march: 8 layers from a first height of 0.001 reach only * with growth 1.2, not the distance "
     "100: raise the first height, the growth limit or nj", 0},
    {"march growth limit below 1", "eg2d_set_parameter(g, EG2D_PARAM_MARCH_GROWTH, 0.9)", S_FRESH, r_march_growth,
     EG2D_ERR_ARGUMENT, "eg2d_set_parameter: march_growth = 0.9: must be in [1, 3]", 0},
    {"march end condition out of range", "eg2d_set_parameter(g, EG2D_PARAM_MARCH_END_IMIN, 4)", S_FRESH,
     r_march_end, EG2D_ERR_ARGUMENT, "eg2d_set_parameter: march_end_imin = 4: must be in [0, 3]", 0},
    {"unknown parameter id, no handle", "eg2d_parameter_bounds(-7, &lo, &hi, &def)", S_NONE, r_bounds_neg,
     EG2D_ERR_ARGUMENT, "eg2d_parameter_bounds: parameter -7: no such parameter", 0},
    {"negative iteration count", "eg2d_iterate(g, -1, NULL)", S_SQUARE, r_iterate_neg, EG2D_ERR_ARGUMENT,
     "eg2d_iterate: iterations = -1: must be >= 0", 0},
    {"iterate before the boundary", "eg2d_iterate(g, 1, NULL)", S_FRESH, r_iterate_early, EG2D_ERR_STATE,
     "eg2d_iterate: the boundary is not complete: side JMIN, IMAX, JMAX, IMIN not set", 0},
    {"coordinates before the interior", "eg2d_get_coordinates(g, x, y)", S_SQUARE, r_coords_early,
     EG2D_ERR_STATE, "eg2d_get_coordinates: coordinates: the grid has a boundary but no interior yet: call eg2d_initialize, "
     "eg2d_iterate or eg2d_solve first", 0},
    {"NULL output arrays", "eg2d_get_coordinates(g, NULL, NULL)", S_INIT, r_coords_null, EG2D_ERR_ARGUMENT,
     "eg2d_get_coordinates: x and y are both NULL", 0},
    {"unknown quality metric", "eg2d_get_quality(g, 999, &v)", S_INIT, r_quality_999, EG2D_ERR_ARGUMENT,
     "eg2d_get_quality: metric = 999: no such quality metric", 0},
    {"unknown wall-layer figure", "eg2d_get_wall_layer(g, EG2D_SIDE_JMIN, 7, &v)", S_INIT, r_wall_what,
     EG2D_ERR_ARGUMENT, "eg2d_get_wall_layer: what = 7: not an EG2D_WALL_* (0-6)", 0},
    {"wall layer of side 4", "eg2d_get_wall_layer(g, 4, EG2D_WALL_GROWTH, &v)", S_INIT, r_wall_side,
     EG2D_ERR_ARGUMENT, "eg2d_get_wall_layer: side = 4: not an EG2D_SIDE_* (0-3)", 0},
    {"wall layer before the interior", "eg2d_get_wall_layer(g, EG2D_SIDE_JMIN, EG2D_WALL_GROWTH, &v)", S_SQUARE,
     r_wall_early, EG2D_ERR_STATE, "eg2d_get_wall_layer: wall layer: the grid has a boundary but no interior yet: "
     "call eg2d_initialize, eg2d_iterate or eg2d_solve first", 0},
    {"control functions before the interior", "eg2d_get_controls(g, P, Q)", S_SQUARE, r_controls_early,
     EG2D_ERR_STATE, "eg2d_get_controls: controls: the grid has a boundary but no interior yet: call "
     "eg2d_initialize, eg2d_iterate or eg2d_solve first", 0},
    {"a first spacing above the uniform one for a clustering function",
     "eg2d_distribution_parameter(EG2D_DIST_TANH_ONE, 9, 0.2, 0, &p1)", S_NONE, r_dparam_above, EG2D_ERR_ARGUMENT,
     "eg2d_distribution_parameter: first_spacing = 0.2: not reachable with n = 9: over tanh delta in (0, 700] the "
     "first spacing stays within [*, 0.125] (it clusters at s = 0: its first spacing is below the uniform 1/(n-1))",
     0},
    {"the uniform first spacing (the parameter would be 0)",
     "eg2d_distribution_parameter(EG2D_DIST_EXPONENTIAL, 9, 0.125, 0, &p1)", S_NONE, r_dparam_uniform,
     EG2D_ERR_ARGUMENT,
     "eg2d_distribution_parameter: first_spacing = 0.125 is the uniform spacing 1/(n-1) with n = 9: that is "
     "EG2D_DIST_UNIFORM (exponential beta in [-700, 700] would be 0)",
     0},
    {"a first spacing beyond the parameter's bound",
     "eg2d_distribution_parameter(EG2D_DIST_EXPONENTIAL, 9, 1e-300, 0, &p1)", S_NONE, r_dparam_beyond,
     EG2D_ERR_ARGUMENT,
     "eg2d_distribution_parameter: first_spacing = 1e-300: not reachable with n = 9: over exponential beta in "
     "[-700, 700] the first spacing stays within [*, *]",
     0},
    {"Plot3D file that does not exist", "eg2d_read_plot3d(\"/nonexistent/grid.x\", 0, ...)", S_NONE,
     r_plot3d_missing, EG2D_ERR_IO,
     "eg2d_read_plot3d: /nonexistent/grid.x: cannot open: No such file or directory", 0},
    {"truncated Plot3D file", "eg2d_read_plot3d(path, 0, ...), \"3 3\\n0 1 2\\n\"", S_NONE,
     r_plot3d_truncated, EG2D_ERR_IO,
     "eg2d_read_plot3d: */eg2d-bad-input-*: not a Plot3D grid file: its 5 numbers fit no 2D/3D, single-/multi-grid "
     "layout (truncated?)", 0},
    {"binary Plot3D header claiming 40000 x 40000 nodes, 40 bytes in all", "eg2d_read_plot3d(path, 0, ...)", S_NONE,
     r_plot3d_huge_header, EG2D_ERR_IO,
     "eg2d_read_plot3d: */eg2d-bad-input-*: not a Plot3D grid file: it has NUL bytes (binary) but no Plot3D binary "
     "layout fits its size", MEMORY_LIMIT},
    {"binary Plot3D header claiming 2147483647 grids", "eg2d_read_plot3d(path, 0, ...)", S_NONE,
     r_plot3d_huge_block_count, EG2D_ERR_IO,
     "eg2d_read_plot3d: */eg2d-bad-input-*: not a Plot3D grid file: it has NUL bytes (binary) but no Plot3D binary "
     "layout fits its size", MEMORY_LIMIT},
    {"a valid 1350 x 1350 binary Plot3D file, 29.2 MB of coordinates (at most 2.2x in memory)", "eg2d_read_plot3d(path, 0, ...)", S_NONE,
     r_plot3d_big_valid, EG2D_OK, "", MEMORY_LIMIT},
    {"text Plot3D header claiming 40000 x 40000 nodes", "eg2d_read_plot3d(path, 0, ...), \"40000 40000\\n0 1 2 3\\n\"", S_NONE,
     r_plot3d_ascii_huge, EG2D_ERR_IO,
     "eg2d_read_plot3d: */eg2d-bad-input-*: not a Plot3D grid file: its 6 numbers fit no 2D/3D, single-/multi-grid "
     "layout (truncated?)", MEMORY_LIMIT},
    {"Plot3D block the file does not have", "eg2d_read_plot3d(path, 1, ...), one block", S_NONE, r_plot3d_block,
     EG2D_ERR_ARGUMENT, "eg2d_read_plot3d: block = 1: */eg2d-bad-input-* has 1 grid(s)", 0},
    {"point file line that is not two numbers", "eg2d_read_points(path, 0, &n, NULL, NULL), line 3 \"abc 2\"",
     S_NONE, r_points_bad_line, EG2D_ERR_IO,
     "eg2d_read_points: */eg2d-bad-input-*:3: \"abc 2\": expected two numbers x y", 0},
    {"more points than the capacity", "eg2d_read_points(path, 2, &n, x, y), 3 points", S_NONE, r_points_capacity,
     EG2D_ERR_ARGUMENT, "eg2d_read_points: */eg2d-bad-input-* holds 3 points, more than capacity = 2", 0},
    {"point file with the wrong number of points for the side", "eg2d_set_side_from_file(g, JMIN, path), 3 of 9",
     S_FRESH, r_side_from_file, EG2D_ERR_BOUNDARY,
     "eg2d_set_side_from_file: */eg2d-bad-input-* holds 3 points; side JMIN has 9", 0},
    {"write into a directory that does not exist", "eg2d_write(g, \"/nonexistent/grid.x\", EG2D_FORMAT_PLOT3D)",
     S_INIT, r_write_no_dir, EG2D_ERR_IO,
     "eg2d_write: /nonexistent/grid.x: cannot create a file in its directory: No such file or directory", 0},
    {"unknown file format", "eg2d_write(g, path, 99)", S_INIT, r_write_format, EG2D_ERR_ARGUMENT,
     "eg2d_write: format = 99: no such file format", 0},
    {"per-cell values of a summary-only metric", "eg2d_get_cell_quality(g, EG2D_QUALITY_ORTHO_MAX_JMIN, v)",
     S_INIT, r_cell_quality, EG2D_ERR_ARGUMENT,
     "eg2d_get_cell_quality: metric = 40 (ortho_max_jmin): a boundary summary with no per-cell values", 0},
    {"iteration limit reached", "eg2d_solve(g), PSOR, max_iterations = 1", S_VALLEY, r_not_converged,
     EG2D_ERR_NOT_CONVERGED, "eg2d_solve: psor did not converge in 1 iterations: residual * > tolerance 1e-08",
     KEEPS_WORK},
    {"monitor asks to stop", "eg2d_iterate(g, 5, NULL), monitor returns 1 after an iteration", S_VALLEY,
     r_interrupted, EG2D_ERR_INTERRUPTED, "eg2d_iterate: stopped by the monitor at iteration 1 (residual *)",
     KEEPS_WORK},
    {"monitor asks to stop during the set-up", "eg2d_iterate(g, 5, NULL), EG2D_PARAM_MONITOR_SET_UP 1, monitor "
     "returns 1 (first call: the set-up's, residual +infinity)", S_VALLEY, r_interrupted_set_up, EG2D_ERR_INTERRUPTED,
     "eg2d_iterate: stopped by the monitor before iteration 1, during the set-up (the wall layer, the start grid): "
     "nothing changed", KEEPS_WORK},  /* it sets the parameter itself; test_monitor_setup.c compares the grid */
    {"over-relaxation that diverges (omega 1.99)", "eg2d_solve(g), PSOR, relaxation 1.99, divergence factor 10",
     S_VALLEY, r_diverged, EG2D_ERR_DIVERGED,
     "eg2d_solve: psor diverged at iteration *: residual * is more than 10 times the run's best * "
     "(largest at node (*, *)); the grid is restored to iteration *",
     KEEPS_WORK},
    {"coordinates of 1e200 (the metric terms would overflow)", "eg2d_set_side(g, JMIN, x, y), x[1] = 1.25e199",
     S_FRESH, r_huge_coords, EG2D_ERR_ARGUMENT,
     "eg2d_set_side: JMIN x[1] = 1.25e+199: coordinates must be within +-1e+30 (the metric terms grow as their "
     "fourth power)",
     0},
    {"a domain of size 1e-100 (the residual would underflow)", "eg2d_solve(g), square of side 1e-100", S_TINY,
     r_solve, EG2D_ERR_BOUNDARY,
     "eg2d_solve: the boundary's extent (bounding-box diagonal) is 1.41421e-100, below 1e-75: the points "
     "(nearly) coincide, or the domain needs scaling",
     0},
    {"every boundary point the same", "eg2d_iterate(g, 1, NULL), square of side 0", S_POINT, r_iterate_early,
     EG2D_ERR_BOUNDARY,
     "eg2d_iterate: the boundary's extent (bounding-box diagonal) is 0, below 1e-75: the points (nearly) "
     "coincide, or the domain needs scaling",
     0},
    {"self-intersecting boundary (JMAX below JMIN)", "eg2d_solve(g)", S_FRESH, r_self_intersecting,
     EG2D_ERR_BOUNDARY, "eg2d_solve: the boundary crosses itself: JMIN segment 0-1 crosses JMAX segment 0-1 near (*, 0)",
     0},
    {"Laplace on a concave domain (swan)", "eg2d_solve(g), EG2D_SYSTEM_LAPLACE", S_SWAN, r_folded,
     EG2D_ERR_FOLDED,
     "eg2d_solve: the converged grid has * folded cells; the first is cell (*, *) (cells are numbered by their "
     "lowest node)",
     KEEPS_WORK},
    {"variational minimum that folds (swan, S alone)", "eg2d_solve(g), EG2D_SYSTEM_VARIATIONAL", S_SWAN,
     r_variational_fold, EG2D_ERR_NOT_CONVERGED,
     "eg2d_solve: variational: the gradient norm fell by less than 1.25 in 10 cycles (best *) while the fold guard "
     "shortened * node steps: the minimum of V for these weights folds or collapses cells, and the grid is kept "
     "unfolded short of it. Raise the area weight, or set EG2D_PARAM_FOLD_CHECK to 0 for the unconstrained minimum",
     KEEPS_WORK},
    {"a zero-length side (IMIN a single point: a triangle)", "eg2d_solve(g)", S_TRIANGLE, r_solve, EG2D_OK,
     "", KEEPS_WORK},
    {"a duplicate point in a side", "eg2d_solve(g), JMIN point 4 = point 3", S_DUPLICATE, r_solve, EG2D_OK, "",
     KEEPS_WORK},
    {"a curve 1.2e-314 long (subnormal: the arc-length panels never converged, a hang before)",
     "eg2d_curve_polyline(13, x, y, &c)", S_NONE, r_subnormal_curve, EG2D_ERR_ARGUMENT,
     "eg2d_curve_polyline: the curve's arc length does not converge to 1e-14 of its length within 65536 panels: "
     "the curve is not smooth, or too small (length *)",
     0},
    {"a parameter-grid value of DBL_MAX (the residual was NaN before)", "eg2d_solve(g), t[80] = DBL_MAX",
     S_INIT, r_huge_parameter_grid, EG2D_ERR_ARGUMENT,
     "eg2d_solve: the equations are not finite at node (7, 7) of the grid as it is: a control value (source, "
     "source array, weight, parameter grid) is too large",
     KEEPS_WORK},
    {"a tanh distribution with a subnormal delta (NaN points before)",
     "eg2d_distribution(EG2D_DIST_TANH_ONE, 9, 5e-324, 0, s): the uniform points", S_NONE, r_tanh_subnormal, EG2D_OK,
     "", 0},
    {"a y+ so small the wall height underflows to 0", "eg2d_first_cell_height(5e-324, 1e6, 1, &h)", S_NONE,
     r_yplus_underflow, EG2D_ERR_ARGUMENT,
     "eg2d_first_cell_height: y+ = 4.94066e-324, chord = 1: the height 0 is not a positive finite number", 0},
    {"Lednicer header announcing 3e33 points (undefined conversion to size_t before)",
     "eg2d_curve_read_airfoil(path, &c), line 2 \"3e33 2\"", S_NONE, r_lednicer_count, EG2D_ERR_ARGUMENT,
     "eg2d_curve_read_airfoil: Lednicer file \"*/eg2d-bad-input-*\" (line 2): announces 3e+33 + 2 points but has 6 "
     "(3 + 3: the lower surface starts at line 6, where x returns to the leading edge): correct the counts",
     0},
    {"a weight of DBL_MAX (the control's sums overflowed before)", "eg2d_iterate(g, 3, NULL), w[40] = DBL_MAX",
     S_INIT, r_huge_weight, EG2D_OK, "", KEEPS_WORK},
    {"a boundary patch overlapping another", "eg2d_set_patch(g, EG2D_SIDE_JMIN, 2, 6, EG2D_PATCH_INFLOW, \"inlet\")",
     S_SQUARE, r_patch_overlap, EG2D_ERR_ARGUMENT,
     "eg2d_set_patch: side JMIN nodes [2, 6] overlap patch \"plate\" [0, 4]; set the same range to replace it, or "
     "eg2d_clear_patches",
     0},
    {"a patch name with a space", "eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, 8, EG2D_PATCH_WALL, \"my wall\")", S_SQUARE,
     r_patch_name, EG2D_ERR_ARGUMENT,
     "eg2d_set_patch: name \"my wall\": character 3 is not a letter, digit, '_' or '-'", 0},
    {"a patch on the side an O-grid lacks", "eg2d_set_patch(g, EG2D_SIDE_IMIN, 0, 8, EG2D_PATCH_WALL, \"x\")",
     S_OGRID, r_patch_ogrid_imin, EG2D_ERR_ARGUMENT,
     "eg2d_set_patch: side IMIN: the O-grid topology has no such side (its i-cut is periodic)", 0},
    {"a patch of the reported-only type CUT", "eg2d_set_patch(g, EG2D_SIDE_IMAX, 0, 8, EG2D_PATCH_CUT, \"x\")",
     S_SQUARE, r_patch_cut_type, EG2D_ERR_ARGUMENT,
     "eg2d_set_patch: type = 5: not one of EG2D_PATCH_WALL (0), FARFIELD (1), OUTFLOW (2), INFLOW (3), SYMMETRY "
     "(4); a cut is the topology's",
     0},
    {"a patch beyond the side's last node", "eg2d_set_patch(g, EG2D_SIDE_JMAX, 3, 9, EG2D_PATCH_WALL, \"x\")",
     S_SQUARE, r_patch_range, EG2D_ERR_ARGUMENT,
     "eg2d_set_patch: first = 3, last = 9: need 0 <= first < last <= 8 (side JMAX has 9 nodes)", 0},
    {"NULL result pointer for a set", "eg2d_blocks_create(NULL)", S_NONE, r_blocks_create_null, EG2D_ERR_ARGUMENT,
     "eg2d_blocks_create: set is NULL", 0},
    {"a join whose sides' node counts differ", "eg2d_blocks_join(set, 0, IMAX, 0, 8, 1, IMIN, 0, 7)", S_SQUARE,
     r_blocks_counts, EG2D_ERR_ARGUMENT,
     "eg2d_blocks_join: join: block 0 side IMAX nodes 0..8 has 9 nodes, block 1 side IMIN nodes 0..7 has 8: joins "
     "match node to node",
     0},
    {"a side's nodes joined twice", "eg2d_blocks_join(set, 0, IMAX, 4, 6, 1, JMIN, 4, 6)", S_SQUARE, r_blocks_twice,
     EG2D_ERR_ARGUMENT,
     "eg2d_blocks_join: join: block 0 side IMAX nodes 4..6 is joined already (to block 1 side IMIN nodes 0..8)", 0},
    {"joined nodes that do not coincide", "eg2d_blocks_check(set)", S_SQUARE, r_blocks_apart, EG2D_ERR_BOUNDARY,
     "eg2d_blocks_check: join block 0 side IMAX nodes 0..8 to block 1 side IMIN nodes 0..8: node 0 of block 0's side "
     "IMAX = (1, 0) and node 0 of block 1's side IMIN = (1.5, 0) are 0.5 apart (tolerance *)",
     0},
    {"a set whose blocks are not joined", "eg2d_blocks_solve(set)", S_SQUARE, r_blocks_unconnected, EG2D_ERR_STATE,
     "eg2d_blocks_solve: the set is not connected: no chain of joins from block 0 to block 1", 0},
    {"a set of Laplace blocks with a wall control", "eg2d_blocks_solve(set)", S_SQUARE, r_blocks_controls,
     EG2D_ERR_STATE,
     "eg2d_blocks_solve: block 1 has control terms but the system is Laplace: controls need EG2D_SYSTEM_WINSLOW (or "
     "clear the controls)",
     0},
    {"a block destroyed while in a set", "eg2d_blocks_solve(set)", S_SQUARE, r_blocks_destroyed, EG2D_ERR_STATE,
     "eg2d_blocks_solve: block 1 was destroyed", 0},
    {"an allocation during a call fails (1000 x 1000, 4 MB margin)", "eg2d_initialize(g, EG2D_INIT_TFI)", S_BIG,
     r_init_oom, EG2D_ERR_MEMORY, "eg2d_initialize: out of memory", MEMORY_LIMIT},
};
#define NROWS (sizeof rows / sizeof rows[0])

static const char *code_name(int code) {
    switch (code) {
    case EG2D_OK: return "EG2D_OK (accepted)";
    case EG2D_ERR_ARGUMENT: return "EG2D_ERR_ARGUMENT";
    case EG2D_ERR_MEMORY: return "EG2D_ERR_MEMORY";
    case EG2D_ERR_BOUNDARY: return "EG2D_ERR_BOUNDARY";
    case EG2D_ERR_STATE: return "EG2D_ERR_STATE";
    case EG2D_ERR_NOT_CONVERGED: return "EG2D_ERR_NOT_CONVERGED";
    case EG2D_ERR_DIVERGED: return "EG2D_ERR_DIVERGED";
    case EG2D_ERR_FOLDED: return "EG2D_ERR_FOLDED";
    case EG2D_ERR_IO: return "EG2D_ERR_IO";
    case EG2D_ERR_UNSUPPORTED: return "EG2D_ERR_UNSUPPORTED";
    case EG2D_ERR_INTERRUPTED: return "EG2D_ERR_INTERRUPTED";
    }
    return "?";
}

/*---------------------------------------------------------------------
 * Checking one row (no cmocka asserts here: it also runs in a child)
 *-------------------------------------------------------------------*/
static char why[1024]; /* the reason of a failed check */

static int failed(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, sizeof why, fmt, ap);
    va_end(ap);
    return 1;
}

static void row_size(const bad_input *r, int *ni, int *nj) {
    *ni = *nj = r->setup == S_BIG ? 1000 : r->setup == S_SWAN ? 33 : N;
}

static int setup(const bad_input *r, eg2d_grid *g) {
    switch (r->setup) {
    case S_NONE:
    case S_FRESH: return EG2D_OK;
    case S_SQUARE: return set_square(g, 1);
    case S_INIT: return set_square(g, 1) || eg2d_initialize(g, EG2D_INIT_TFI);
    case S_VALLEY: return domain_set(g, "valley");
    case S_SWAN: return domain_set(g, "swan");
    case S_OGRID: return eg2d_set_topology(g, EG2D_TOPO_O);
    case S_TINY: return set_square(g, 1e-100);
    case S_POINT: return set_square(g, 0);
    case S_TRIANGLE: return set_triangle(g);
    case S_DUPLICATE: return set_square(g, 1) || jmin_with(g, 4, 0.375, 0);
    case S_VAR_LSOR:
        return set_square(g, 1) || eg2d_set_system(g, EG2D_SYSTEM_VARIATIONAL) ||
               eg2d_set_solver(g, EG2D_SOLVER_LSOR);
    case S_BIG: return domain_set(g, "quad");
    }
    return EG2D_ERR_ARGUMENT;
}

/* Everything a caller can observe of a grid. */
typedef struct {
    int ni, nj, topology, solver, iterations, rc_coords, rc_residual;
    double params[300], residual;
    double *x, *y;
} observed;

static void observe(eg2d_grid *g, observed *o) {
    int k;
    double lo, hi, def;
    memset(o, 0, sizeof *o);
    eg2d_get_size(g, &o->ni, &o->nj);
    eg2d_get_topology(g, &o->topology);
    eg2d_get_solver(g, &o->solver);
    eg2d_get_iterations(g, &o->iterations);
    for (k = 0; k < 300; ++k)
        if (eg2d_parameter_bounds(k, &lo, &hi, &def) == EG2D_OK) eg2d_get_parameter(g, k, &o->params[k]);
    o->x = calloc((size_t)o->ni * (size_t)o->nj, sizeof(double));
    o->y = calloc((size_t)o->ni * (size_t)o->nj, sizeof(double));
    o->rc_coords = eg2d_get_coordinates(g, o->x, o->y);
    o->rc_residual = eg2d_get_residual(g, &o->residual);
}

static int same(const observed *a, const observed *b) {
    const size_t n = (size_t)a->ni * (size_t)a->nj * sizeof(double);
    return a->ni == b->ni && a->nj == b->nj && a->topology == b->topology && a->solver == b->solver &&
           a->iterations == b->iterations && a->rc_coords == b->rc_coords && a->rc_residual == b->rc_residual &&
           memcmp(a->params, b->params, sizeof a->params) == 0 && memcmp(&a->residual, &b->residual, sizeof(double)) == 0 &&
           memcmp(a->x, b->x, n) == 0 && memcmp(a->y, b->y, n) == 0;
}

static void forget(observed *o) {
    free(o->x);
    free(o->y);
}

/* The good sequence: every setting back to its default, the quad domain,
 * TFI, then a solve (big grids: 2 iterations). Fills *o with the result. */
static int good_sequence(eg2d_grid *g, observed *o) {
    int k, ni, nj;
    double lo, hi, def;
    eg2d_get_size(g, &ni, &nj);
    for (k = 0; k < 300; ++k)
        if (eg2d_parameter_bounds(k, &lo, &hi, &def) == EG2D_OK && eg2d_set_parameter(g, k, def) != EG2D_OK)
            return failed("resetting parameter %d: %s", k, eg2d_last_error(g));
    /* Controls the row may have set are the user's settings, not damage. */
    if (eg2d_set_weight(g, NULL) || eg2d_clear_sources(g) || eg2d_set_source_arrays(g, NULL, NULL) ||
        eg2d_set_parameter_grid(g, NULL, NULL) || eg2d_set_orthogonality(g, EG2D_ORTHO_NONE))
        return failed("clearing the controls failed: %s", eg2d_last_error(g));
    if (eg2d_set_system(g, EG2D_SYSTEM_WINSLOW) || eg2d_set_solver(g, EG2D_SOLVER_PSOR) ||
        eg2d_set_monitor(g, NULL, NULL) || eg2d_set_topology(g, EG2D_TOPO_SINGLE) || domain_set(g, "quad") ||
        eg2d_initialize(g, EG2D_INIT_TFI))
        return failed("the good sequence's setup failed: %s", eg2d_last_error(g));
    k = ni * nj > 10000 ? eg2d_iterate(g, 2, NULL) : eg2d_solve(g);
    if (k != EG2D_OK) return failed("the good sequence's run failed: %s", eg2d_last_error(g));
    observe(g, o);
    return 0;
}

static int address_space_limit(size_t margin) {
    long pages = 0;
    FILE *f = fopen("/proc/self/statm", "r");
    struct rlimit rl;
    if (!f || fscanf(f, "%ld", &pages) != 1) {
        if (f) fclose(f);
        return failed("cannot read /proc/self/statm");
    }
    fclose(f);
    getrlimit(RLIMIT_AS, &rl);
    rl.rlim_cur = (rlim_t)pages * (rlim_t)sysconf(_SC_PAGESIZE) + margin;
    return setrlimit(RLIMIT_AS, &rl) != 0 ? failed("setrlimit failed") : 0;
}

static void address_space_unlimited(void) {
    struct rlimit rl;
    getrlimit(RLIMIT_AS, &rl);
    rl.rlim_cur = rl.rlim_max;
    setrlimit(RLIMIT_AS, &rl);
}

/* Whether text matches pattern, where '*' stands for any run of characters
 * (and nothing else is special: messages contain [ ] and ?). */
static int matches(const char *pattern, const char *text) {
    if (*pattern == '\0') return *text == '\0';
    if (*pattern == '*') {
        do {
            if (matches(pattern + 1, text)) return 1;
        } while (*text++);
        return 0;
    }
    return *pattern == *text && matches(pattern + 1, text + 1);
}

/* Runs row r; 0 when it behaves, else 1 with the reason in why. */
static int check_row(const bad_input *r) {
    eg2d_grid *g = NULL, *fresh = NULL;
    observed before, after, good, reference;
    const char *message;
    int ni, nj, rc, bad = 0;
    row_size(r, &ni, &nj);
    if (r->setup != S_NONE) {
        if (eg2d_create(ni, nj, &g) != EG2D_OK) return failed("create: %s", eg2d_last_error(NULL));
        if (setup(r, g) != EG2D_OK) return failed("setup: %s", eg2d_last_error(g));
        observe(g, &before);
    }
    if ((r->flags & MEMORY_LIMIT) && address_space_limit(r->setup == S_NONE ? 64u << 20 : 4u << 20)) return 1;
    set_message[0] = 0;
    rc = r->run(g);
    if (r->flags & MEMORY_LIMIT) address_space_unlimited();
    message = rc == EG2D_OK ? "" : set_message[0] ? set_message : eg2d_last_error(g);
    if (rc != r->code)
        bad = failed("returned %d (%s), expected %s: \"%s\"", rc, code_name(rc), code_name(r->code), message);
    else if (!matches(r->message, message))
        bad = failed("message \"%s\" does not match \"%s\"", message, r->message);
    if (r->setup != S_NONE) {
        if (!bad && !(r->flags & KEEPS_WORK)) {
            observe(g, &after);
            if (!same(&before, &after)) bad = failed("the failed call changed the grid");
            forget(&after);
        }
        forget(&before);
    } else if (eg2d_create(ni, nj, &g) != EG2D_OK) {
        return failed("a good eg2d_create after the failure failed: %s", eg2d_last_error(NULL));
    }
    /* Usable: the good sequence gives what it gives on a fresh handle. */
    if (!bad && !good_sequence(g, &good)) {
        if (eg2d_create(ni, nj, &fresh) != EG2D_OK || good_sequence(fresh, &reference))
            bad = failed("the reference run failed");
        else if (!same(&good, &reference))
            bad = failed("after the failure the good sequence gives a different grid than on a fresh handle");
        else
            forget(&reference);
        forget(&good);
    } else {
        bad = 1;
    }
    eg2d_destroy(fresh);
    eg2d_destroy(g);
    return bad;
}

static int running_on_valgrind(void) {
    const char *p = getenv("LD_PRELOAD");
    return p && strstr(p, "vgpreload") != NULL;
}

/* Memory-limit rows run in a child: its address space is its own, and an
 * abort there is seen as a failure rather than the end of the test run. */
static int check_row_in_child(const bad_input *r) {
    int fd[2], status = 0;
    pid_t pid;
    ssize_t n;
    if (pipe(fd) != 0) return failed("pipe failed");
    pid = fork();
    if (pid < 0) return failed("fork failed");
    if (pid == 0) {
        const int bad = check_row(r);
        close(fd[0]);
        if (bad && write(fd[1], why, strlen(why) + 1) < 0) _exit(3);
        _exit(bad ? 1 : 0);
    }
    close(fd[1]);
    memset(why, 0, sizeof why);
    n = read(fd[0], why, sizeof why - 1);
    close(fd[0]);
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) return failed("the child died of signal %d (an abort is a failure)", WTERMSIG(status));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        if (n <= 0) failed("the child exited with status %d", WEXITSTATUS(status));
        return 1;
    }
    return 0;
}

static void test_row(void **state) {
    const bad_input *r = (const bad_input *)*state;
    int bad;
    if (r->flags & MEMORY_LIMIT) {
        if (ALLOCATOR_REPLACED || running_on_valgrind()) {
            print_message("skipped: a sanitizer or valgrind allocator aborts on failure instead of throwing\n");
            skip();
        }
        bad = check_row_in_child(r);
    } else {
        bad = check_row(r);
    }
    if (bad) fail_msg("%s: %s: %s", r->input, r->call, why);
}

/*---------------------------------------------------------------------
 * Divergence restores the last good grid
 *-------------------------------------------------------------------*/
static int restored_to(const char *message) {
    const char *p = strstr(message, "restored to iteration ");
    assert_non_null(p);
    return atoi(p + strlen("restored to iteration "));
}

/* Valley with point SOR at omega 1.99 diverges after K good iterations: the grid left is
 * bitwise the grid of K iterations from the same start, done without failing;
 * same for eg2d_iterate. */
static void test_divergence_restores_last_good_grid(void **state) {
    eg2d_grid *a, *b;
    double xa[N * N], ya[N * N], xb[N * N], yb[N * N], ra, rb;
    int k, it, use_iterate;
    (void)state;
    for (use_iterate = 0; use_iterate < 2; ++use_iterate) {
        assert_int_equal(eg2d_create(N, N, &a), EG2D_OK);
        assert_int_equal(domain_set(a, "valley"), EG2D_OK);
        assert_int_equal(eg2d_set_solver(a, EG2D_SOLVER_PSOR), EG2D_OK);
        assert_int_equal(eg2d_set_relaxation(a, 1.99), EG2D_OK);
        assert_int_equal(eg2d_set_parameter(a, EG2D_PARAM_DIVERGENCE_FACTOR, 10), EG2D_OK);
        assert_int_equal(use_iterate ? eg2d_iterate(a, 100000, NULL) : eg2d_solve(a), EG2D_ERR_DIVERGED);
        k = restored_to(eg2d_last_error(a));
        assert_true(k > 10); /* it diverges after a run of good iterations */
        assert_int_equal(eg2d_get_iterations(a, &it), EG2D_OK);
        assert_int_equal(it, k);
        assert_int_equal(eg2d_get_coordinates(a, xa, ya), EG2D_OK);
        assert_int_equal(eg2d_get_residual(a, &ra), EG2D_OK);

        assert_int_equal(eg2d_create(N, N, &b), EG2D_OK);
        assert_int_equal(domain_set(b, "valley"), EG2D_OK);
        assert_int_equal(eg2d_set_solver(b, EG2D_SOLVER_PSOR), EG2D_OK);
        assert_int_equal(eg2d_set_relaxation(b, 1.99), EG2D_OK);
        assert_int_equal(eg2d_set_parameter(b, EG2D_PARAM_DIVERGENCE_FACTOR, 10), EG2D_OK);
        assert_int_equal(eg2d_iterate(b, k, &rb), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(b, xb, yb), EG2D_OK);
        assert_memory_equal(xa, xb, sizeof xa);
        assert_memory_equal(ya, yb, sizeof ya);
        assert_memory_equal(&ra, &rb, sizeof ra);
        print_message("%s: diverged at iteration %d, restored to %d (residual %.3g)\n",
                      use_iterate ? "eg2d_iterate" : "eg2d_solve", k + 1, k, ra);
        eg2d_destroy(a);
        eg2d_destroy(b);
    }
}

/*---------------------------------------------------------------------*/
static void print_table(void) {
    size_t k;
    puts("| Bad input | Call | Returns | Message (`*`: a value the numerics decide) |");
    puts("|---|---|---|---|");
    for (k = 0; k < NROWS; ++k)
        printf("| %s%s | `%s` | %s | %s%s%s |\n", rows[k].input,
               rows[k].flags & MEMORY_LIMIT ? " (setrlimit in a child)" : "", rows[k].call,
               code_name(rows[k].code), *rows[k].message ? "`" : "", *rows[k].message ? rows[k].message : "(none)",
               *rows[k].message ? "`" : "");
}

int main(int argc, char **argv) {
    struct CMUnitTest tests[NROWS + 1];
    size_t k;
    if (argc > 1 && strcmp(argv[1], "--table") == 0) {
        print_table();
        return 0;
    }
    for (k = 0; k < NROWS; ++k) {
        memset(&tests[k], 0, sizeof tests[k]);
        tests[k].name = rows[k].input;
        tests[k].test_func = test_row;
        tests[k].initial_state = (void *)&rows[k];
    }
    {
        const struct CMUnitTest more[] = {
            cmocka_unit_test(test_divergence_restores_last_good_grid),
        };
        tests[NROWS] = more[0];
    }
    return _cmocka_run_group_tests("failures", tests, NROWS + 1, NULL, NULL);
}
