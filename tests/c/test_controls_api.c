/* The control API's contract: every argument checked with a precise
 * message, a failed call changes nothing, controls need the Winslow system,
 * and the control parameters' bounds. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

#define NI 13
#define NJ 9

static void expect_error(eg2d_grid *g, int status, int want, const char *text) {
    if (status != want) fail_msg("status %d, not %d, for the call that should say \"%s\"", status, want, text);
    if (!strstr(eg2d_last_error(g), text)) fail_msg("message \"%s\" lacks \"%s\"", eg2d_last_error(g), text);
}

/* Every control call with bad arguments fails with EG2D_ERR_ARGUMENT and a
 * message naming the problem; the grid then solves exactly like a grid that
 * never saw the failed calls. */
static void test_bad_arguments_change_nothing(void **state) {
    eg2d_grid *g, *ref;
    double P[NI * NJ], s[NI * NJ], t[NI * NJ], w[NI * NJ], x[NI * NJ], y[NI * NJ], xr[NI * NJ], yr[NI * NJ];
    int k, i, j;
    (void)state;
    for (k = 0; k < NI * NJ; ++k) P[k] = w[k] = 1.0;
    for (j = 0; j < NJ; ++j)
        for (i = 0; i < NI; ++i) {
            s[i + NI * j] = (double)i / (NI - 1);
            t[i + NI * j] = (double)j / (NJ - 1);
        }
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(eg2d_create(NI, NJ, &ref), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    assert_int_equal(domain_set(ref, "valley"), EG2D_OK);
    assert_int_equal(eg2d_add_line_source(g, EG2D_ETA, 0.0, 5.0, 0.5), EG2D_OK);
    assert_int_equal(eg2d_add_line_source(ref, EG2D_ETA, 0.0, 5.0, 0.5), EG2D_OK);

    expect_error(NULL, eg2d_add_line_source(NULL, EG2D_XI, 1, 1, 1), EG2D_ERR_ARGUMENT, "grid is NULL");
    expect_error(g, eg2d_add_line_source(g, 2, 1, 1, 1), EG2D_ERR_ARGUMENT, "direction = 2");
    expect_error(g, eg2d_add_line_source(g, EG2D_XI, 12.5, 1, 1), EG2D_ERR_ARGUMENT, "line = 12.5: must be in [0, 12]");
    expect_error(g, eg2d_add_line_source(g, EG2D_ETA, 8.5, 1, 1), EG2D_ERR_ARGUMENT, "must be in [0, 8]");
    expect_error(g, eg2d_add_line_source(g, EG2D_XI, 1, NAN, 1), EG2D_ERR_ARGUMENT, "amplitude = nan");
    expect_error(g, eg2d_add_line_source(g, EG2D_XI, 1, 1, -1), EG2D_ERR_ARGUMENT, "decay = -1");
    expect_error(g, eg2d_add_line_source(g, EG2D_XI, INFINITY, 1, 1), EG2D_ERR_ARGUMENT, "line = inf");
    expect_error(g, eg2d_add_point_source(g, -1, 1, 1, 1), EG2D_ERR_ARGUMENT, "xi = -1");
    expect_error(g, eg2d_add_point_source(g, 1, 9, 1, 1), EG2D_ERR_ARGUMENT, "eta = 9");
    expect_error(g, eg2d_add_point_source(g, 1, 1, 1, NAN), EG2D_ERR_ARGUMENT, "decay = nan");
    P[17] = NAN;
    expect_error(g, eg2d_set_source_arrays(g, P, NULL), EG2D_ERR_ARGUMENT, "P[17] = nan");
    expect_error(g, eg2d_set_source_arrays(g, NULL, P), EG2D_ERR_ARGUMENT, "Q[17] = nan");
    expect_error(g, eg2d_set_orthogonality(g, 3), EG2D_ERR_ARGUMENT, "method = 3");
    expect_error(g, eg2d_set_wall_spacing(g, 4, 0.1), EG2D_ERR_ARGUMENT, "side = 4");
    expect_error(g, eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, NAN), EG2D_ERR_ARGUMENT, "height = nan");
    expect_error(g, eg2d_set_parameter_grid(g, s, NULL), EG2D_ERR_ARGUMENT, "both");
    s[20] = s[22] + 0.01; /* node (7, 1) beyond its east neighbour: folded at (8, 1) */
    expect_error(g, eg2d_set_parameter_grid(g, s, t), EG2D_ERR_ARGUMENT, "folded or degenerate at node");
    s[20] = NAN;
    expect_error(g, eg2d_set_parameter_grid(g, s, t), EG2D_ERR_ARGUMENT, "s[20] = nan");
    w[5] = -1.0;
    expect_error(g, eg2d_set_weight(g, w), EG2D_ERR_ARGUMENT, "w[5] = -1: must be > 0");
    expect_error(g, eg2d_set_parameter(g, EG2D_PARAM_WALL_DECAY, 0.0), EG2D_ERR_ARGUMENT, "wall_decay = 0");
    expect_error(g, eg2d_set_parameter(g, EG2D_PARAM_WALL_RELAXATION, 1.5), EG2D_ERR_ARGUMENT, "wall_relaxation");

    assert_int_equal(eg2d_set_tolerance(g, 1e-11), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(ref, 1e-11), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_solve(ref), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(ref, xr, yr), EG2D_OK);
    assert_memory_equal(x, xr, sizeof x);
    assert_memory_equal(y, yr, sizeof y);
    eg2d_destroy(g);
    eg2d_destroy(ref);
}

