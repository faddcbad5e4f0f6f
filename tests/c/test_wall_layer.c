/* The marched wall layer of EG2D_ORTHO_WALL with EG2D_PARAM_WALL_LAYER = 1
 * (grid/wall_layer.hpp): on a C-grid and on a smooth O-grid the first cells
 * have exactly the asked height, leave the wall at 90 degrees, grow by
 * EG2D_PARAM_WALL_GROWTH row by row, fold nothing, and multigrid converges
 * in a few cycles with the layer held; an O-grid round a sharp trailing edge
 * keeps the Sorenson-type updates (eg2d.h), and the run says which it did. */
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
#include "measure.h"

static double *alloc(int n) {
    double *p = malloc(sizeof(double) * (size_t)n);
    assert_non_null(p);
    return p;
}

/* The run's first event, or "" */
static void first_event(const eg2d_grid *g, char *msg, int size) {
    int n = 0;
    msg[0] = 0;
    assert_int_equal(eg2d_get_run_info(g, EG2D_RUN_EVENTS, &n), EG2D_OK);
    if (n > 0) assert_int_equal(eg2d_get_run_event(g, 0, NULL, msg, size), EG2D_OK);
}

/* Every event of the run, one per line. */
static void all_events(const eg2d_grid *g, char *msg, int size) {
    int n = 0, k, used = 0;
    msg[0] = 0;
    assert_int_equal(eg2d_get_run_info(g, EG2D_RUN_EVENTS, &n), EG2D_OK);
    for (k = 0; k < n && used + 2 < size; ++k) {
        assert_int_equal(eg2d_get_run_event(g, k, NULL, msg + used, size - used - 1), EG2D_OK);
        used += (int)strlen(msg + used);
        msg[used++] = '\n';
        msg[used] = 0;
    }
}

/* Cell height of column i between rows j and j+1. */
static double height(const double *x, const double *y, int ni, int i, int j) {
    return hypot(x[i + ni * (j + 1)] - x[i + ni * j], y[i + ni * (j + 1)] - y[i + ni * j]);
}

/* The least and largest ratio of consecutive cell heights over the first
 * 30 cells of columns first..last (C-grids: the body). */
static void growth_range(const double *x, const double *y, int ni, int first, int last, double *least,
                         double *worst) {
    int i, j;
    *least = 10;
    *worst = 0;
    for (i = first; i <= last; ++i)
        for (j = 1; j < 30; ++j) {
            const double q = height(x, y, ni, i, j) / height(x, y, ni, i, j - 1);
            *worst = fmax(*worst, q);
            *least = fmin(*least, q);
        }
}

static void solve_c_grid(double h, int pass_limit) {
    const int ni = 129, nj = 33, wake = 32;
    const double growth = 1.15;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), dev, hmin, hmax, cdev, cmin, cmax, folded, worst = 0, lo = 10;
    int i, j, it, rows;
    char msg[256];
    eg2d_grid *g;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set_airfoil_c(g, "0012", wake, 5.0), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), EG2D_OK);
    assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_WALL_LAYER, 1), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_WALL_GROWTH, growth), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
    assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
    first_event(g, msg, sizeof msg);
    assert_int_equal(sscanf(msg, "wall layer: %d rows", &rows), 1);
    assert_int_equal(rows, (nj - 1) / 3);
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
    assert_true(folded == 0);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    measure_wall(x, y, ni, nj, EG2D_SIDE_JMIN, 0, wake + 1, ni - 1 - wake, &dev, &hmin, &hmax);
    measure_wall(x, y, ni, nj, EG2D_SIDE_JMIN, 0, 1, wake, &cdev, &cmin, &cmax);
    for (i = 0; i < ni; ++i) /* every column, the wake's included */
        for (j = 1; j < rows; ++j) {
            const double q = height(x, y, ni, i, j) / height(x, y, ni, i, j - 1);
            worst = fmax(worst, q);
            lo = fmin(lo, q);
        }
    print_message("C-grid %dx%d, wall %g: %d cycles, %s; airfoil first cell %.6g..%.6g, %.2e deg; cut %.6g..%.6g, "
                  "%.2e deg; growth in the layer %.6f..%.6f\n",
                  ni, nj, h, it, msg, hmin, hmax, dev, cmin, cmax, cdev, lo, worst);
    assert_true(it <= pass_limit);
    assert_true(fabs(hmin / h - 1) < 1e-6 && fabs(hmax / h - 1) < 1e-6 && dev < 0.01);
    assert_true(fabs(cmin / h - 1) < 1e-6 && fabs(cmax / h - 1) < 1e-6 && cdev < 0.01);
    assert_true(fabs(worst - growth) < 1e-6 && fabs(lo - growth) < 1e-6);
    eg2d_destroy(g);
    free(x);
    free(y);
}

