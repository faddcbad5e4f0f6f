/* Attraction sources and user source arrays: Petrilli's (1989) p1/p2 against an
 * independent one-dimensional solution and on its three channels, the
 * line clustering of Ly & Norrison (2007) (mu = 100, kappa = 0.2) on an annulus O-grid against
 * the exact radial recurrence, point sources and xi-lines across the O-grid
 * cut. Every solver. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "channels.h"
#include "domains.h"
#include "eg2d.h"
#include "measure.h"

#define PI 3.14159265358979323846

static double *alloc(int n) {
    double *p = malloc(sizeof(double) * (size_t)n);
    assert_non_null(p);
    return p;
}

/* Petrilli's (1989) column values p1 = -20, -10 at i = 1, 2 and i = ni-1, ni-2 on
 * every row of the rectangle [0, 1] x [0, 2] at the listing's 9 x 33 nodes,
 * with the points of JMIN and JMAX at X(i) and a uniform interior to start
 * from. The grid x = X(i), y = 2j/(nj-1) is then exact, with X solving the 1-D
 * equation X_{i+1} - 2 X_i + X_{i-1} + P_i ((X_{i+1} - X_{i-1})/2)^3 = 0
 * (alpha x_xixi + J^2 P x_xi with alpha = y_eta^2, J^2 = x_xi^2 y_eta^2),
 * which we solve here on its own. The first cell's factor against the
 * uniform 1/8 is the expected factor of the sources; the library must give
 * the same grid. */
static void test_user_source_arrays_expected_factor(void **state) {
    const int ni = 9, nj = 33;
    double X[9], Pc[9] = {0, -20, -10, 0, 0, 0, -10, -20, 0};
    double *P = alloc(ni * nj), *x = alloc(ni * nj), *y = alloc(ni * nj);
    int i, j, sweep, id;
    (void)state;
    for (i = 0; i < ni; ++i) X[i] = (double)i / (ni - 1);
    for (sweep = 0; sweep < 20000; ++sweep)
        for (i = 1; i < ni - 1; ++i) {
            const double d = 0.5 * (X[i + 1] - X[i - 1]);
            X[i] = 0.5 * (X[i + 1] + X[i - 1]) + 0.5 * Pc[i] * d * d * d;
        }
    for (j = 0; j < nj; ++j)
        for (i = 0; i < ni; ++i) P[i + ni * j] = Pc[i];
    for (id = 0; id < 100; ++id) {
        eg2d_grid *g;
        double err = 0.0;
        int it;
        if (!eg2d_solver_name(id)) continue;
        assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
        assert_int_equal(domain_set_rectangle_columns(g, X, 2.0), EG2D_OK); /* the boundary follows X too */
        assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        for (j = 1; j < nj - 1; ++j)
            for (i = 1; i < ni - 1; ++i) x[i + ni * j] = (double)i / (ni - 1);
        assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
        assert_int_equal(eg2d_set_source_arrays(g, P, NULL), EG2D_OK);
        assert_int_equal(eg2d_set_solver(g, id), EG2D_OK);
        assert_int_equal(eg2d_set_tolerance(g, 1e-12), EG2D_OK);
        if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
        assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        for (j = 0; j < nj; ++j)
            for (i = 0; i < ni; ++i) {
                err = fmax(err, fabs(x[i + ni * j] - X[i]));
                err = fmax(err, fabs(y[i + ni * j] - 2.0 * j / (nj - 1)));
            }
        print_message("Petrilli (1989) p1 columns, %s: %d iterations; first cells %.5f and %.5f (factors %.3f, %.3f of 1/8), "
                      "distance from the 1-D solution %.1e\n",
                      eg2d_solver_name(id), it, X[1] - X[0], X[ni - 1] - X[ni - 2], (X[1] - X[0]) * 8,
                      (X[ni - 1] - X[ni - 2]) * 8, err);
        assert_true(it > 0); /* it had work to do */
        assert_true(err < 1e-9);
        eg2d_destroy(g);
    }
    /* Negative P pushes xi-lines to lower i (a comment of Petrilli 1989): both sides. */
    assert_true(X[1] - X[0] < 0.125 && X[ni - 1] - X[ni - 2] > 0.125);
    free(P);
    free(x);
    free(y);
}