/* An O-grid has no IMIN/IMAX to be a wall. */
static void test_wall_side_must_exist(void **state) {
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(domain_set_annulus(g, 1.0, 2.0), EG2D_OK);
    expect_error(g, eg2d_set_wall_spacing(g, EG2D_SIDE_IMIN, 0.1), EG2D_ERR_ARGUMENT, "side IMIN: the grid's topology");
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, 0.01), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, -1.0), EG2D_OK); /* no wall again */
    eg2d_destroy(g);
}

/* Controls need the Winslow system: with Laplace, iterate and solve fail
 * with EG2D_ERR_STATE and do nothing; removing the controls (or choosing
 * Winslow) runs. Each control kind counts. */
static void test_laplace_refuses_controls(void **state) {
    eg2d_grid *g;
    double P[NI * NJ], w[NI * NJ], s[NI * NJ], t[NI * NJ];
    int it, before, kind, i, j;
    (void)state;
    for (i = 0; i < NI * NJ; ++i) P[i] = w[i] = 1.0;
    for (j = 0; j < NJ; ++j)
        for (i = 0; i < NI; ++i) {
            s[i + NI * j] = (double)i / (NI - 1);
            t[i + NI * j] = (double)j / (NJ - 1);
        }
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    assert_int_equal(eg2d_set_system(g, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    for (kind = 0; kind < 6; ++kind) {
        switch (kind) {
        case 0: assert_int_equal(eg2d_add_point_source(g, 3, 3, 1, 1), EG2D_OK); break;
        case 1: assert_int_equal(eg2d_set_source_arrays(g, P, P), EG2D_OK); break;
        case 2: assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_MIDDLECOFF_THOMAS), EG2D_OK); break;
        case 3: assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK); break;
        case 4: assert_int_equal(eg2d_set_parameter_grid(g, s, t), EG2D_OK); break;
        default: assert_int_equal(eg2d_set_weight(g, w), EG2D_OK); break;
        }
        assert_int_equal(eg2d_get_iterations(g, &before), EG2D_OK);
        expect_error(g, eg2d_solve(g), EG2D_ERR_STATE, "controls need EG2D_SYSTEM_WINSLOW");
        expect_error(g, eg2d_iterate(g, 1, NULL), EG2D_ERR_STATE, "the system is Laplace");
        assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
        assert_int_equal(it, before);
        switch (kind) {
        case 0: assert_int_equal(eg2d_clear_sources(g), EG2D_OK); break;
        case 1: assert_int_equal(eg2d_set_source_arrays(g, NULL, NULL), EG2D_OK); break;
        case 2:
        case 3: assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_NONE), EG2D_OK); break;
        case 4: assert_int_equal(eg2d_set_parameter_grid(g, NULL, NULL), EG2D_OK); break;
        default: assert_int_equal(eg2d_set_weight(g, NULL), EG2D_OK); break;
        }
        assert_int_equal(eg2d_iterate(g, 1, NULL), EG2D_OK); /* no control left */
    }
    eg2d_destroy(g);
}