/* The Sorenson-type control took 507 iterations at 1e-5 and did not
 * converge at 1e-3 (test_controls_wall). */
static void test_c_grid_layer(void **state) {
    (void)state;
    solve_c_grid(1e-5, 20);
    solve_c_grid(1e-3, 40);
}

/* A circle (no corner): the layer, and every solver but AF converges to it
 * (AF diverges next to the layer's top row: not yet understood; at a 1e-4
 * wall line SOR does too). */
static void test_smooth_o_grid_every_solver(void **state) {
    const int ni = 65, nj = 33;
    const double h = 1e-3;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), dev, hmin, hmax;
    int id;
    (void)state;
    for (id = 0; id < 100; ++id) {
        eg2d_grid *g;
        int it;
        char msg[256];
        if (!eg2d_solver_name(id) || id == EG2D_SOLVER_AF) continue;
        assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
        assert_int_equal(domain_set_annulus(g, 1.0, 10.0), EG2D_OK);
        assert_int_equal(eg2d_set_solver(g, id), EG2D_OK);
        assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), EG2D_OK);
        assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
        assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_WALL_LAYER, 1), EG2D_OK);
        assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
        if (eg2d_solve(g) != EG2D_OK) fail_msg("%s: %s", eg2d_solver_name(id), eg2d_last_error(g));
        assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        measure_wall(x, y, ni, nj, EG2D_SIDE_JMIN, 1, 0, ni - 1, &dev, &hmin, &hmax);
        first_event(g, msg, sizeof msg);
        print_message("annulus 1..10 %dx%d, wall %g, %-9s %4d iterations, first cell %.6g..%.6g, %.1e deg\n", ni, nj,
                      h, eg2d_solver_name(id), it, hmin, hmax, dev);
        assert_non_null(strstr(msg, "wall layer: 10 rows"));
        assert_true(fabs(hmin / h - 1) < 1e-9 && fabs(hmax / h - 1) < 1e-9 && dev < 1e-6);
        if (id == EG2D_SOLVER_MULTIGRID) assert_true(it <= 10);
        eg2d_destroy(g);
    }
    free(x);
    free(y);
}

/* The notes of one iteration on a NACA 0012 O-grid in a circle of
 * `radius` chords, wall control at height h with EG2D_PARAM_WALL_LAYER `layer`. */
static void note_of_one_iteration(int ni, int nj, double radius, double h, int layer, char *msg, int size) {
    eg2d_grid *g;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set_airfoil_o(g, "0012", radius), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), EG2D_OK);
    assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_WALL_LAYER, layer), EG2D_OK);
    assert_int_equal(eg2d_iterate(g, 1, NULL), EG2D_OK);
    all_events(g, msg, size);
    eg2d_destroy(g);
}

/* Round a sharp trailing edge the rows above a thin layer cannot yet turn
 * robustly: the O-grid keeps the Sorenson-type control, and no layer is said. */
static void test_sharp_o_grid_keeps_the_control(void **state) {
    char msg[256];
    (void)state;
    note_of_one_iteration(65, 17, 10.0, 1e-3, 1, msg, sizeof msg);
    assert_null(strstr(msg, "wall layer"));
}

/* The hybrid layer (EG2D_PARAM_WALL_LAYER = 2) round the sharp trailing edge
 * of a NACA 0012 O-grid, far field 15 chords: every solver converges to a
 * grid without folds whose first cells have the height (within 0.1%) and
 * leave the wall within 0.5 degrees, growing no faster than the march's
 * schedule; multigrid in a few cycles. */
