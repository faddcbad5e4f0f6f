/* Line SOR (EG2D_SOLVER_LSOR): the same grids as point SOR on the elliptic-grid course notes
 * domains, the annulus O-grid with the branch cut solved
 * implicitly (columns 0 and ni-1 stay the same points), Laplace exact on a
 * bilinear map, and a given relaxation factor honoured. */
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

/* solve_domain, checked: the iteration count. */
static int solve(const char *domain, int ni, int nj, int solver, int system, double tol, double *x, double *y) {
    const int it = solve_domain(domain, ni, nj, solver, system, tol, x, y);
    if (it < 0) fail_msg("%s %dx%d: %s", domain, ni, nj, eg2d_status_string(-it));
    return it;
}

static void test_same_grid_as_psor(void **state) {
    const int n = 25;
    double *x1 = alloc(n * n), *y1 = alloc(n * n), *x2 = alloc(n * n), *y2 = alloc(n * n);
    int d, s;
    (void)state;
    for (s = EG2D_SYSTEM_LAPLACE; s <= EG2D_SYSTEM_WINSLOW; ++s)
        for (d = 0; domain_names[d]; ++d) {
            const int kp = solve(domain_names[d], n, n, EG2D_SOLVER_PSOR, s, 1e-13, x1, y1);
            const int kl = solve(domain_names[d], n, n, EG2D_SOLVER_LSOR, s, 1e-13, x2, y2);
            const double dist = grid_distance(x1, y1, x2, y2, n * n);
            print_message("%-7s %-14s %dx%d: psor %4d sweeps, lsor %4d, grids differ by %.2e\n",
                          s ? "Winslow" : "Laplace", domain_names[d], n, n, kp, kl, dist);
            assert_true(dist < 1e-10);
        }
    free(x1); free(y1); free(x2); free(y2);
}

/* Start with the cut column pushed off the solution: every sweep must keep
 * columns 0 and ni-1 identical, and the cut must move to the solution with
 * the rest (it is solved for, not copied from a neighbour). */
static void test_cut_moves_with_the_interior(void **state) {
    const int ni = 33, nj = 13;
    eg2d_grid *g;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), *xs = alloc(ni * nj), *ys = alloc(ni * nj), r;
    int j, k;
    (void)state;
    solve("annulus", ni, nj, EG2D_SOLVER_PSOR, EG2D_SYSTEM_WINSLOW, 1e-13, xs, ys);
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set_annulus(g, 3.0, 9.0), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (j = 1; j < nj - 1; ++j) {
        x[ni * j] += 0.3;
        x[ni * j + ni - 1] += 0.3;
        y[ni * j] -= 0.2;
        y[ni * j + ni - 1] -= 0.2;
    }
    assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
    assert_int_equal(eg2d_set_solver(g, EG2D_SOLVER_LSOR), EG2D_OK);
    for (k = 0; k < 40; ++k) {
        assert_int_equal(eg2d_iterate(g, 1, &r), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        for (j = 0; j < nj; ++j) {
            assert_true(x[ni * j] == x[ni * j + ni - 1]);
            assert_true(y[ni * j] == y[ni * j + ni - 1]);
        }
    }
    assert_int_equal(eg2d_set_tolerance(g, 1e-13), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    print_message("lsor: cut start off by 0.36, after solve %.2e from point SOR's grid\n",
                  grid_distance(x, y, xs, ys, ni * nj));
    assert_true(grid_distance(x, y, xs, ys, ni * nj) < 1e-10);
    eg2d_destroy(g);
    free(x); free(y); free(xs); free(ys);
}

/* A given factor is used as it is: omega = 1 (line Gauss-Seidel) needs more
 * sweeps than the automatic factor, and both reach the same grid. */
static void test_given_relaxation(void **state) {
    const int n = 33;
    eg2d_grid *g;
    double *x1 = alloc(n * n), *y1 = alloc(n * n), *x2 = alloc(n * n), *y2 = alloc(n * n);
    int k_auto, k_one;
    (void)state;
    k_auto = solve("valley", n, n, EG2D_SOLVER_LSOR, EG2D_SYSTEM_WINSLOW, 1e-11, x1, y1);
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    assert_int_equal(eg2d_set_solver(g, EG2D_SOLVER_LSOR), EG2D_OK);
    assert_int_equal(eg2d_set_relaxation(g, 1.0), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-11), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_iterations(g, &k_one), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x2, y2), EG2D_OK);
    print_message("lsor valley 33x33: automatic factor %d sweeps, omega = 1 %d sweeps\n", k_auto, k_one);
    assert_true(k_one > 2 * k_auto);
    assert_true(grid_distance(x1, y1, x2, y2, n * n) < 1e-8);
    assert_string_equal(eg2d_solver_name(EG2D_SOLVER_LSOR), "lsor");
    eg2d_destroy(g);
    free(x1); free(y1); free(x2); free(y2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_grid_as_psor),
        cmocka_unit_test(test_cut_moves_with_the_interior),
        cmocka_unit_test(test_given_relaxation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