/* A uniform parameter grid and a constant weight are no control at all:
 * the grid equals the one without (the terms vanish identically). */
static void test_neutral_controls(void **state) {
    eg2d_grid *g;
    double s[NI * NJ], t[NI * NJ], w[NI * NJ], x0[NI * NJ], y0[NI * NJ], x[NI * NJ], y[NI * NJ], err = 0;
    int i, j;
    (void)state;
    for (j = 0; j < NJ; ++j)
        for (i = 0; i < NI; ++i) {
            s[i + NI * j] = (double)i / (NI - 1);
            t[i + NI * j] = (double)j / (NJ - 1);
            w[i + NI * j] = 3.0;
        }
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "swan"), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-12), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x0, y0), EG2D_OK);
    assert_int_equal(eg2d_set_parameter_grid(g, s, t), EG2D_OK);
    assert_int_equal(eg2d_set_weight(g, w), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (i = 0; i < NI * NJ; ++i) err = fmax(err, hypot(x[i] - x0[i], y[i] - y0[i]));
    assert_true(err < 1e-10);
    eg2d_destroy(g);
}

/* eg2d_get_controls: the user's arrays come back as they were set at the
 * unknown nodes (0 on the boundary); a weight's Phi, Psi come back as
 * alpha Phi / J^2, gamma Psi / J^2 from the grid's central differences;
 * the Laplace system and no control give 0; an O-grid's column ni-1 is
 * its column 0. */