static void hybrid_o_grid(int ni, int nj, double h, int solver, int cycle_limit, double growth_limit, int layer) {
    double *x = alloc(ni * nj), *y = alloc(ni * nj), dev, hmin, hmax, folded, worst = 0;
    int it, i, j, rows;
    char msg[256];
    eg2d_grid *g;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set_airfoil_o(g, "0012", 15.0), EG2D_OK);
    assert_int_equal(eg2d_set_solver(g, solver), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), EG2D_OK);
    assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
    if (layer >= 0) assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_WALL_LAYER, layer), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    if (eg2d_solve(g) != EG2D_OK) fail_msg("%s: %s", eg2d_solver_name(solver), eg2d_last_error(g));
    assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
    first_event(g, msg, sizeof msg);
    assert_int_equal(sscanf(msg, "wall layer (hybrid): %d rows of the hyperbolic march held", &rows), 1);
    assert_int_equal(rows, 2 * (nj - 1) / 3);
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
    assert_true(folded == 0);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    measure_wall(x, y, ni, nj, EG2D_SIDE_JMIN, 1, 0, ni - 1, &dev, &hmin, &hmax);
    for (i = 0; i < ni - 1; ++i)
        for (j = 1; j < 30 && j < nj - 1; ++j) worst = fmax(worst, height(x, y, ni, i, j) / height(x, y, ni, i, j - 1));
    print_message("hybrid NACA 0012 O-grid %dx%d, wall %g, %-9s %4d iterations, first cell %.6g..%.6g, %.2e deg, "
                  "growth over 30 cells %.3f\n", ni, nj, h, eg2d_solver_name(solver), it, hmin, hmax, dev, worst);
    assert_true(fabs(hmin / h - 1) < 1e-3 && fabs(hmax / h - 1) < 1e-3);
    assert_true(dev < 0.5);
    assert_true(worst <= growth_limit);
    if (cycle_limit > 0) assert_true(it <= cycle_limit);
    eg2d_destroy(g);
    free(x);
    free(y);
}

static void test_hybrid_sharp_o_grid(void **state) {
    int id;
    (void)state;
    for (id = 0; id < 100; ++id)
        if (eg2d_solver_name(id)) hybrid_o_grid(129, 65, 1e-5, id, id == EG2D_SOLVER_MULTIGRID ? 10 : 0, 1.29, 2);
    /* Construct2D's default case: 250x100, first cell 1.04e-5 chord */
    hybrid_o_grid(250, 100, 1.04e-5, EG2D_SOLVER_MULTIGRID, 10, 1.2, 2);
}

/* The default, EG2D_PARAM_WALL_LAYER = 3 (automatic): a user who sets only a
 * first-cell height and solves gets the hybrid layer where its rows grow by
 * at most 1.25 and its first cells are within 1% and 0.5 degrees
 * (Construct2D's case, 250x100 at 1.04e-5 chord, far field 15 chords: growth
 * <= 1.2 over the first 30 cells, 10 cycles at most), and the Sorenson-type
 * control, which meets the height and the angle exactly, where they are not
 * (65x17: 16 rows to 10 chords grow by 2.1), saying why. */
static void test_default_is_automatic(void **state) {
    double value = -1, *x = alloc(65 * 17), *y = alloc(65 * 17), dev, hmin, hmax;
    char msg[1024];
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_create(9, 9, &g), EG2D_OK);
    assert_int_equal(eg2d_get_parameter(g, EG2D_PARAM_WALL_LAYER, &value), EG2D_OK);
    assert_true(value == 3.0);
    eg2d_destroy(g);
    hybrid_o_grid(250, 100, 1.04e-5, EG2D_SOLVER_MULTIGRID, 10, 1.2, -1);
    assert_int_equal(eg2d_create(65, 17, &g), EG2D_OK);
    assert_int_equal(domain_set_airfoil_o(g, "0012", 10.0), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, 1e-4), EG2D_OK);
    assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    first_event(g, msg, sizeof msg);
    print_message("65x17 at 1e-4, default: %s\n", msg);
    assert_non_null(strstr(msg, "wall layer (automatic): the hybrid layer would grow by 2.0"));
    assert_non_null(strstr(msg, "the wall control's updates instead"));
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    measure_wall(x, y, 65, 17, EG2D_SIDE_JMIN, 1, 0, 64, &dev, &hmin, &hmax);
    assert_true(fabs(hmin / 1e-4 - 1) < 1e-3 && fabs(hmax / 1e-4 - 1) < 1e-3);
    eg2d_destroy(g);
    free(x);
    free(y);
}

/* A march that folds at its default dissipation goes on with more from a
 * little before the fold (NACA 0012 513x25 to 500 chords at 1e-5: layer 22,
 * so from the wall), and one that folds then too (at 1e-7: layer 2 at every
 * dissipation) leaves the Sorenson-type control; the run says which. Until
 * the march took up to 64 sub-steps a layer, NACA 0012 O-grids 385x97 and
 * 897x257 to 100 chords at 1e-5 were these cases; they march now. */
