/* The numerics against known answers: TFI, Laplace on a bilinear map,
 * Winslow's second-order convergence to a conformal map, the elliptic-grid course notes domains
 * without folds, folds reported. (Second order on the annulus O-grid, for
 * every solver, is in test_geometry_grids.) */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "solve_compare.h"
#include "eg2d.h"

#define PI 3.14159265358979323846

static double *alloc(int n) {
    double *p = malloc(sizeof(double) * (size_t)n);
    assert_non_null(p);
    return p;
}

static void test_tfi_exact_on_boundary(void **state) {
    const int ni = 17, nj = 13;
    eg2d_grid *g;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), sx[17], sy[17];
    int i;
    (void)state;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (i = 0; i < ni; ++i) { /* the top of the valley, exactly */
        const double s = (double)i / (ni - 1);
        sx[i] = s;
        sy[i] = 0.75 + 0.25 * sin(PI * (0.5 + 2 * s));
        assert_true(x[i + ni * (nj - 1)] == sx[i]);
        assert_true(y[i + ni * (nj - 1)] == sy[i]);
        assert_true(y[i] == 0.0);
    }
    for (i = 0; i < nj; ++i) {
        assert_true(x[ni * i] == 0.0);
        assert_true(x[ni - 1 + ni * i] == 1.0);
        assert_true(y[ni * i] == (double)i / (nj - 1));
    }
    free(x);
    free(y);
    eg2d_destroy(g);
}

static void test_laplace_reproduces_bilinear(void **state) {
    const int n = 21;
    eg2d_grid *g;
    double *x = alloc(n * n), *y = alloc(n * n), *x0 = alloc(n * n), *y0 = alloc(n * n), err = 0;
    int k;
    (void)state;
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "quad"), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK); /* TFI of a bilinear map is exact */
    assert_int_equal(eg2d_get_coordinates(g, x0, y0), EG2D_OK);
    for (k = 0; k < n * n; ++k) { /* disturb the interior: the start must not matter */
        const int i = k % n, j = k / n;
        x[k] = x0[k] + ((i > 0 && i < n - 1 && j > 0 && j < n - 1) ? 0.05 * sin(3.0 * k) : 0);
        y[k] = y0[k] + ((i > 0 && i < n - 1 && j > 0 && j < n - 1) ? 0.05 * cos(5.0 * k) : 0);
    }
    assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
    assert_int_equal(eg2d_set_system(g, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-15), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (k = 0; k < n * n; ++k) err = fmax(err, fmax(fabs(x[k] - x0[k]), fabs(y[k] - y0[k])));
    print_message("Laplace on a bilinear map: max error %.3g\n", err);
    assert_true(err < 1e-12);
    free(x); free(y); free(x0); free(y0);
    eg2d_destroy(g);
}

/* w = exp(z), z = xi + i*eta on the unit square: conformal, so Winslow's
 * discrete solution converges to it at second order (NUMERICS.md). */
static double conformal_error(int n, int solver) {
    eg2d_grid *g;
    double *x = alloc(n * n), *y = alloc(n * n), b[4][2][129], err = 0;
    int i, j, side;
    assert_true(n <= 129);
    for (i = 0; i < n; ++i) {
        const double s = (double)i / (n - 1);
        b[0][0][i] = exp(s) * cos(0.0);  b[0][1][i] = exp(s) * sin(0.0); /* JMIN: eta = 0 */
        b[1][0][i] = exp(1.0) * cos(s);  b[1][1][i] = exp(1.0) * sin(s); /* IMAX: xi = 1 */
        b[2][0][i] = exp(s) * cos(1.0);  b[2][1][i] = exp(s) * sin(1.0); /* JMAX: eta = 1 */
        b[3][0][i] = cos(s);             b[3][1][i] = sin(s);            /* IMIN: xi = 0 */
    }
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    for (side = 0; side < 4; ++side) assert_int_equal(eg2d_set_side(g, side, b[side][0], b[side][1]), EG2D_OK);
    assert_int_equal(eg2d_set_solver(g, solver), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-13), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) {
            const double xi = (double)i / (n - 1), eta = (double)j / (n - 1);
            err = fmax(err, hypot(x[i + n * j] - exp(xi) * cos(eta), y[i + n * j] - exp(xi) * sin(eta)));
        }
    free(x);
    free(y);
    eg2d_destroy(g);
    return err;
}

static void test_winslow_second_order_conformal(void **state) {
    const int sizes[] = {9, 17, 33, 65};
    double e[4];
    int m;
    (void)state;
    for (m = 0; m < 4; ++m) e[m] = conformal_error(sizes[m], EG2D_SOLVER_PSOR);
    for (m = 1; m < 4; ++m) {
        const double order = log(e[m - 1] / e[m]) / log(2.0);
        print_message("exp map: n = %d error %.3e, observed order %.3f\n", sizes[m], e[m], order);
        assert_true(order > 1.9 && order < 2.1);
    }
}

static void test_course_note_domains_converge_unfolded(void **state) {
    int d;
    (void)state;
    for (d = 0; domain_names[d]; ++d) {
        eg2d_grid *g;
        double r, folded, min_area;
        int k;
        assert_int_equal(eg2d_create(33, 33, &g), EG2D_OK);
        assert_int_equal(domain_set(g, domain_names[d]), EG2D_OK);
        assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
        assert_int_equal(eg2d_solve(g), EG2D_OK); /* solve fails with FOLDED on a folded grid */
        assert_int_equal(eg2d_get_residual(g, &r), EG2D_OK);
        assert_int_equal(eg2d_get_iterations(g, &k), EG2D_OK);
        assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
        assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_MIN_AREA, &min_area), EG2D_OK);
        print_message("%-14s 33x33: %5d iterations, residual %.2e, min cell area %.3e\n", domain_names[d], k, r,
                      min_area);
        assert_true(r <= 1e-10);
        assert_true(folded == 0);
        assert_true(min_area > 0);
        eg2d_destroy(g);
    }
}

static void test_folded_start_is_reported(void **state) {
    const int n = 9;
    eg2d_grid *g;
    double *x = alloc(n * n), *y = alloc(n * n), v;
    (void)state;
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "quad"), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    /* Pull node (4, 4) beyond its neighbour (5, 4): the cells around it fold. */
    x[4 + n * 4] = x[6 + n * 4];
    assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &v), EG2D_OK);
    assert_true(v >= 2);
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_MIN_AREA, &v), EG2D_OK);
    assert_true(v < 0);
    /* A left-handed grid (IMIN and IMAX swapped by mirroring x) is legal: no folds. */
    {
        int k;
        assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        for (k = 0; k < n * n; ++k) x[k] = -x[k];
        assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
        assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &v), EG2D_OK);
        assert_true(v == 0);
        assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_MIN_AREA, &v), EG2D_OK);
        assert_true(v > 0);
    }
    free(x);
    free(y);
    eg2d_destroy(g);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tfi_exact_on_boundary),
        cmocka_unit_test(test_laplace_reproduces_bilinear),
        cmocka_unit_test(test_winslow_second_order_conformal),
        cmocka_unit_test(test_course_note_domains_converge_unfolded),
        cmocka_unit_test(test_folded_start_is_reported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
