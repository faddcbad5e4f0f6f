/* A solve that stops making progress ends after EG2D_PARAM_STALL_ITERATIONS
 * iterations without a 10% gain (generator/stall_watch.hpp), not at the
 * iteration limit: NOT_CONVERGED, the grid restored to the best iteration,
 * the message naming the window and the run's events. The case: NACA0012
 * C-grid 129x33 with a first cell of 1e-3 chord, whose cut node next to
 * the trailing edge keeps sliding along the cut (test_controls_wall.c). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

static eg2d_grid *sliding_cut(void) {
    eg2d_grid *g;
    assert_int_equal(eg2d_create(129, 33, &g), EG2D_OK);
    assert_int_equal(domain_set_airfoil_c(g, "0012", 32, 5.0), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, 1e-3), EG2D_OK);
    return g;
}

static int calls;
static int count(void *user, int iteration, double residual) {
    (void)user;
    (void)iteration;
    (void)residual;
    ++calls;
    return 0;
}

/* Automatic: multigrid's 200 iterations, where the limit is 100000. */
static void test_stall_automatic(void **state) {
    (void)state;
    eg2d_grid *g = sliding_cut();
    double window = -1;
    assert_int_equal(eg2d_get_parameter(g, EG2D_PARAM_STALL_ITERATIONS, &window), EG2D_OK);
    assert_true(window == 0.0);
    calls = 0;
    assert_int_equal(eg2d_set_monitor(g, count, NULL), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_ERR_NOT_CONVERGED);
    const char *e = eg2d_last_error(g);
    print_message("%s (%d iterations run)\n", e, calls);
    assert_non_null(strstr(e, "multigrid made no progress in 200 iterations"));
    assert_non_null(strstr(e, "restored to iteration"));
    assert_non_null(strstr(e, "the run's events: [iteration"));
    assert_true(calls >= 200 && calls < 1000);
    int it = -1;
    assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
    assert_true(it < calls);  /* the best iteration, before the stall */
    double folded = -1;
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
    assert_true(folded == 0.0);
    eg2d_destroy(g);
}

/* A window of the user's; iterate runs the count it is given. */
static void test_stall_set(void **state) {
    (void)state;
    eg2d_grid *g = sliding_cut();
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_STALL_ITERATIONS, 40), EG2D_OK);
    calls = 0;
    assert_int_equal(eg2d_set_monitor(g, count, NULL), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_ERR_NOT_CONVERGED);
    assert_non_null(strstr(eg2d_last_error(g), "made no progress in 40 iterations"));
    const int solved = calls;
    calls = 0;
    double r = 0;
    assert_int_equal(eg2d_iterate(g, solved + 100, &r), EG2D_OK);
    assert_int_equal(calls, solved + 100);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_STALL_ITERATIONS, -1), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(g), "stall_iterations"));
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_STALL_ITERATIONS, 2.5), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stall_automatic),
        cmocka_unit_test(test_stall_set),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
