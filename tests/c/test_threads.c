/* Independent handles from many threads at once (eg2d.h, Threads): 8 threads
 * each make 50 grids of different domains, sizes, systems and settings, some
 * of them with failing calls, and every result (status, message, iteration
 * count, residual, every coordinate) is bitwise the result of the same job run
 * serially. The monitor reads its own grid while it runs. Run under
 * ThreadSanitizer by the tsan preset. */
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

#define THREADS 8
#define GRIDS 50
#define MAXN 17

typedef struct {
    int status, iterations, monitor_calls;
    double residual;
    char message[256], thread_error[256];
    double x[MAXN * MAXN], y[MAXN * MAXN];
} result;

typedef struct {
    eg2d_grid *grid;
    int calls;
    double *scratch_x, *scratch_y;
} monitor_state;

/* Reads its own grid from inside the run, as eg2d.h allows. */
static int monitor(void *user, int iteration, double residual) {
    monitor_state *m = (monitor_state *)user;
    int it = -1;
    (void)residual;
    ++m->calls;
    if (eg2d_get_iterations(m->grid, &it) != EG2D_OK || it != iteration) return 1;
    return eg2d_get_coordinates(m->grid, m->scratch_x, m->scratch_y) != EG2D_OK;
}

/* Job k: a grid decided by k alone. */
static void run_job(int k, result *r) {
    static const char *const domains[] = {"valley", "almost-convex", "swan", "dome", "quad"};
    const int n = 9 + 2 * (k % 5); /* 9 .. 17 */
    double sx[MAXN * MAXN], sy[MAXN * MAXN];
    monitor_state m;
    eg2d_grid *g = NULL;
    memset(r, 0, sizeof *r);
    /* A failing create first: its message is this thread's own. */
    r->status = eg2d_create(-k, n, &g);
    snprintf(r->thread_error, sizeof r->thread_error, "%s", eg2d_last_error(NULL));
    if (eg2d_create(n, n, &g) != EG2D_OK) {
        r->status = -1;
        return;
    }
    m.grid = g;
    m.calls = 0;
    m.scratch_x = sx;
    m.scratch_y = sy;
    domain_set(g, domains[k % 5]);
    eg2d_set_system(g, k % 3 == 0 ? EG2D_SYSTEM_LAPLACE : EG2D_SYSTEM_WINSLOW);
    eg2d_set_relaxation(g, k % 4 == 0 ? 0.0 : 1.0 + 0.1 * (k % 9));
    eg2d_set_tolerance(g, 1e-9);
    eg2d_set_max_iterations(g, 150 + k % 50); /* some converge, some do not */
    eg2d_set_monitor(g, monitor, &m);
    if (k % 7 == 0) eg2d_set_side(g, 9, sx, sy); /* a failing call, then carry on */
    r->status = eg2d_solve(g);
    snprintf(r->message, sizeof r->message, "%s", eg2d_last_error(g));
    eg2d_get_iterations(g, &r->iterations);
    eg2d_get_residual(g, &r->residual);
    eg2d_get_coordinates(g, r->x, r->y);
    r->monitor_calls = m.calls;
    eg2d_destroy(g);
}

typedef struct {
    int thread;
    result *results;
} worker_arg;

static void *worker(void *p) {
    const worker_arg *a = (const worker_arg *)p;
    int j;
    for (j = 0; j < GRIDS; ++j) run_job(a->thread * GRIDS + j, &a->results[a->thread * GRIDS + j]);
    return NULL;
}

static void test_threads_match_serial(void **state) {
    result *serial = calloc(THREADS * GRIDS, sizeof(result));
    result *parallel = calloc(THREADS * GRIDS, sizeof(result));
    pthread_t threads[THREADS];
    worker_arg args[THREADS];
    int k, t, converged = 0, failed = 0, iterations = 0;
    (void)state;
    assert_non_null(serial);
    assert_non_null(parallel);
    for (k = 0; k < THREADS * GRIDS; ++k) run_job(k, &serial[k]);
    for (t = 0; t < THREADS; ++t) {
        args[t].thread = t;
        args[t].results = parallel;
        assert_int_equal(pthread_create(&threads[t], NULL, worker, &args[t]), 0);
    }
    for (t = 0; t < THREADS; ++t) assert_int_equal(pthread_join(threads[t], NULL), 0);
    for (k = 0; k < THREADS * GRIDS; ++k) {
        char expected[64];
        snprintf(expected, sizeof expected, "eg2d_create: ni = %d: need at least 3", -k);
        assert_string_equal(parallel[k].thread_error, expected);
        assert_int_not_equal(serial[k].status, EG2D_ERR_INTERRUPTED); /* the monitor's reads all worked */
        assert_int_equal(serial[k].monitor_calls, serial[k].iterations);
        if (memcmp(&serial[k], &parallel[k], sizeof(result)) != 0)
            fail_msg("job %d: threaded result differs from the serial one (status %d vs %d, \"%s\" vs \"%s\")", k,
                     parallel[k].status, serial[k].status, parallel[k].message, serial[k].message);
        iterations += serial[k].iterations;
        converged += serial[k].status == EG2D_OK;
        failed += serial[k].status != EG2D_OK;
    }
    /* The jobs are a mix: some converge, some stop at the limit or fold. */
    assert_true(converged > 0);
    assert_true(failed > 0);
    print_message("%d jobs on %d threads bitwise equal to serial: %d converged, %d failed, %d iterations\n",
                  THREADS * GRIDS, THREADS, converged, failed, iterations);
    free(serial);
    free(parallel);
}

/* The handle-free calls from many threads at once. */
static void *handle_free_calls(void *p) {
    int k, *bad = (int *)p;
    for (k = 0; k < 2000; ++k) {
        double lo, hi, def;
        int ma, mi, pa;
        eg2d_version(&ma, &mi, &pa);
        *bad |= eg2d_status_string(k % 12) == NULL;
        *bad |= eg2d_solver_name(EG2D_SOLVER_PSOR) == NULL;
        *bad |= eg2d_parameter_bounds(k % 5, &lo, &hi, &def) != EG2D_OK;
    }
    return NULL;
}

static void test_handle_free_calls_concurrently(void **state) {
    pthread_t threads[THREADS];
    int bad[THREADS] = {0}, t;
    (void)state;
    for (t = 0; t < THREADS; ++t) assert_int_equal(pthread_create(&threads[t], NULL, handle_free_calls, &bad[t]), 0);
    for (t = 0; t < THREADS; ++t) {
        assert_int_equal(pthread_join(threads[t], NULL), 0);
        assert_int_equal(bad[t], 0);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_threads_match_serial),
        cmocka_unit_test(test_handle_free_calls_concurrently),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
