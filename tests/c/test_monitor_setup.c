/* The monitor from the start of a run (eg2d.h, eg2d_monitor_fn, with
 * EG2D_PARAM_MONITOR_SET_UP 1; without it, iterations alone): during the
 * set-up (the start grid, then every layer of the hybrid wall layer's
 * march) it is called with the iteration count so far and +infinity; a stop
 * there returns EG2D_ERR_INTERRUPTED and leaves the handle as it was. NACA
 * 0012 C-grid 385x97 at a first cell of 4.5e-6 chord (y+ 1 at Re 6e6): its
 * march has 96 layers before the first cycle. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eg2d.h"

enum { NI = 385, NJ = 97 };

typedef struct {
    int setup_calls, iteration_calls, stop_at_setup_call;
    int first_iteration, first_was_setup;
} watch;

static int monitor(void *user, int iteration, double residual) {
    watch *w = (watch *)user;
    if (isinf(residual)) {
        if (w->setup_calls + w->iteration_calls == 0) w->first_was_setup = 1;
        if (iteration != 0) w->first_iteration = iteration;  /* a fresh grid: 0 throughout */
        return ++w->setup_calls == w->stop_at_setup_call;
    }
    ++w->iteration_calls;
    return 0;
}

static eg2d_grid *airfoil(void) {
    eg2d_curve *c = NULL;
    eg2d_grid *g = NULL;
    assert_int_equal(eg2d_curve_naca4("0012", 0, &c), EG2D_OK);
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_C), EG2D_OK);
    eg2d_curve_destroy(c);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, 4.46e-6), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_MONITOR_SET_UP, 1), EG2D_OK);
    return g;
}

static void test_setup_calls_before_the_first_cycle(void **state) {
    (void)state;
    eg2d_grid *g = airfoil();
    watch w = {0, 0, -1, 0, 0};
    assert_int_equal(eg2d_set_monitor(g, monitor, &w), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    print_message("%d set-up calls, %d after iterations\n", w.setup_calls, w.iteration_calls);
    assert_true(w.first_was_setup);
    assert_int_equal(w.first_iteration, 0);
    assert_true(w.setup_calls > NJ - 1);  /* the start grid and every layer marched */
    assert_true(w.iteration_calls >= 1);
    eg2d_destroy(g);
    /* Without the parameter the monitor sees iterations alone, as before it. */
    g = airfoil();
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_MONITOR_SET_UP, 0), EG2D_OK);
    watch plain = {0, 0, -1, 0, 0};
    assert_int_equal(eg2d_set_monitor(g, monitor, &plain), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(plain.setup_calls, 0);
    assert_true(plain.iteration_calls >= 1);
    eg2d_destroy(g);
}

/* Stopped in the middle of the march: nothing changed (no start grid yet,
 * as before the call; no iteration), and the next solve makes the same grid
 * as a handle that was never stopped. (eg2d_initialize makes the start and
 * its layer outside any run: no monitor calls.) */
static void test_stop_during_the_march(void **state) {
    (void)state;
    const size_t n = (size_t)NI * NJ;
    double *x0 = malloc(n * sizeof *x0), *y0 = malloc(n * sizeof *y0);
    double *x1 = malloc(n * sizeof *x1), *y1 = malloc(n * sizeof *y1);
    assert_non_null(x0);
    assert_non_null(y0);
    assert_non_null(x1);
    assert_non_null(y1);
    eg2d_grid *g = airfoil();
    const int before = eg2d_get_coordinates(g, x0, y0);
    watch w = {0, 0, 40, 0, 0};
    assert_int_equal(eg2d_set_monitor(g, monitor, &w), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_ERR_INTERRUPTED);
    assert_non_null(strstr(eg2d_last_error(g), "during the set-up"));
    assert_int_equal(w.setup_calls, 40);
    assert_int_equal(w.iteration_calls, 0);
    int it = -1, events = -1;
    assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
    assert_int_equal(it, 0);
    assert_int_equal(eg2d_get_coordinates(g, x1, y1), before);
    if (before == EG2D_OK) {
        assert_memory_equal(x0, x1, n * sizeof *x0);
        assert_memory_equal(y0, y1, n * sizeof *y0);
    }
    assert_int_equal(eg2d_set_monitor(g, NULL, NULL), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_run_info(g, EG2D_RUN_EVENTS, &events), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x1, y1), EG2D_OK);
    eg2d_grid *fresh = airfoil();
    assert_int_equal(eg2d_solve(fresh), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(fresh, x0, y0), EG2D_OK);
    assert_memory_equal(x0, x1, n * sizeof *x0);
    assert_memory_equal(y0, y1, n * sizeof *y0);
    eg2d_destroy(fresh);
    eg2d_destroy(g);
    free(x0);
    free(y0);
    free(x1);
    free(y1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_setup_calls_before_the_first_cycle),
        cmocka_unit_test(test_stop_during_the_march),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
