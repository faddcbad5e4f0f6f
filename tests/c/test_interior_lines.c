/* Interior lines (eg2d_set_interior_line): TFI passes through them exactly,
 * and every solver keeps them fixed as an interior boundary while it
 * converges the rest; without the lines a solve moves those nodes. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

#define PI 3.14159265358979323846
#define N 33
#define ROW 10 /* the row j = ROW and the column i = COL of the valley */
#define COL 20

static double valley_top(double s) { return 0.75 + 0.25 * sin(PI * (0.5 + 2 * s)); }

/* The row: from IMIN's node ROW to IMAX's, bulging up by 0.05. */
static void row_curve(double *x, double *y) {
    int i;
    for (i = 0; i < N; ++i) {
        x[i] = (double)i / (N - 1);
        y[i] = (double)ROW / (N - 1) + 0.05 * sin(PI * x[i]);
    }
}

/* The column: from JMIN's node COL through the row's node COL to JMAX's,
 * each piece bulging sideways by 0.03. */
static void column_curve(double *x, double *y) {
    double rx[N], ry[N];
    const double x0 = (double)COL / (N - 1), top = valley_top(x0);
    int j;
    row_curve(rx, ry);
    for (j = 0; j < N; ++j) {
        const double t = j <= ROW ? (double)j / ROW : (double)(j - ROW) / (N - 1 - ROW);
        const double ya = j <= ROW ? 0.0 : ry[COL], yb = j <= ROW ? ry[COL] : top;
        x[j] = x0 + 0.03 * sin(PI * t);
        y[j] = ya + t * (yb - ya);
    }
    x[ROW] = rx[COL]; /* the crossing node: exactly the row's point */
    y[ROW] = ry[COL];
}

/* The largest distance of the line's interior nodes from the curve's points. */
static double line_error(const double *x, const double *y, int direction, int index, const double *cx,
                         const double *cy, int count) {
    double worst = 0;
    int p;
    for (p = 1; p < count - 1; ++p) {
        const int k = direction == EG2D_ETA ? p + N * index : index + N * p;
        worst = fmax(worst, hypot(x[k] - cx[p], y[k] - cy[p]));
    }
    return worst;
}

static eg2d_grid *valley_with_lines(void) {
    double cx[N], cy[N];
    eg2d_grid *g;
    assert_int_equal(eg2d_create(N, N, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    row_curve(cx, cy);
    assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, ROW, cx, cy), EG2D_OK);
    column_curve(cx, cy);
    assert_int_equal(eg2d_set_interior_line(g, EG2D_XI, COL, cx, cy), EG2D_OK);
    return g;
}

static void lines_error(eg2d_grid *g, double *row, double *column) {
    double x[N * N], y[N * N], cx[N], cy[N];
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    row_curve(cx, cy);
    *row = line_error(x, y, EG2D_ETA, ROW, cx, cy, N);
    column_curve(cx, cy);
    *column = line_error(x, y, EG2D_XI, COL, cx, cy, N);
}

static double folded(eg2d_grid *g) {
    double f;
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &f), EG2D_OK);
    return f;
}

/* TFI through the lines holds them exactly; plain TFI does not come near. */
static void test_tfi_holds_lines(void **state) {
    eg2d_grid *g = valley_with_lines(), *plain;
    double row, column;
    (void)state;
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    lines_error(g, &row, &column);
    assert_true(row == 0 && column == 0);
    assert_true(folded(g) == 0);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_HERMITE), EG2D_OK);
    lines_error(g, &row, &column);
    assert_true(row == 0 && column == 0);
    assert_int_equal(eg2d_create(N, N, &plain), EG2D_OK);
    assert_int_equal(domain_set(plain, "valley"), EG2D_OK);
    assert_int_equal(eg2d_initialize(plain, EG2D_INIT_TFI), EG2D_OK);
    lines_error(plain, &row, &column);
    print_message("linear TFI without the lines: %.3f from the row, %.3f from the column\n", row, column);
    assert_true(row > 0.02 && column > 0.01);
    eg2d_destroy(plain);
    eg2d_destroy(g);
}

/* Every solver and system keeps the lines to the last bit and converges
 * the rest; the same solve without the lines moves them. */
static void test_solvers_keep_lines(void **state) {
    const int solvers[5] = {EG2D_SOLVER_PSOR, EG2D_SOLVER_LSOR, EG2D_SOLVER_AF, EG2D_SOLVER_NESTED,
                            EG2D_SOLVER_MULTIGRID};
    const int systems[3] = {EG2D_SYSTEM_WINSLOW, EG2D_SYSTEM_LAPLACE, EG2D_SYSTEM_VARIATIONAL};
    double x[N * N], y[N * N];
    int s, t, iterations;
    (void)state;
    for (t = 0; t < 3; ++t)
        for (s = 0; s < 5; ++s) {
            eg2d_grid *g = valley_with_lines();
            double row, column, residual;
            if (systems[t] == EG2D_SYSTEM_VARIATIONAL &&
                (solvers[s] == EG2D_SOLVER_LSOR || solvers[s] == EG2D_SOLVER_AF)) {
                eg2d_destroy(g);
                continue; /* the line solvers do not run the variational system */
            }
            assert_int_equal(eg2d_set_system(g, systems[t]), EG2D_OK);
            /* Amsden-Hirt folds the valley's concave top with or without
             * lines (eg2d.h); the variational weights whose minimum is
             * unfolded there: a = 10 b, c = b. */
            if (systems[t] == EG2D_SYSTEM_LAPLACE)
                assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_FOLD_CHECK, 0), EG2D_OK);
            if (systems[t] == EG2D_SYSTEM_VARIATIONAL) {
                assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_VARIATIONAL_AREA, 10), EG2D_OK);
                assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_VARIATIONAL_ORTHOGONALITY, 1), EG2D_OK);
            }
            assert_int_equal(eg2d_set_solver(g, solvers[s]), EG2D_OK);
            assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
            assert_int_equal(eg2d_solve(g), EG2D_OK);
            assert_int_equal(eg2d_get_residual(g, &residual), EG2D_OK);
            assert_int_equal(eg2d_get_iterations(g, &iterations), EG2D_OK);
            lines_error(g, &row, &column);
            print_message("system %d %-9s %5d iterations, residual %.1e, lines off by %g, %g\n", systems[t],
                          eg2d_solver_name(solvers[s]), iterations, residual, row, column);
            assert_true(row == 0 && column == 0);
            assert_true(residual <= 1e-10);
            if (systems[t] != EG2D_SYSTEM_LAPLACE) assert_true(folded(g) == 0);
            if (s == 4) {
                /* The same start without the lines: the solve moves them. */
                assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
                assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
                assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
                assert_int_equal(eg2d_clear_interior_lines(g), EG2D_OK);
                assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
                assert_int_equal(eg2d_solve(g), EG2D_OK);
                lines_error(g, &row, &column);
                print_message("  without the lines: the row moves by %.3f, the column by %.3f\n", row, column);
                assert_true(row > 1e-2 && column > 1e-2);
            }
            eg2d_destroy(g);
        }
}