static void test_hybrid_retries_then_falls_back_and_says_so(void **state) {
    char msg[1024];
    (void)state;
    note_of_one_iteration(385, 97, 100.0, 1e-5, 2, msg, sizeof msg);
    assert_non_null(strstr(msg, "wall layer (hybrid): 64 rows of the hyperbolic march held"));
    assert_null(strstr(msg, "march: layer "));
    note_of_one_iteration(513, 25, 500.0, 1e-5, 2, msg, sizeof msg);
    print_message("513x25 at 1e-5: %s\n", msg);
    assert_non_null(strstr(msg, "wall layer (hybrid): 16 rows of the hyperbolic march held"));
    assert_non_null(strstr(msg, "wall layer (hybrid): march: layer "));
    assert_non_null(strstr(msg, "marched on from layer 1 with 1"));
    note_of_one_iteration(513, 25, 500.0, 1e-7, 2, msg, sizeof msg);
    print_message("513x25 at 1e-7: %s\n", msg);
    assert_non_null(strstr(msg, "wall layer (hybrid) not made: march: layer "));
    assert_non_null(strstr(msg, "; the wall control's updates instead"));
}

/* The hybrid layer on a C-grid as flow solvers ask for it, by default:
 * NACA 0012 385x97, y+ = 1 at Re = 6e6, far field 100 chords, the section
 * clustered at its edges and the cut growing geometrically from the
 * trailing edge's spacing. Converged in a few cycles without folds; every
 * body node's first cell has the height (the trailing edge's included);
 * every body column grows by at least 1 and at most 1.2 over its first 30
 * cells; the lines leave the body within 0.5 degrees; no wake cell is
 * skewed beyond 45 degrees; the cut's first cells grow downstream. */
static void test_hybrid_c_grid(void **state) {
    const int ni = 385, nj = 97, wake = 80;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), *skew = alloc((ni - 1) * (nj - 1)), h, dev, hmin, hmax, folded;
    double worst = 0, least = 10, wake_skew = 0, cut_prev = 0;
    int it, i, j;
    char msg[2048];
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_first_cell_height(1.0, 6e6, 1.0, &h), EG2D_OK);
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set_airfoil_c_graded(g, "0012", wake, 100.0, 1e-3, 2e-3), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), EG2D_OK);
    assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
    assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
    all_events(g, msg, sizeof msg);
    assert_non_null(strstr(msg, "wall layer (hybrid): 64 rows of the hyperbolic march held"));
    assert_non_null(strstr(msg, "the far field's nodes moved along it"));
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
    assert_true(folded == 0);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    measure_wall(x, y, ni, nj, EG2D_SIDE_JMIN, 0, wake, ni - wake, &dev, &hmin, &hmax);
    growth_range(x, y, ni, wake, ni - 1 - wake, &least, &worst);
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, skew), EG2D_OK);
    for (j = 0; j < nj - 1; ++j)
        for (i = 0; i < ni - 1; ++i)
            if (i < wake || i >= ni - 1 - wake) wake_skew = fmax(wake_skew, skew[i + (ni - 1) * j]);
    /* The lower cut from the trailing edge to the outflow: the first cells
       grow, then stay level in the far wake, where they follow the layer's
       thickness (within 1%). */
    for (i = wake - 1; i >= 1; --i) {
        const double c = height(x, y, ni, i, 0);
        assert_true(c >= cut_prev * (1 - 1e-2));
        cut_prev = c;
    }
    assert_true(cut_prev > 10 * h);
    print_message("hybrid NACA 0012 C-grid %dx%d, y+ 1 at Re 6e6 (%.3g), 100 chords: %d cycles, first cell %.6g..%.6g, "
                  "%.3f deg, growth %.4f..%.4f over 30 cells, wake skew %.1f deg, cut's first cell %.3g at the "
                  "outflow\n", ni, nj, h, it, hmin, hmax, dev, least, worst, wake_skew, cut_prev);
    assert_true(it <= 10);
    assert_true(fabs(hmin / h - 1) < 1e-3 && fabs(hmax / h - 1) < 1e-3);
    assert_true(dev <= 0.5);
    assert_true(least >= 1.0 && worst <= 1.2);
    assert_true(wake_skew <= 45.0);
    assert_true(cut_prev > 10 * h);
    eg2d_destroy(g);
    free(x);
    free(y);
    free(skew);
}

