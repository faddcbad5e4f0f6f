/* Every API call's good and bad paths: codes, precise messages, and a failed
 * call leaving the grid as it was. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

#define N 9

static void assert_contains(const char *text, const char *part) {
    if (!strstr(text, part)) fail_msg("message \"%s\" does not contain \"%s\"", text, part);
}

static eg2d_grid *make_square(int ni, int nj) {
    eg2d_grid *g = NULL;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "quad"), EG2D_OK);
    return g;
}

static void test_version_and_status(void **state) {
    int ma = -1, mi = -1, pa = -1;
    (void)state;
    eg2d_version(&ma, &mi, &pa);
    assert_int_equal(ma, EG2D_VERSION_MAJOR);
    assert_int_equal(mi, EG2D_VERSION_MINOR);
    assert_int_equal(pa, EG2D_VERSION_PATCH);
    eg2d_version(NULL, NULL, NULL);
    assert_contains(eg2d_status_string(EG2D_OK), "EG2D_OK");
    assert_contains(eg2d_status_string(EG2D_ERR_BOUNDARY), "EG2D_ERR_BOUNDARY");
    assert_contains(eg2d_status_string(EG2D_ERR_INTERRUPTED), "monitor");
    assert_contains(eg2d_status_string(12345), "unknown");
    /* The fixed values are the contract. */
    assert_int_equal(EG2D_ERR_ARGUMENT, 1);
    assert_int_equal(EG2D_ERR_UNSUPPORTED, 9);
    assert_int_equal(EG2D_SIDE_IMIN, 3);
    assert_int_equal(EG2D_SOLVER_MULTIGRID, 4);
}

static void test_create(void **state) {
    eg2d_grid *g = (eg2d_grid *)&g; /* must be reset to NULL on failure */
    int ni = 0, nj = 0;
    (void)state;
    assert_int_equal(eg2d_create(2, 5, &g), EG2D_ERR_ARGUMENT);
    assert_null(g);
    assert_string_equal(eg2d_last_error(NULL), "eg2d_create: ni = 2: need at least 3");
    assert_int_equal(eg2d_create(5, -1, &g), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(NULL), "eg2d_create: nj = -1: need at least 3");
    assert_int_equal(eg2d_create(2000000000, 2000000000, &g), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(NULL), "overflows");
    assert_int_equal(eg2d_create(5, 5, NULL), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(NULL), "grid is NULL");
    assert_int_equal(eg2d_create(7, 4, &g), EG2D_OK);
    assert_non_null(g);
    assert_string_equal(eg2d_last_error(g), "");
    assert_int_equal(eg2d_get_size(g, &ni, &nj), EG2D_OK);
    assert_int_equal(ni, 7);
    assert_int_equal(nj, 4);
    assert_int_equal(eg2d_get_size(g, NULL, NULL), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
    eg2d_destroy(NULL);
}

static void test_null_handle(void **state) {
    double v = 0;
    int k;
    (void)state;
    assert_int_equal(eg2d_set_side(NULL, 0, &v, &v), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(NULL), "eg2d_set_side: grid is NULL");
    assert_int_equal(eg2d_set_boundary(NULL, &v, &v), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_initialize(NULL, EG2D_INIT_TFI), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_coordinates(NULL, &v, &v), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_system(NULL, 0), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_solver(NULL, 0), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_solver(NULL, &k), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_topology(NULL, 0), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_topology(NULL, &k), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_relaxation(NULL, 1), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_tolerance(NULL, 1e-6), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_max_iterations(NULL, 5), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_parameter(NULL, 0, 1), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_parameter(NULL, 0, &v), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_monitor(NULL, NULL, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_iterate(NULL, 1, &v), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_solve(NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_size(NULL, &k, &k), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_coordinates(NULL, &v, &v), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_residual(NULL, &v), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_iterations(NULL, &k), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_quality(NULL, 0, &v), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(NULL), "eg2d_get_quality: grid is NULL");
}

static void test_set_side_errors(void **state) {
    eg2d_grid *g;
    double x[N], y[N], xx[N * N], yy[N * N], r;
    int i;
    (void)state;
    assert_int_equal(eg2d_create(N, N, &g), EG2D_OK);
    for (i = 0; i < N; ++i) {
        x[i] = (double)i / (N - 1);
        y[i] = 0;
    }
    assert_int_equal(eg2d_set_side(g, 4, x, y), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "side = 4");
    assert_int_equal(eg2d_set_side(g, -1, x, y), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, NULL, y), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g), "eg2d_set_side: x is NULL");
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, NULL), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g), "eg2d_set_side: y is NULL");
    y[3] = NAN;
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "JMIN y[3] = nan");
    y[3] = INFINITY;
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "JMIN y[3] = inf");
    y[3] = -1e200; /* finite, but its fourth power would overflow the metric terms */
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "JMIN y[3] = -1e+200: coordinates must be within +-1e+30");
    y[3] = 0;
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_OK);
    /* IMAX starting at (1.2, 0) instead of (1, 0). */
    for (i = 0; i < N; ++i) {
        x[i] = 1.2;
        y[i] = (double)i / (N - 1);
    }
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_IMAX, x, y), EG2D_ERR_BOUNDARY);
    assert_string_equal(eg2d_last_error(g), "eg2d_set_side: corner JMIN/IMAX: (1, 0) vs (1.2, 0)");
    /* Nothing was set: iterating still lacks IMAX. */
    assert_int_equal(eg2d_iterate(g, 1, &r), EG2D_ERR_STATE);
    assert_contains(eg2d_last_error(g), "side IMAX, JMAX, IMIN not set");
    /* set_boundary with a NaN on the ring changes nothing either; interior NaN is not read. */
    for (i = 0; i < N * N; ++i) {
        xx[i] = (double)(i % N) / (N - 1);
        yy[i] = (double)(i / N) / (N - 1);
    }
    xx[N * (N / 2)] = NAN; /* on IMIN */
    assert_int_equal(eg2d_set_boundary(g, xx, yy), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "IMIN x[4] = nan");
    assert_int_equal(eg2d_iterate(g, 1, &r), EG2D_ERR_STATE);
    xx[N * (N / 2)] = 0;
    xx[N + 1] = NAN;
    assert_int_equal(eg2d_set_boundary(g, xx, yy), EG2D_OK);
    assert_int_equal(eg2d_set_boundary(g, NULL, yy), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
}