/* An O-grid row: a wavy circle r = 2 + 0.2 cos 3t between r = 1 and r = 3. */
static void test_o_grid_row(void **state) {
    const int ni = 65, nj = 33, row = 15; /* odd: multigrid keeps it as a coarse node (an anchor) */
    const int solvers[4] = {EG2D_SOLVER_LSOR, EG2D_SOLVER_AF, EG2D_SOLVER_MULTIGRID, EG2D_SOLVER_PSOR};
    double *x = malloc(sizeof(double) * ni * nj), *y = malloc(sizeof(double) * ni * nj), cx[65], cy[65];
    int i, s;
    (void)state;
    assert_non_null(x);
    assert_non_null(y);
    for (i = 0; i < ni; ++i) {
        const double t = 2 * PI * i / (ni - 1), r = 2 + 0.2 * cos(3 * t);
        cx[i] = r * cos(t);
        cy[i] = r * sin(t);
    }
    cx[ni - 1] = cx[0];
    cy[ni - 1] = cy[0];
    for (s = 0; s < 4; ++s) {
        eg2d_grid *g;
        double worst = 0;
        int iterations;
        assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
        assert_int_equal(domain_set_annulus(g, 1.0, 3.0), EG2D_OK);
        assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, row, cx, cy), EG2D_OK);
        assert_int_equal(eg2d_set_solver(g, solvers[s]), EG2D_OK);
        assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
        assert_int_equal(eg2d_solve(g), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        for (i = 0; i < ni; ++i)
            worst = fmax(worst, hypot(x[i + ni * row] - cx[i], y[i + ni * row] - cy[i]));
        assert_int_equal(eg2d_get_iterations(g, &iterations), EG2D_OK);
        print_message("O-grid row %d, %-9s %4d iterations, off by %g\n", row, eg2d_solver_name(solvers[s]), iterations,
                      worst);
        assert_true(worst == 0);
        assert_true(folded(g) == 0);
        eg2d_destroy(g);
    }
    free(x);
    free(y);
}

/* Bad input fails and leaves the handle as it was. */
static void test_interior_line_errors(void **state) {
    eg2d_grid *g = valley_with_lines();
    double cx[N], cy[N], x0[N * N], y0[N * N], x1[N * N], y1[N * N];
    (void)state;
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x0, y0), EG2D_OK);
    row_curve(cx, cy);
    assert_int_equal(eg2d_set_interior_line(g, 2, ROW, cx, cy), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, 0, cx, cy), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, N - 1, cx, cy), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, ROW, NULL, cy), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_interior_line(NULL, EG2D_ETA, ROW, cx, cy), EG2D_ERR_ARGUMENT);
    cy[3] = NAN;
    assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, ROW, cx, cy), EG2D_ERR_ARGUMENT);
    row_curve(cx, cy);
    cy[0] += 0.01; /* off IMIN's node */
    assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, ROW, cx, cy), EG2D_ERR_BOUNDARY);
    assert_non_null(strstr(eg2d_last_error(g), "IMIN"));
    row_curve(cx, cy);
    cy[COL] += 0.01; /* off the column's crossing point */
    assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, ROW, cx, cy), EG2D_ERR_BOUNDARY);
    assert_non_null(strstr(eg2d_last_error(g), "cross"));
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_HYPERBOLIC), EG2D_ERR_STATE);
    assert_int_equal(eg2d_get_coordinates(g, x1, y1), EG2D_OK);
    assert_memory_equal(x0, x1, sizeof x0);
    assert_memory_equal(y0, y1, sizeof y0);
    eg2d_destroy(g);
    assert_int_equal(eg2d_create(N, N, &g), EG2D_OK);
    assert_int_equal(domain_set_annulus(g, 1.0, 3.0), EG2D_OK);
    column_curve(cx, cy);
    assert_int_equal(eg2d_set_interior_line(g, EG2D_XI, COL, cx, cy), EG2D_ERR_UNSUPPORTED);
    assert_int_equal(eg2d_set_interior_line(g, EG2D_ETA, ROW, cx, cy), EG2D_ERR_BOUNDARY); /* not closed */
    assert_int_equal(eg2d_clear_interior_lines(NULL), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tfi_holds_lines),
        cmocka_unit_test(test_solvers_keep_lines),
        cmocka_unit_test(test_o_grid_row),
        cmocka_unit_test(test_interior_line_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