/* The C-grid that eg2d_set_airfoil builds (NACA 0012, 385x97, its default
 * cut), across first cells from 1e-6 to 2e-5 chord and far fields of 100
 * and 500 chords: the wake's largest skew depended on the first cell (21-62
 * degrees) before the C-grid's march started at more dissipation and the
 * cut's columns were re-spaced to one shape (bench/RESULTS.md). Each: the
 * hybrid layer, a few cycles, no folds, first cells within 2% over the
 * body, growth 1..1.2 over 30 cells (1.25 to 500 chords), the wake's cells
 * within 45 degrees, and the cells above the held layer on the cut at most
 * the body's growth times its last (the spacing does not jump where the
 * solve takes over: it did by 2.4-11 before). */
static void test_hybrid_c_grid_first_cells(void **state) {
    const int ni = 385, nj = 97, rows = 64;
    const double cells[] = {1e-6, 4.46e-6, 1e-5, 2e-5}, radii[] = {100, 500};
    double *x = alloc(ni * nj), *y = alloc(ni * nj), *skew = alloc((ni - 1) * (nj - 1));
    eg2d_curve *foil;
    int r, c, i, j;
    (void)state;
    assert_int_equal(eg2d_curve_naca4("0012", EG2D_NACA_CLOSED_TE, &foil), EG2D_OK);
    for (r = 0; r < 2; ++r)
        for (c = 0; c < 4; ++c) {
            const double h = cells[c];
            double folded, dev, hmin, hmax, worst, least, wake_skew = 0, jump = 0;
            int it, wake;
            eg2d_grid *g;
            assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
            assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_FARFIELD, radii[r]), EG2D_OK);
            assert_int_equal(eg2d_set_airfoil(g, foil, EG2D_TOPO_C), EG2D_OK);
            assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), EG2D_OK);
            assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
            assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
            if (eg2d_solve(g) != EG2D_OK) fail_msg("%g chords, %g: %s", radii[r], h, eg2d_last_error(g));
            assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
            assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
            assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
            assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, skew), EG2D_OK);
            for (wake = 0; x[wake + 1] == x[ni - 2 - wake] && y[wake + 1] == y[ni - 2 - wake]; ++wake) {
            } /* the trailing edge: the last node the cut's two sides share */
            assert_true(wake > 0 && wake < ni / 2);
            measure_wall(x, y, ni, nj, EG2D_SIDE_JMIN, 0, wake, ni - wake, &dev, &hmin, &hmax);
            growth_range(x, y, ni, wake, ni - 1 - wake, &least, &worst);
            for (j = 0; j < nj - 1; ++j)
                for (i = 0; i < ni - 1; ++i)
                    if (i < wake || i >= ni - 1 - wake) wake_skew = fmax(wake_skew, skew[i + (ni - 1) * j]);
            for (i = 0; i < wake; ++i)
                jump = fmax(jump, height(x, y, ni, i, rows) / height(x, y, ni, i, rows - 1));
            print_message("eg2d_set_airfoil C-grid %dx%d to %g chords, first cell %g: %d cycles, first cell "
                          "%.4g..%.4g, %.3f deg, growth %.4f..%.4f, wake skew %.1f deg, cut's spacing above the "
                          "layer %.3f x its last\n", ni, nj, radii[r], h, it, hmin, hmax, dev, least, worst, wake_skew,
                          jump);
            assert_true(folded == 0);
            assert_true(it <= 10);
            assert_true(fabs(hmin / h - 1) < 0.02 && fabs(hmax / h - 1) < 0.02);
            assert_true(dev <= 0.5);
            /* 96 rows from 1e-6 to 500 chords grow by 1.21 at least */
            assert_true(least >= 1.0 && worst <= (radii[r] > 100 ? 1.25 : 1.2));
            assert_true(wake_skew <= 45.0);
            assert_true(jump <= 1.05 * worst);
            eg2d_destroy(g);
        }
    eg2d_curve_destroy(foil);
    free(x);
    free(y);
    free(skew);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_c_grid_layer),
        cmocka_unit_test(test_smooth_o_grid_every_solver),
        cmocka_unit_test(test_sharp_o_grid_keeps_the_control),
        cmocka_unit_test(test_hybrid_sharp_o_grid),
        cmocka_unit_test(test_hybrid_retries_then_falls_back_and_says_so),
        cmocka_unit_test(test_default_is_automatic),
        cmocka_unit_test(test_hybrid_c_grid),
        cmocka_unit_test(test_hybrid_c_grid_first_cells),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