static void test_corner_message_fixed_order(void **state) {
    eg2d_grid *g = make_square(N, N);
    double x[N], y[N];
    int i;
    (void)state;
    for (i = 0; i < N; ++i) {
        x[i] = 0.3 + 0.1 * i;
        y[i] = 1.0;
    }
    /* JMAX from (0.3, 1) to (1.1, 1): its first point disagrees with IMIN's last (0.3, 1) - no,
     * IMIN ends at (0.3, 1) as well; its last point disagrees with IMAX's last (2.4, 1.6). */
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMAX, x, y), EG2D_ERR_BOUNDARY);
    assert_contains(eg2d_last_error(g), "corner JMAX/IMAX: (1.1000000000000001, 1) vs (2.3999999999999999, 1.6000000000000001)");
    eg2d_destroy(g);
}

static void test_state_errors(void **state) {
    eg2d_grid *g;
    double v, x[N * N], y[N * N];
    int k;
    (void)state;
    assert_int_equal(eg2d_create(N, N, &g), EG2D_OK);
    assert_int_equal(eg2d_iterate(g, 1, &v), EG2D_ERR_STATE);
    assert_string_equal(eg2d_last_error(g), "eg2d_iterate: the boundary is not complete: side JMIN, IMAX, JMAX, IMIN not set");
    assert_int_equal(eg2d_solve(g), EG2D_ERR_STATE);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_ERR_STATE);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_ERR_STATE);
    assert_int_equal(eg2d_get_residual(g, &v), EG2D_ERR_STATE);
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_MIN_AREA, &v), EG2D_ERR_STATE);
    assert_int_equal(domain_set(g, "swan"), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_ERR_STATE);
    assert_contains(eg2d_last_error(g), "no interior yet");
    assert_int_equal(eg2d_initialize(g, 77), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "method 77");
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, NULL, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_coordinates(g, x, NULL), EG2D_OK);
    assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
    assert_int_equal(k, 0);
    assert_int_equal(eg2d_get_iterations(g, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_residual(g, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_iterate(g, -1, &v), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g), "eg2d_iterate: iterations = -1: must be >= 0");
    eg2d_destroy(g);
}

