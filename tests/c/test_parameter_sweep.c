/* Every parameter of the library's table (walked through eg2d_list_*, so a
 * new one is swept without a line here) at its bounds, just inside open
 * ones, at points between and at 0 where 0 means automatic, each in a run
 * that uses it: the run's family of ids picks the grid, the initial grid,
 * the solver or the writer that reads the parameter. Each call ends in a
 * documented status with a message, never EG2D_ERR_INTERNAL; a value just
 * outside the range is refused and changes nothing. The point is the
 * sanitizer builds: the ASan+UBSan suite (float-cast-overflow included) and
 * the clang build of .ci/run run this program, so every value a user may
 * give goes through the code that converts and uses it. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

static char scratch[64];

/* The statuses a run may end with on a valid setting. */
static int documented(int status) { return status >= EG2D_OK && status <= EG2D_ERR_INTERRUPTED; }

#define CALL(expr)                                                                     \
    do {                                                                               \
        const int status_ = (expr);                                                    \
        if (!documented(status_)) fail_msg("%s: status %d: %s", #expr, status_, eg2d_last_error(g)); \
    } while (0)

/* A short run that reads parameter `id` (set to `value` on the fresh grid g). */
static void exercise(eg2d_grid *g, int id, double value) {
    char path[128];
    if (id < 10 || (id >= 110 && id < 200)) { /* the run; multigrid */
        CALL(domain_set(g, "valley"));
        CALL(eg2d_solve(g));
    } else if (id < 100) { /* the variational system */
        CALL(domain_set(g, "swan"));
        CALL(eg2d_set_system(g, EG2D_SYSTEM_VARIATIONAL));
        CALL(eg2d_set_max_iterations(g, 10));
        CALL(eg2d_solve(g));
    } else if (id < 110) { /* approximate factorisation */
        CALL(domain_set_annulus(g, 1.0, 4.0));
        CALL(eg2d_set_solver(g, EG2D_SOLVER_AF));
        CALL(eg2d_set_max_iterations(g, 30));
        CALL(eg2d_solve(g));
    } else if (id < 300) { /* the wall control and its layer */
        CALL(domain_set_airfoil_c(g, "0012", 16, 5.0));
        CALL(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL));
        CALL(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, 1e-3));
        CALL(eg2d_set_max_iterations(g, 5));
        CALL(eg2d_solve(g));
    } else if (id < 400) { /* the files */
        CALL(domain_set(g, "dome"));
        CALL(eg2d_initialize(g, EG2D_INIT_TFI));
        snprintf(path, sizeof path, "%s/g.svg", scratch);
        CALL(eg2d_write(g, path, EG2D_FORMAT_SVG));
        snprintf(path, sizeof path, "%s/g.xyz", scratch);
        CALL(eg2d_write(g, path, EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_EXTRUDED));
    } else if (id < 410) { /* Hermite TFI */
        CALL(domain_set(g, "swan"));
        CALL(eg2d_initialize(g, EG2D_INIT_HERMITE));
    } else if (id < 420) { /* the hyperbolic march, round a body and from an open curve */
        CALL(domain_set_airfoil_o(g, "0012", 5.0));
        CALL(eg2d_initialize(g, EG2D_INIT_HYPERBOLIC));
        {
            eg2d_grid *open;
            double x[33], y[33];
            int i;
            CALL(eg2d_create(33, 17, &open));
            for (i = 0; i < 33; ++i) x[i] = i / 32.0, y[i] = 0.1 * sin(3.0 * x[i]);
            CALL(eg2d_set_side(open, EG2D_SIDE_JMIN, x, y));
            CALL(eg2d_set_parameter(open, id, value));
            CALL(eg2d_initialize(open, EG2D_INIT_HYPERBOLIC));
            eg2d_destroy(open);
        }
    } else { /* airfoil boundaries: an O- and a C-grid made after the setting */
        eg2d_curve *naca;
        int topology;
        CALL(eg2d_curve_naca4("0012", 0, &naca));
        for (topology = EG2D_TOPO_O; topology <= EG2D_TOPO_C; ++topology) CALL(eg2d_set_airfoil(g, naca, topology));
        eg2d_curve_destroy(naca);
        CALL(eg2d_set_max_iterations(g, 3));
        CALL(eg2d_solve(g));
    }
}