static void test_get_controls(void **state) {
    eg2d_grid *g;
    double P[NI * NJ], Q[NI * NJ], w[NI * NJ], x[NI * NJ], y[NI * NJ], gp[NI * NJ], gq[NI * NJ];
    int i, j, k;
    (void)state;
    for (j = 0; j < NJ; ++j)
        for (i = 0; i < NI; ++i) {
            P[i + NI * j] = 0.1 * i - 0.3;
            Q[i + NI * j] = -0.05 * j * j;
            w[i + NI * j] = 1 + 0.2 * i + 0.05 * j * j;
        }
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    expect_error(g, eg2d_get_controls(g, NULL, NULL), EG2D_ERR_ARGUMENT, "P and Q are both NULL");
    for (k = 0; k < NI * NJ; ++k) gp[k] = gq[k] = 7;
    assert_int_equal(eg2d_get_controls(g, gp, gq), EG2D_OK); /* no control */
    for (k = 0; k < NI * NJ; ++k) assert_true(gp[k] == 0 && gq[k] == 0);

    assert_int_equal(eg2d_set_source_arrays(g, P, Q), EG2D_OK);
    assert_int_equal(eg2d_iterate(g, 3, NULL), EG2D_OK);
    assert_int_equal(eg2d_get_controls(g, gp, NULL), EG2D_OK);
    assert_int_equal(eg2d_get_controls(g, NULL, gq), EG2D_OK);
    for (j = 0; j < NJ; ++j)
        for (i = 0; i < NI; ++i) {
            k = i + NI * j;
            if (i == 0 || j == 0 || i == NI - 1 || j == NJ - 1) {
                assert_true(gp[k] == 0 && gq[k] == 0);
            } else {
                assert_true(fabs(gp[k] - P[k]) <= 1e-13 * (1 + fabs(P[k])));
                assert_true(fabs(gq[k] - Q[k]) <= 1e-13 * (1 + fabs(Q[k])));
            }
        }

    assert_int_equal(eg2d_set_source_arrays(g, NULL, NULL), EG2D_OK);
    assert_int_equal(eg2d_set_weight(g, w), EG2D_OK);
    assert_int_equal(eg2d_iterate(g, 2, NULL), EG2D_OK);
    assert_int_equal(eg2d_get_controls(g, gp, gq), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (j = 1; j < NJ - 1; ++j)
        for (i = 1; i < NI - 1; ++i) {
            const int c = i + NI * j, e = c + 1, wst = c - 1, n = c + NI, so = c - NI;
            const double xxi = 0.5 * (x[e] - x[wst]), yxi = 0.5 * (y[e] - y[wst]);
            const double xeta = 0.5 * (x[n] - x[so]), yeta = 0.5 * (y[n] - y[so]);
            const double alpha = xeta * xeta + yeta * yeta, gamma = xxi * xxi + yxi * yxi;
            const double jac = xxi * yeta - xeta * yxi;
            const double phi = 2 * (w[e] - w[wst]) / (w[wst] + 2 * w[c] + w[e]);
            const double psi = 2 * (w[n] - w[so]) / (w[so] + 2 * w[c] + w[n]);
            assert_true(fabs(gp[c] - alpha * phi / (jac * jac)) <= 1e-12 * fabs(alpha * phi / (jac * jac)));
            assert_true(fabs(gq[c] - gamma * psi / (jac * jac)) <= 1e-12 * fabs(gamma * psi / (jac * jac)));
        }
    assert_int_equal(eg2d_set_system(g, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    assert_int_equal(eg2d_get_controls(g, gp, gq), EG2D_OK);
    for (k = 0; k < NI * NJ; ++k) assert_true(gp[k] == 0 && gq[k] == 0);
    eg2d_destroy(g);

    /* O-grid: the cut column repeats column 0 */
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_O), EG2D_OK);
    assert_int_equal(domain_set_annulus(g, 1, 3), EG2D_OK);
    assert_int_equal(eg2d_add_line_source(g, EG2D_XI, 3, 2, 0.5), EG2D_OK);
    assert_int_equal(eg2d_iterate(g, 2, NULL), EG2D_OK);
    assert_int_equal(eg2d_get_controls(g, gp, gq), EG2D_OK);
    for (j = 1; j < NJ - 1; ++j) {
        assert_true(gp[NI * j] != 0 && gp[NI * j] == gp[NI - 1 + NI * j]);
        assert_true(gq[NI * j] == gq[NI - 1 + NI * j]);
    }
    for (i = 0; i < NI; ++i) assert_true(gp[i] == 0 && gp[i + NI * (NJ - 1)] == 0);
    eg2d_destroy(g);
}

static void test_parameter_bounds(void **state) {
    double lo, hi, def;
    (void)state;
    assert_int_equal(eg2d_parameter_bounds(EG2D_PARAM_WALL_DECAY, &lo, &hi, &def), EG2D_OK);
    assert_true(lo == 0.01 && hi == 10.0 && def == 0.3);
    assert_int_equal(eg2d_parameter_bounds(EG2D_PARAM_WALL_RELAXATION, &lo, &hi, &def), EG2D_OK);
    assert_true(lo == 0.0 && hi == 1.0 && def == 0.1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_arguments_change_nothing), cmocka_unit_test(test_wall_side_must_exist),
        cmocka_unit_test(test_laplace_refuses_controls),     cmocka_unit_test(test_neutral_controls),
        cmocka_unit_test(test_parameter_bounds),            cmocka_unit_test(test_get_controls),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