static void test_set_coordinates(void **state) {
    eg2d_grid *g = make_square(N, N);
    double x[N * N], y[N * N], x2[N * N], y2[N * N];
    (void)state;
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    x[N + 1] += 0.01;
    assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x2, y2), EG2D_OK);
    assert_memory_equal(x, x2, sizeof x);
    x[2 * N + 4] = NAN;
    assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "x[22] = nan");
    assert_int_equal(eg2d_get_coordinates(g, x2, y2), EG2D_OK);
    assert_true(x2[2 * N + 4] == x2[2 * N + 4]); /* unchanged, not NaN */
    assert_int_equal(eg2d_set_coordinates(g, NULL, y), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
}

static void test_system_solver_parameters(void **state) {
    eg2d_grid *g;
    double v, lo, hi, def;
    int s;
    (void)state;
    assert_int_equal(eg2d_create(N, N, &g), EG2D_OK);
    assert_int_equal(eg2d_set_system(g, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    assert_int_equal(eg2d_set_system(g, 3), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "system = 3");
    assert_int_equal(eg2d_get_solver(g, &s), EG2D_OK);
    assert_int_equal(s, EG2D_SOLVER_MULTIGRID); /* the default */
    assert_int_equal(eg2d_get_solver(g, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_solver(g, EG2D_SOLVER_PSOR), EG2D_OK);
    assert_string_equal(eg2d_solver_name(EG2D_SOLVER_PSOR), "psor");
    assert_null(eg2d_solver_name(-3));
    for (s = EG2D_SOLVER_LSOR; s <= EG2D_SOLVER_MULTIGRID; ++s) {
        if (eg2d_solver_name(s)) continue; /* built: other tests cover it */
        assert_int_equal(eg2d_set_solver(g, s), EG2D_ERR_UNSUPPORTED);
        assert_contains(eg2d_last_error(g), "not built into this library");
    }
    assert_int_equal(eg2d_set_solver(g, -1), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_solver(g, &s), EG2D_OK);
    assert_int_equal(s, EG2D_SOLVER_PSOR);

    assert_int_equal(eg2d_set_relaxation(g, 0), EG2D_OK);
    assert_int_equal(eg2d_set_relaxation(g, 1.5), EG2D_OK);
    assert_int_equal(eg2d_set_relaxation(g, 2), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g),
                        "eg2d_set_relaxation: relaxation = 2: must be in (0, 2) (or 0 for automatic)");
    assert_int_equal(eg2d_set_relaxation(g, -0.5), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_relaxation(g, NAN), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "must be finite");
    assert_int_equal(eg2d_get_parameter(g, EG2D_PARAM_RELAXATION, &v), EG2D_OK);
    assert_true(v == 1.5); /* the failed calls changed nothing */
    assert_int_equal(eg2d_set_tolerance(g, 0), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_tolerance(g, 1e-12), EG2D_OK);
    assert_int_equal(eg2d_get_parameter(g, EG2D_PARAM_TOLERANCE, &v), EG2D_OK);
    assert_true(v == 1e-12);
    assert_int_equal(eg2d_set_max_iterations(g, 0), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_max_iterations(g, 10), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_MAX_ITERATIONS, 2.5), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "whole number");
    assert_int_equal(eg2d_set_parameter(g, 999, 1), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "parameter 999");
    assert_int_equal(eg2d_get_parameter(g, 999, &v), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_parameter(g, EG2D_PARAM_TOLERANCE, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_parameter_bounds(EG2D_PARAM_TOLERANCE, &lo, &hi, &def), EG2D_OK);
    assert_true(lo == 0 && hi == 1 && def == 1e-8);
    assert_int_equal(eg2d_parameter_bounds(EG2D_PARAM_MAX_ITERATIONS, NULL, NULL, &def), EG2D_OK);
    assert_true(def == 100000);
    assert_int_equal(eg2d_parameter_bounds(-7, &lo, &hi, &def), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(NULL), "parameter -7");
    eg2d_destroy(g);
}

static void test_topology(void **state) {
    eg2d_grid *g;
    int t;
    double x[N], y[N];
    int i;
    (void)state;
    assert_int_equal(eg2d_create(N, 5, &g), EG2D_OK);
    assert_int_equal(eg2d_get_topology(g, &t), EG2D_OK);
    assert_int_equal(t, EG2D_TOPO_SINGLE);
    assert_int_equal(eg2d_set_topology(g, 7), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_topology(g, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_O), EG2D_OK);
    assert_int_equal(eg2d_get_topology(g, &t), EG2D_OK);
    assert_int_equal(t, EG2D_TOPO_O);
    for (i = 0; i < N; ++i) {
        x[i] = cos(6.283185307179586 * i / (N - 1));
        y[i] = sin(6.283185307179586 * i / (N - 1));
    }
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_IMIN, x, y), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "periodic cut");
    x[N - 1] = 1.5; /* open curve */
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_ERR_BOUNDARY);
    assert_contains(eg2d_last_error(g), "O-grid side JMIN is not closed");
    eg2d_destroy(g);
}