/* The values of a sweep over [lo, hi]: the ends (just inside an open one),
 * points between (geometric over a wide positive range), 0 if automatic;
 * whole numbers for an integer parameter. Returns the count. */
static int sweep_values(double lo, double hi, int kind, double *v) {
    const double a = (kind & EG2D_VALUE_OPEN_LOWER) ? nextafter(lo, hi) : lo;
    const double b = (kind & EG2D_VALUE_OPEN_UPPER) ? nextafter(hi, lo) : hi;
    int n = 0, k;
    v[n++] = a;
    v[n++] = b;
    v[n++] = a + 0.5 * (b - a);
    v[n++] = a + 0.1 * (b - a);
    if (a > 0 && b > 1e3 * a) v[n++] = sqrt(a) * sqrt(b);
    if (kind & EG2D_VALUE_AUTOMATIC) v[n++] = 0.0;
    if (kind & EG2D_VALUE_INTEGER)
        for (k = 0; k < n; ++k) v[k] = v[k] == b ? floor(v[k]) : ceil(v[k]);
    return n;
}

static void every_value_of_every_parameter(void **state) {
    int count, k, swept = 0, refused = 0;
    (void)state;
    assert_int_equal(eg2d_list_count(EG2D_LIST_PARAMETERS, &count), EG2D_OK);
    for (k = 0; k < count; ++k) {
        int id, kind, n, m;
        const char *name;
        double lo, hi, def, v[8];
        assert_int_equal(eg2d_list_entry(EG2D_LIST_PARAMETERS, k, &id, &name), EG2D_OK);
        assert_int_equal(eg2d_parameter_bounds(id, &lo, &hi, &def), EG2D_OK);
        assert_int_equal(eg2d_parameter_info(id, &kind, NULL, NULL), EG2D_OK);
        n = sweep_values(lo, hi, kind, v);
        for (m = 0; m < n; ++m) {
            eg2d_grid *g;
            double got;
            assert_int_equal(eg2d_create(33, 17, &g), EG2D_OK);
            if (eg2d_set_parameter(g, id, v[m]) != EG2D_OK) {
                /* a value the defaults of the others forbid (every variational
                   weight 0; af_dtau_max below af_dtau_min), said by name */
                assert_non_null(strstr(eg2d_last_error(g), name));
                ++refused;
                eg2d_destroy(g);
                continue;
            }
            assert_int_equal(eg2d_get_parameter(g, id, &got), EG2D_OK);
            assert_true(got == v[m]);
            exercise(g, id, v[m]);
            eg2d_destroy(g);
            ++swept;
        }
        { /* just outside the range: refused, nothing changed */
            eg2d_grid *g;
            const double below = lo - 1 - fabs(lo), above = hi + 1 + fabs(hi); /* never 0 (automatic) */
            double got;
            assert_int_equal(eg2d_create(9, 9, &g), EG2D_OK);
            if (eg2d_set_parameter(g, id, below) != EG2D_ERR_ARGUMENT) fail_msg("%s = %g accepted", name, below);
            assert_non_null(strstr(eg2d_last_error(g), name));
            assert_int_equal(eg2d_set_parameter(g, id, above), EG2D_ERR_ARGUMENT);
            assert_non_null(strstr(eg2d_last_error(g), name));
            assert_int_equal(eg2d_set_parameter(g, id, NAN), EG2D_ERR_ARGUMENT);
            assert_int_equal(eg2d_get_parameter(g, id, &got), EG2D_OK);
            assert_true(got == def);
            eg2d_destroy(g);
        }
    }
    assert_true(swept >= 4 * count);
    assert_true(refused <= 3);
}

static int make_scratch(void **state) {
    (void)state;
    strcpy(scratch, "/tmp/eg2d-sweep-XXXXXX");
    return mkdtemp(scratch) ? 0 : -1;
}

static int remove_scratch(void **state) {
    char path[128];
    (void)state;
    snprintf(path, sizeof path, "%s/g.svg", scratch);
    remove(path);
    snprintf(path, sizeof path, "%s/g.xyz", scratch);
    remove(path);
    return rmdir(scratch);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(every_value_of_every_parameter, make_scratch, remove_scratch),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