/* Solves channel `geom` (listing size 9 x 33) with or without its p1/p2 and
 * with or without wall orthogonality at its two walls. Returns the status. */
static int solve_channel(int geom, int sources, int walls, int solver, double *x, double *y, int *iterations) {
    const int ni = 9, nj = 33;
    double *P = alloc(ni * nj), *Q = alloc(ni * nj);
    eg2d_grid *g;
    int status;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(channel_set(g, geom), EG2D_OK);
    channel_sources(geom, ni, nj, P, Q);
    if (sources) assert_int_equal(eg2d_set_source_arrays(g, P, Q), EG2D_OK);
    if (walls) {
        assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_IMIN, 0.0), EG2D_OK);
        assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_IMAX, 0.0), EG2D_OK);
        assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
    }
    assert_int_equal(eg2d_set_solver(g, solver), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    status = eg2d_solve(g);
    if (status != EG2D_OK && status != EG2D_ERR_FOLDED) fail_msg("%s", eg2d_last_error(g));
    assert_int_equal(eg2d_get_iterations(g, iterations), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    eg2d_destroy(g);
    free(P);
    free(Q);
    return status;
}

/* Petrilli's (1989) three channels with its p1/p2. Channel 1 converges unfolded
 * in plain Winslow; the sources pull the xi-lines toward i = 0 in rows
 * 13..19 (p1 < 0 at i = 1, 2): the first cell next to the outer corner
 * (row 16) shrinks and the last one (i = 7..8) grows, while rows far from
 * the sources keep their spacing. Channels 2 and 3 have re-entrant corners at
 * which the converged Winslow grid folds (with or without the sources); with
 * the wall orthogonality on the channel walls (test_controls_wall) all three
 * converge unfolded, and the sources act the same way there. */
static void test_petrilli_channels(void **state) {
    const int ni = 9, nj = 33;
    double *x0 = alloc(ni * nj), *y0 = alloc(ni * nj), *x = alloc(ni * nj), *y = alloc(ni * nj);
    int id, it0, it, geom;
    (void)state;
    for (id = 0; id < 100; ++id) {
        double f0, f1, far;
        if (!eg2d_solver_name(id)) continue;
        assert_int_equal(solve_channel(1, 0, 0, id, x0, y0, &it0), EG2D_OK);
        assert_int_equal(solve_channel(1, 1, 0, id, x, y, &it), EG2D_OK);
        f0 = measure_distance(x, y, ni, 0, 16, 1, 16) / measure_distance(x0, y0, ni, 0, 16, 1, 16);
        f1 = measure_distance(x, y, ni, 7, 16, 8, 16) / measure_distance(x0, y0, ni, 7, 16, 8, 16);
        far = measure_distance(x, y, ni, 0, 2, 1, 2) / measure_distance(x0, y0, ni, 0, 2, 1, 2);
        print_message("channel 1, %s: %d iterations with p1/p2 (%d without), unfolded; row 16: first cell x%.3f, "
                      "last cell x%.3f; row 2: x%.3f\n", eg2d_solver_name(id), it, it0, f0, f1, far);
        assert_true(f0 < 0.75);
        assert_true(f1 > 1.15);
        assert_true(fabs(far - 1.0) < 0.05);
        for (geom = 2; geom <= 3; ++geom) {
            double g0, g1;
            int i0, i1;
            /* Rows of the sources' middle: channel 2 p1 = 40 at i = 1..3 round row 19 pushes
               lines to higher i; channel 3 p1 = -20 at i = 1, 2 round row 21 to lower i. */
            const int row = geom == 2 ? 19 : 21;
            assert_int_equal(solve_channel(geom, 1, 0, id, x, y, &it), EG2D_ERR_FOLDED);
            assert_int_equal(solve_channel(geom, 0, 1, id, x0, y0, &it0), EG2D_OK);
            assert_int_equal(solve_channel(geom, 1, 1, id, x, y, &it), EG2D_OK);
            i0 = 0;
            i1 = 1;
            g0 = measure_distance(x, y, ni, i0, row, i1, row) / measure_distance(x0, y0, ni, i0, row, i1, row);
            g1 = measure_distance(x, y, ni, 7, row, 8, row) / measure_distance(x0, y0, ni, 7, row, 8, row);
            print_message("channel %d, %s, wall orthogonality: %d iterations with p1/p2 (%d without), unfolded; "
                          "row %d: first cell x%.3f, last cell x%.3f\n",
                          geom, eg2d_solver_name(id), it, it0, row, g0, g1);
            if (geom == 2) assert_true(g0 > 1.1);
            else assert_true(g0 < 0.9);
        }
    }
    free(x0);
    free(y0);
    free(x);
    free(y);
}

/* Ly & Norrison's (2007) clustering toward the body, eq 14 with mu = 100, kappa = 0.2 at
 * the inner wall eta = 0 of the annulus 1 <= r <= 2 (O-grid, 41 x 17). The
 * discrete solution stays rotationally symmetric, x = R_j cos(theta_i), and
 * at theta = 0 the equation reduces to the recurrence
 *   2 R_j (cos d - 1) R_eta^2 + R_j^2 sin^2 d (R_{j+1} - 2 R_j + R_{j-1})
 *     + R_eta^3 R_j^2 sin^2 d Q_j = 0,  Q_j = -mu exp(-kappa j), d = 2 pi/(ni-1),
 * which we solve on its own: the library's grid must be it (and without the
 * source, with Q = 0, too). */
static void radial_solution(int ni, int nj, double mu, double kappa, double *R) {
    const double d = 2 * PI / (ni - 1), s2 = sin(d) * sin(d);
    int j, sweep;
    for (j = 0; j < nj; ++j) R[j] = 1.0 + (double)j / (nj - 1);
    for (sweep = 0; sweep < 200000; ++sweep)
        for (j = 1; j < nj - 1; ++j) {
            const double re = 0.5 * (R[j + 1] - R[j - 1]), q = -mu * exp(-kappa * j);
            const double a = re * re, g = R[j] * R[j] * s2;
            /* a 2R (cos d - 1) + g (R+ - 2R + R-) + a g q re = 0, solved for the R in g's second difference */
            R[j] = 0.5 * (R[j + 1] + R[j - 1]) + (a * 2 * R[j] * (cos(d) - 1) + a * g * q * re) / (2 * g);
        }
}

static void test_line_clustering_toward_body(void **state) {
    const int ni = 41, nj = 17;
    double R0[17], R[17], *x = alloc(ni * nj), *y = alloc(ni * nj);
    int id, pass;
    (void)state;
    radial_solution(ni, nj, 0.0, 0.2, R0);
    radial_solution(ni, nj, 100.0, 0.2, R);
    for (id = 0; id < 100; ++id) {
        if (!eg2d_solver_name(id)) continue;
        for (pass = 0; pass < 2; ++pass) {
            const double *want = pass ? R : R0;
            eg2d_grid *g;
            double err = 0.0, folded;
            int i, j, it;
            assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
            assert_int_equal(domain_set_annulus(g, 1.0, 2.0), EG2D_OK);
            if (pass) assert_int_equal(eg2d_add_line_source(g, EG2D_ETA, 0.0, 100.0, 0.2), EG2D_OK);
            assert_int_equal(eg2d_set_solver(g, id), EG2D_OK);
            assert_int_equal(eg2d_set_tolerance(g, 1e-12), EG2D_OK);
            if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
            assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
            assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
            assert_true(folded == 0.0);
            assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
            for (j = 0; j < nj; ++j)
                for (i = 0; i < ni; ++i) err = fmax(err, fabs(hypot(x[i + ni * j], y[i + ni * j]) - want[j]));
            if (pass)
                print_message("Ly & Norrison (2007) eq 14 (mu 100, kappa 0.2) on the annulus O-grid %dx%d, %s: %d iterations; "
                              "first cell %.5f vs %.5f without (x%.3f), last %.5f vs %.5f; distance from the "
                              "radial solution %.1e\n",
                              ni, nj, eg2d_solver_name(id), it, R[1] - R[0], R0[1] - R0[0],
                              (R[1] - R[0]) / (R0[1] - R0[0]), R[nj - 1] - R[nj - 2], R0[nj - 1] - R0[nj - 2], err);
            assert_true(err < 1e-8);
            eg2d_destroy(g);
        }
    }
    /* Clustered toward the wall: the first cell is smaller, the last larger. */
    assert_true(R[1] - R[0] < 0.7 * (R0[1] - R0[0]));
    assert_true(R[nj - 1] - R[nj - 2] > R0[nj - 1] - R0[nj - 2]);
    free(x);
    free(y);
}

/* An attracting xi-line at the cut of an O-grid acts on both sides of it
 * (distances in xi are periodic), and a point source pulls both families. */
static void test_xi_line_across_cut_and_point(void **state) {
    const int ni = 41, nj = 11;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), a0, a1, a20, uniform = 2 * PI / (ni - 1);
    eg2d_grid *g;
    int id;
    (void)state;
    for (id = 0; id < 100; ++id) {
        if (!eg2d_solver_name(id)) continue;
        assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
        assert_int_equal(domain_set_annulus(g, 1.0, 2.0), EG2D_OK);
        assert_int_equal(eg2d_add_line_source(g, EG2D_XI, 0.0, 10.0, 0.3), EG2D_OK);
        assert_int_equal(eg2d_set_solver(g, id), EG2D_OK);
        assert_int_equal(eg2d_set_tolerance(g, 1e-11), EG2D_OK);
        if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        /* Angular spacing at mid radius, j = 5: cells next to the cut on both sides. */
        a0 = atan2(y[1 + ni * 5], x[1 + ni * 5]) - atan2(y[ni * 5], x[ni * 5]);
        a1 = atan2(y[ni * 5], x[ni * 5]) - atan2(y[ni - 2 + ni * 5], x[ni - 2 + ni * 5]);
        a20 = atan2(y[21 + ni * 5], x[21 + ni * 5]) - atan2(y[20 + ni * 5], x[20 + ni * 5]);
        print_message("xi-line at the cut, %s: cells next to it %.4f and %.4f rad, opposite %.4f (uniform %.4f)\n",
                      eg2d_solver_name(id), a0, a1, a20, uniform);
        assert_true(fabs(a0 - a1) < 1e-9);
        assert_true(a0 < 0.8 * uniform && a20 > uniform);
        assert_int_equal(eg2d_clear_sources(g), EG2D_OK);
        assert_int_equal(eg2d_add_point_source(g, 10.0, 5.0, 10.0, 0.5), EG2D_OK);
        if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        /* Around node (10, 5) both families are pulled in: the cells there are smaller than
           the same cells on the opposite side (30, 5). */
        a0 = measure_distance(x, y, ni, 10, 5, 11, 5) / measure_distance(x, y, ni, 30, 5, 31, 5);
        a1 = measure_distance(x, y, ni, 10, 5, 10, 6) / measure_distance(x, y, ni, 30, 5, 30, 6);
        print_message("point source at (10, 5), %s: cells next to it x%.3f (xi), x%.3f (eta) of the opposite ones\n",
                      eg2d_solver_name(id), a0, a1);
        assert_true(a0 < 0.9 && a1 < 0.95);
        eg2d_destroy(g);
    }
    free(x);
    free(y);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_user_source_arrays_expected_factor),
        cmocka_unit_test(test_petrilli_channels),
        cmocka_unit_test(test_line_clustering_toward_body),
        cmocka_unit_test(test_xi_line_across_cut_and_point),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