static int count_calls(void *user, int iteration, double residual) {
    int *calls = (int *)user;
    assert_true(residual > 0);
    assert_int_equal(iteration, calls[0] + 1);
    calls[0] = iteration;
    return iteration >= calls[1];
}

static void test_iterate_solve_monitor(void **state) {
    eg2d_grid *g = make_square(17, 17);
    double r, r2;
    int k, calls[2] = {0, 1000000};
    (void)state;
    /* Point SOR: slow enough that the monitor stops it before it converges. */
    assert_int_equal(eg2d_set_solver(g, EG2D_SOLVER_PSOR), EG2D_OK);
    assert_int_equal(eg2d_iterate(g, 0, &r), EG2D_OK); /* initialises by TFI */
    assert_int_equal(eg2d_iterate(g, 5, &r), EG2D_OK);
    assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
    assert_int_equal(k, 5);
    assert_int_equal(eg2d_get_residual(g, &r2), EG2D_OK);
    assert_true(r == r2);
    assert_int_equal(eg2d_iterate(g, 3, NULL), EG2D_OK);
    assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
    assert_int_equal(k, 8);

    assert_int_equal(eg2d_set_monitor(g, count_calls, calls), EG2D_OK);
    calls[0] = 8;
    calls[1] = 12;
    assert_int_equal(eg2d_solve(g), EG2D_ERR_INTERRUPTED);
    assert_contains(eg2d_last_error(g), "eg2d_solve: stopped by the monitor at iteration 12 (residual ");
    assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
    assert_int_equal(k, 12);
    calls[1] = 14;
    assert_int_equal(eg2d_iterate(g, 10, &r), EG2D_ERR_INTERRUPTED);
    assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
    assert_int_equal(k, 14);
    assert_int_equal(eg2d_set_monitor(g, NULL, NULL), EG2D_OK);

    assert_int_equal(eg2d_set_tolerance(g, 1e-12), EG2D_OK);
    assert_int_equal(eg2d_set_max_iterations(g, 3), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_ERR_NOT_CONVERGED);
    assert_contains(eg2d_last_error(g), "psor did not converge in 3 iterations: residual ");
    assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
    assert_int_equal(k, 17);
    assert_int_equal(eg2d_set_max_iterations(g, 100000), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_residual(g, &r), EG2D_OK);
    assert_true(r <= 1e-12);
    /* Solving a converged grid does no iteration. */
    assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
    r2 = k;
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
    assert_true(k == r2);
    eg2d_destroy(g);
}

static void test_quality_errors(void **state) {
    eg2d_grid *g = make_square(N, N);
    double v;
    (void)state;
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_quality(g, 999, &v), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "metric = 999");
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &v), EG2D_OK);
    assert_true(v == 0);
    eg2d_destroy(g);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version_and_status),
        cmocka_unit_test(test_create),
        cmocka_unit_test(test_null_handle),
        cmocka_unit_test(test_set_side_errors),
        cmocka_unit_test(test_corner_message_fixed_order),
        cmocka_unit_test(test_state_errors),
        cmocka_unit_test(test_set_coordinates),
        cmocka_unit_test(test_system_solver_parameters),
        cmocka_unit_test(test_topology),
        cmocka_unit_test(test_iterate_solve_monitor),
        cmocka_unit_test(test_quality_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
