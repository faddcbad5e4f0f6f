/* The automatic relaxation factor (eg2d_set_relaxation(grid, 0)) of point
 * and line SOR against the best fixed factor of a scan, counting sweeps to
 * the residual 1e-10 from TFI (Winslow). The old rules needed 2.3x (point
 * SOR, swan 65^2: 592 sweeps against 259 at omega = 1.9) and 3.2x (line SOR,
 * valley 257x33: 263 against 82 at 1.8): a start at the optimum of a grid
 * half as fine, and a ramp of max(ni, nj) sweeps on a grid that converges in
 * a hundred. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

/* Sweeps to 1e-10 from TFI; 0 if the run did not converge (diverged). */
static int sweeps(const char *domain, int ni, int nj, int solver, double omega) {
    eg2d_grid *g;
    int it, status;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set(g, domain), EG2D_OK);
    assert_int_equal(eg2d_set_solver(g, solver), EG2D_OK);
    assert_int_equal(eg2d_set_relaxation(g, omega), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    assert_int_equal(eg2d_set_max_iterations(g, 5000), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    status = eg2d_solve(g);
    assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
    eg2d_destroy(g);
    return status == EG2D_OK ? it : 0;
}

/* The automatic factor converges, in at most twice the sweeps of the best
 * factor of `omegas` (which must bracket it: the best is not at an end). */
static void check_within_twice_best(const char *domain, int ni, int nj, int solver, const double *omegas, int n) {
    const int automatic = sweeps(domain, ni, nj, solver, 0.0);
    int best = 0, k_best = -1, k;
    for (k = 0; k < n; ++k) {
        const int it = sweeps(domain, ni, nj, solver, omegas[k]);
        if (it > 0 && (k_best < 0 || it < best)) {
            best = it;
            k_best = k;
        }
    }
    print_message("%s %s %dx%d: automatic %d sweeps, best fixed omega %.2f %d sweeps\n",
                  eg2d_solver_name(solver), domain, ni, nj, automatic, omegas[k_best], best);
    assert_true(k_best > 0 && k_best < n - 1);
    assert_true(automatic > 0);
    assert_true(automatic <= 2 * best);
}

static void test_point_sor_swan(void **state) {
    const double omegas[] = {1.85, 1.88, 1.9, 1.92, 1.94};
    (void)state;
    check_within_twice_best("swan", 65, 65, EG2D_SOLVER_PSOR, omegas, 5);
}

static void test_line_sor_thin_valley(void **state) {
    const double omegas[] = {1.7, 1.75, 1.8, 1.85, 1.9};
    (void)state;
    check_within_twice_best("valley", 257, 33, EG2D_SOLVER_LSOR, omegas, 5);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_point_sor_swan),
        cmocka_unit_test(test_line_sor_thin_valley),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
