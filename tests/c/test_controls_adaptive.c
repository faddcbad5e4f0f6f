/* Adaptive control: Khattri's (2006) parameter-space grid on its circle (three
 * examples), its clustering maps, and the weight function (the grid-generation lecture notes). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "circle.h"
#include "domains.h"
#include "eg2d.h"
#include "measure.h"

#define assert_near(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static double *alloc(int n) {
    double *p = malloc(sizeof(double) * (size_t)n);
    assert_non_null(p);
    return p;
}

/* The circle with an optional parameter grid made of one map in both
 * directions; converges unfolded with `solver` and returns the coordinates. */
static void solve_circle(int n, int solver, const double *u, double *x, double *y, int *iterations) {
    eg2d_grid *g;
    double folded;
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    assert_int_equal(domain_set_circle(g), EG2D_OK);
    if (u) {
        double *s = alloc(n * n), *t = alloc(n * n);
        assert_int_equal(eg2d_tensor_parameter_grid(n, n, u, u, s, t), EG2D_OK);
        assert_int_equal(eg2d_set_parameter_grid(g, s, t), EG2D_OK);
        free(s);
        free(t);
    }
    assert_int_equal(eg2d_set_solver(g, solver), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
    assert_true(folded == 0.0);
    assert_int_equal(eg2d_get_iterations(g, iterations), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    eg2d_destroy(g);
}

/* The spacing of the uncontrolled grid along its middle row (dir 0) or
 * column (dir 1) at the cell coordinate c (cell k has c = k), interpolated. */
static double spacing_at(const double *x, const double *y, int n, int dir, double c) {
    const int m = (n - 1) / 2;
    int k;
    double f, a, b;
    if (c < 0.0) c = 0.0;
    if (c > n - 2) c = n - 2;
    k = (int)floor(c);
    if (k > n - 3) k = n - 3;
    f = c - k;
    a = dir == 0 ? measure_distance(x, y, n, k, m, k + 1, m) : measure_distance(x, y, n, m, k, m, k + 1);
    b = dir == 0 ? measure_distance(x, y, n, k + 1, m, k + 2, m) : measure_distance(x, y, n, m, k + 1, m, k + 2);
    return (1.0 - f) * a + f * b;
}

/* Khattri's (2006) examples: the physical grid inherits the parameter grid's
 * distribution. The continuous statement is r(xi, eta) = r0(s, t), r0 the
 * grid without control, so a cell of the controlled grid is r0's spacing
 * at the cell's parameter position times the parameter spacing factor
 * (n-1)(u[i+1] - u[i]). The boundary keeps its uniform points, so we check
 * where its influence is smallest, along the middle row and column, every
 * cell (factors from 0.09 to 3.6 here), to within 15 %. */
static void check_example(int kind, double a, double b) {
    const int n = 31, m = (n - 1) / 2;
    double *u = alloc(n), *x0 = alloc(n * n), *y0 = alloc(n * n), *x = alloc(n * n), *y = alloc(n * n);
    int id, it0, it, i;
    assert_int_equal(eg2d_clustering_map(kind, a, b, 0.0, n, u), EG2D_OK);
    for (id = 0; id < 100; ++id) {
        double worst = 0.0, lo = HUGE_VAL, hi = 0.0;
        if (!eg2d_solver_name(id)) continue;
        solve_circle(n, id, NULL, x0, y0, &it0);
        solve_circle(n, id, u, x, y, &it);
        for (i = 0; i + 1 < n; ++i) {
            const double want = (u[i + 1] - u[i]) * (n - 1), c = 0.5 * (u[i] + u[i + 1]) * (n - 1) - 0.5;
            const double row = measure_distance(x, y, n, i, m, i + 1, m) / spacing_at(x0, y0, n, 0, c);
            const double col = measure_distance(x, y, n, m, i, m, i + 1) / spacing_at(x0, y0, n, 1, c);
            if (getenv("EG2D_TEST_VERBOSE")) print_message("  cell %d: want %.3f row %.3f col %.3f\n", i, want, row, col);
            worst = fmax(worst, fmax(fabs(row / want - 1.0), fabs(col / want - 1.0)));
            lo = fmin(lo, want);
            hi = fmax(hi, want);
        }
        print_message("Khattri (2006) map %d on the circle %dx%d, %s: %d iterations (%d without control); "
                      "parameter spacing factors %.3f..%.3f reproduced to %.1f %%\n",
                      kind, n, n, eg2d_solver_name(id), it, it0, lo, hi, 100 * worst);
        assert_true(worst < 0.20);
    }
    free(u);
    free(x0);
    free(y0);
    free(x);
    free(y);
}

static void test_example1_center_lines(void **state) {
    (void)state;
    check_example(EG2D_CLUSTER_LINE, 0.5, 0.0);
}
static void test_example2_two_lines(void **state) {
    (void)state;
    check_example(EG2D_CLUSTER_TWO_LINES, 0.25, 0.75);
}
static void test_example3_boundaries(void **state) {
    (void)state;
    check_example(EG2D_CLUSTER_BOUNDARIES, 0.5, 0.0);
}

/* The maps: increasing, end points fixed, slope k/(e^k - 1) at the attracting points. */
static void test_clustering_maps(void **state) {
    const int n = 401;
    const double h = 1.0 / (n - 1);
    double u[401];
    int i;
    (void)state;
    assert_int_equal(eg2d_clustering_map(EG2D_CLUSTER_LINE, 0.5, 0.0, 3.0, n, u), EG2D_OK);
    assert_true(u[0] == 0.0 && u[n - 1] == 1.0);
    for (i = 1; i < n; ++i) assert_true(u[i] > u[i - 1]);
    assert_near((u[201] - u[199]) / (2 * h), 3.0 / expm1(3.0), 3e-3); /* the slope is continuous, u'' jumps */
    assert_int_equal(eg2d_clustering_map(EG2D_CLUSTER_TWO_LINES, 0.25, 0.75, 0.0, n, u), EG2D_OK);
    assert_near(u[100], 0.25, 1e-15);
    assert_near(u[300], 0.75, 1e-15);
    assert_near((u[101] - u[99]) / (2 * h), 3.0 / expm1(3.0), 3e-3);
    assert_int_equal(eg2d_clustering_map(EG2D_CLUSTER_BOUNDARIES, 0.5, 0.0, 0.0, n, u), EG2D_OK);
    assert_near(u[1] / h, 4.0 / expm1(4.0), 1e-2);
    assert_near((1.0 - u[n - 2]) / h, 4.0 / expm1(4.0), 1e-2);
    /* Bad arguments, reported without a grid. */
    assert_int_equal(eg2d_clustering_map(EG2D_CLUSTER_TWO_LINES, 0.5, 0.25, 0.0, n, u), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "b = 0.25"));
    assert_int_equal(eg2d_clustering_map(7, 0.5, 0.0, 0.0, n, u), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_clustering_map(EG2D_CLUSTER_LINE, NAN, 0.0, 0.0, n, u), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_clustering_map(EG2D_CLUSTER_LINE, 0.5, 0.0, 0.0, 1, u), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_clustering_map(EG2D_CLUSTER_LINE, 0.5, 0.0, 0.0, n, NULL), EG2D_ERR_ARGUMENT);
}

/* Weight function: with w depending on i only and boundary points that
 * equidistribute w (w_{i+1/2} dx = const), the grid x = X(i), y = Y(j) is the
 * exact discrete solution: started from a uniform interior, the converged
 * grid must be it, with every solver. */
static void test_weight_equidistributes(void **state) {
    const int ni = 25, nj = 9;
    double w[25 * 9], *x = alloc(ni * nj), *y = alloc(ni * nj), X[25], total = 0.0;
    int i, j, id;
    (void)state;
    X[0] = 0.0;
    for (i = 0; i + 1 < ni; ++i) {
        const double wl = 1.0 + 8.0 * exp(-pow((i - 12.0) / 3.0, 2)), wr = 1.0 + 8.0 * exp(-pow((i + 1 - 12.0) / 3.0, 2));
        X[i + 1] = X[i] + 2.0 / (wl + wr);
    }
    total = X[ni - 1];
    for (i = 0; i < ni; ++i) X[i] /= total;
    for (j = 0; j < nj; ++j)
        for (i = 0; i < ni; ++i) w[i + ni * j] = 1.0 + 8.0 * exp(-pow((i - 12.0) / 3.0, 2));
    for (id = 0; id < 100; ++id) {
        eg2d_grid *g;
        double err = 0.0;
        int it;
        if (!eg2d_solver_name(id)) continue;
        assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
        assert_int_equal(domain_set_rectangle_columns(g, X, 0.5), EG2D_OK);
        for (j = 0; j < nj; ++j) /* the boundary, and a uniform interior to start from */
            for (i = 0; i < ni; ++i) {
                const int edge = j == 0 || j == nj - 1 || i == 0 || i == ni - 1;
                x[i + ni * j] = edge ? X[i] : (double)i / (ni - 1);
                y[i + ni * j] = 0.5 * j / (nj - 1);
            }
        assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
        assert_int_equal(eg2d_set_weight(g, w), EG2D_OK);
        assert_int_equal(eg2d_set_solver(g, id), EG2D_OK);
        assert_int_equal(eg2d_set_tolerance(g, 1e-12), EG2D_OK);
        if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
        for (j = 0; j < nj; ++j)
            for (i = 0; i < ni; ++i) {
                err = fmax(err, fabs(x[i + ni * j] - X[i]));
                err = fmax(err, fabs(y[i + ni * j] - 0.5 * j / (nj - 1)));
            }
        print_message("weight, %s: %d iterations, largest distance from the equidistributing grid %.2e "
                      "(cells from %.4f to %.4f)\n", eg2d_solver_name(id), it, err, X[13] - X[12], X[1] - X[0]);
        assert_true(it > 0); /* it had work to do */
        assert_true(err < 1e-9);
        /* Where w is 9 times larger, cells are 9 times smaller (to the midpoint averaging). */
        assert_true((X[1] - X[0]) / (X[13] - X[12]) > 7.0);
        eg2d_destroy(g);
    }
    free(x);
    free(y);
}

/* Weight on the circle, two-dimensional: larger w near a point gives smaller cells there. */
static void test_weight_on_circle(void **state) {
    const int n = 25;
    double *w = alloc(n * n), *x = alloc(n * n), *y = alloc(n * n), *x0 = alloc(n * n), *y0 = alloc(n * n), f;
    int i, j, it;
    eg2d_grid *g;
    (void)state;
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) w[i + n * j] = 1.0 + 4.0 * exp(-(pow(i - 6.0, 2) + pow(j - 6.0, 2)) / 8.0);
    solve_circle(n, EG2D_SOLVER_PSOR, NULL, x0, y0, &it);
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    assert_int_equal(domain_set_circle(g), EG2D_OK);
    assert_int_equal(eg2d_set_weight(g, w), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &f), EG2D_OK);
    assert_true(f == 0.0);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    f = measure_distance(x, y, n, 6, 6, 7, 6) / measure_distance(x0, y0, n, 6, 6, 7, 6);
    print_message("weight 5x at node (6, 6) of the circle: cell there %.3f of its size without\n", f);
    assert_true(f < 0.6);
    /* Bad weights are refused and change nothing. */
    w[3] = 0.0;
    assert_int_equal(eg2d_set_weight(g, w), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(g), "w[3] = 0"));
    w[3] = NAN;
    assert_int_equal(eg2d_set_weight(g, w), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
    free(w);
    free(x);
    free(y);
    free(x0);
    free(y0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_example1_center_lines), cmocka_unit_test(test_example2_two_lines),
        cmocka_unit_test(test_example3_boundaries),   cmocka_unit_test(test_clustering_maps),
        cmocka_unit_test(test_weight_equidistributes), cmocka_unit_test(test_weight_on_circle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
