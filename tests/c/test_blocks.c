/* Sets of blocks (eg2d_blocks_*): a set that covers a single block's domain
 * solves to that block's grid, whichever way its blocks are turned; the
 * set's errors name the thing; a backward-facing step in three blocks
 * (block_domains.h) solves without folds and without kinks at its joins;
 * walls across blocks get their first cells, normal lines and no folds. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "block_domains.h"
#include "domains.h"
#include "eg2d.h"

/* The reference domain: the bump of block_domains.h, NI x NJ. Column
 * MID is where the sets below join their two blocks. */
enum { NI = 33, NJ = 17, MID = 16 };

static void map_left(int i, int j, int *I, int *J, const int *p) { (void)p, *I = i, *J = j; }
static void map_right(int i, int j, int *I, int *J, const int *p) { (void)p, *I = MID + i, *J = j; }
static void map_right_turned(int i, int j, int *I, int *J, const int *p) { (void)p, *I = NI - 1 - i, *J = NJ - 1 - j; }  /* 180 degrees */
static void map_right_quarter(int i, int j, int *I, int *J, const int *p) { (void)p, *I = MID + j, *J = NJ - 1 - i; }     /* 90 degrees */

static eg2d_grid *make_block(int ni, int nj, block_map map) {
    eg2d_grid *g;
    assert_int_equal(bump_block(NI, NJ, ni, nj, map, NULL, &g), EG2D_OK);
    return g;
}

static eg2d_grid *reference(int system, int solver, int *iterations) {
    eg2d_grid *g = make_block(NI, NJ, map_left);
    assert_int_equal(eg2d_set_system(g, system), EG2D_OK);
    assert_int_equal(eg2d_set_solver(g, solver), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-13), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_iterations(g, iterations), EG2D_OK);
    return g;
}

/* The largest distance between a block's nodes and the reference's. */
static double distance_to(const eg2d_grid *ref, const eg2d_grid *g, int ni, int nj, block_map map) {
    double *rx = malloc(sizeof(double) * NI * NJ), *ry = malloc(sizeof(double) * NI * NJ);
    double *x = malloc(sizeof(double) * (size_t)(ni * nj)), *y = malloc(sizeof(double) * (size_t)(ni * nj));
    assert_int_equal(eg2d_get_coordinates(ref, rx, ry), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    double worst = 0.0;
    for (int j = 0; j < nj; ++j)
        for (int i = 0; i < ni; ++i) {
            int I, J;
            map(i, j, &I, &J, NULL);
            const double d = hypot(x[i + ni * j] - rx[I + NI * J], y[i + ni * j] - ry[I + NI * J]);
            if (d > worst) worst = d;
        }
    free(rx), free(ry), free(x), free(y);
    return worst;
}

struct turned {
    block_map map;
    int ni, nj;                  /* the right block's size */
    int side, first, last;       /* its side joined to the left block's IMAX 0..NJ-1 */
};

static const struct turned kTurns[] = {
    {map_right, NI - MID, NJ, EG2D_SIDE_IMIN, 0, NJ - 1},
    {map_right_turned, NI - MID, NJ, EG2D_SIDE_IMAX, NJ - 1, 0},
    {map_right_quarter, NJ, NI - MID, EG2D_SIDE_JMIN, NJ - 1, 0},
};

/* Two blocks covering the reference domain, the right one as given, turned
 * by 180 and by 90 degrees, give the single block's grid: the joined
 * column is solved as an interior one; by multigrid over the set in at most
 * twice the single block's cycles, and by point SOR, line SOR and the
 * nested iteration. */
static void test_set_is_the_single_block(void **state) {
    (void)state;
    const int systems[] = {EG2D_SYSTEM_LAPLACE, EG2D_SYSTEM_WINSLOW, EG2D_SYSTEM_LAPLACE, EG2D_SYSTEM_WINSLOW,
                           EG2D_SYSTEM_WINSLOW, EG2D_SYSTEM_WINSLOW};
    const int solvers[] = {EG2D_SOLVER_MULTIGRID, EG2D_SOLVER_MULTIGRID, EG2D_SOLVER_PSOR, EG2D_SOLVER_PSOR,
                           EG2D_SOLVER_LSOR, EG2D_SOLVER_NESTED};
    for (size_t s = 0; s < sizeof solvers / sizeof solvers[0]; ++s) {
        int single;
        eg2d_grid *ref = reference(systems[s], solvers[s], &single);
        for (size_t t = 0; t < sizeof kTurns / sizeof kTurns[0]; ++t) {
            const struct turned *T = &kTurns[t];
            eg2d_grid *left = make_block(MID + 1, NJ, map_left), *right = make_block(T->ni, T->nj, T->map);
            eg2d_blocks *set;
            int b0, b1, iterations, unknowns;
            double residual;
            assert_int_equal(eg2d_blocks_create(&set), EG2D_OK);
            assert_int_equal(eg2d_blocks_add(set, left, &b0), EG2D_OK);
            assert_int_equal(eg2d_blocks_add(set, right, &b1), EG2D_OK);
            assert_int_equal(b0, 0);
            assert_int_equal(b1, 1);
            assert_int_equal(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, NJ - 1, 1, T->side, T->first, T->last), EG2D_OK);
            assert_int_equal(eg2d_set_system(left, systems[s]), EG2D_OK);
            assert_int_equal(eg2d_set_system(right, systems[s]), EG2D_OK);
            assert_int_equal(eg2d_set_tolerance(left, 1e-13), EG2D_OK);
            assert_int_equal(eg2d_set_solver(left, solvers[s]), EG2D_OK);
            /* Before the solve: each block interpolated on its own (TFI). */
            double tfi_at, tfi_near, at, near;
            assert_int_equal(eg2d_initialize(left, EG2D_INIT_TFI), EG2D_OK);
            assert_int_equal(eg2d_initialize(right, EG2D_INIT_TFI), EG2D_OK);
            assert_int_equal(eg2d_blocks_get_kinks(set, &tfi_at, &tfi_near), EG2D_OK);
            assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
            assert_int_equal(eg2d_blocks_get_kinks(set, &at, &near), EG2D_OK);
            printf("turns at the join %.3g degrees (nearby %.3g); TFI blocks %.3g (%.3g)\n", at, near, tfi_at, tfi_near);
            assert_true(at <= near);
            assert_int_equal(eg2d_blocks_get_run(set, &iterations, &residual, &unknowns), EG2D_OK);
            assert_true(residual <= 1e-13);
            assert_int_equal(unknowns, (NI - 2) * (NJ - 2));  /* every interior node of the reference, once */
            const double dl = distance_to(ref, left, MID + 1, NJ, map_left);
            const double dr = distance_to(ref, right, T->ni, T->nj, T->map);
            printf("system %d, solver %d, turn %zu: %d iterations (the single block %d), residual %.2g, largest "
                   "distance to the single block %.2g, %.2g\n", systems[s], solvers[s], t, iterations, single, residual, dl, dr);
            assert_true(dl < 1e-9 && dr < 1e-9);
            if (solvers[s] == EG2D_SOLVER_MULTIGRID) assert_true(iterations <= 2 * single);
            eg2d_blocks_destroy(set);
            eg2d_destroy(left);
            eg2d_destroy(right);
        }
        eg2d_destroy(ref);
    }
}

/* Four blocks round an inner vertex (the reference split at column MID and
 * row 8): the vertex moves to the mean of its four neighbours, which is
 * Laplace's equation there, so the set gives the single block's Laplace
 * grid, multigrid in at most twice its cycles. */
enum { ROW = 8 };
static void map_q0(int i, int j, int *I, int *J, const int *p) { (void)p, *I = i, *J = j; }
static void map_q1(int i, int j, int *I, int *J, const int *p) { (void)p, *I = MID + i, *J = j; }
static void map_q2(int i, int j, int *I, int *J, const int *p) { (void)p, *I = i, *J = ROW + j; }
static void map_q3(int i, int j, int *I, int *J, const int *p) { (void)p, *I = MID + i, *J = ROW + j; }

static void test_inner_vertex(void **state) {
    (void)state;
    const block_map maps[4] = {map_q0, map_q1, map_q2, map_q3};
    const int solvers[2] = {EG2D_SOLVER_MULTIGRID, EG2D_SOLVER_PSOR};
    for (int sv = 0; sv < 2; ++sv) {
        int single, iterations, b;
        eg2d_grid *ref = reference(EG2D_SYSTEM_LAPLACE, solvers[sv], &single), *q[4];
        eg2d_blocks *set;
        assert_int_equal(eg2d_blocks_create(&set), EG2D_OK);
        for (int k = 0; k < 4; ++k) {
            q[k] = make_block(k % 2 ? NI - MID : MID + 1, k < 2 ? ROW + 1 : NJ - ROW, maps[k]);
            assert_int_equal(eg2d_set_system(q[k], EG2D_SYSTEM_LAPLACE), EG2D_OK);
            assert_int_equal(eg2d_blocks_add(set, q[k], &b), EG2D_OK);
        }
        assert_int_equal(eg2d_set_tolerance(q[0], 1e-13), EG2D_OK);
        assert_int_equal(eg2d_set_solver(q[0], solvers[sv]), EG2D_OK);
        assert_int_equal(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, ROW, 1, EG2D_SIDE_IMIN, 0, ROW), EG2D_OK);
        assert_int_equal(eg2d_blocks_join(set, 2, EG2D_SIDE_IMAX, 0, NJ - 1 - ROW, 3, EG2D_SIDE_IMIN, 0, NJ - 1 - ROW), EG2D_OK);
        assert_int_equal(eg2d_blocks_join(set, 0, EG2D_SIDE_JMAX, 0, MID, 2, EG2D_SIDE_JMIN, 0, MID), EG2D_OK);
        assert_int_equal(eg2d_blocks_join(set, 1, EG2D_SIDE_JMAX, 0, NI - 1 - MID, 3, EG2D_SIDE_JMIN, 0, NI - 1 - MID), EG2D_OK);
        assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
        assert_int_equal(eg2d_blocks_get_run(set, &iterations, NULL, NULL), EG2D_OK);
        double worst = 0.0;
        for (int k = 0; k < 4; ++k) {
            const double d = distance_to(ref, q[k], k % 2 ? NI - MID : MID + 1, k < 2 ? ROW + 1 : NJ - ROW, maps[k]);
            if (d > worst) worst = d;
        }
        printf("inner vertex, solver %d: %d iterations (the single block %d), largest distance to the single block %.2g\n",
               solvers[sv], iterations, single, worst);
        assert_true(worst < 1e-9);
        if (solvers[sv] == EG2D_SOLVER_MULTIGRID) assert_true(iterations <= 2 * single);
        eg2d_blocks_destroy(set);
        for (int k = 0; k < 4; ++k) eg2d_destroy(q[k]);
        eg2d_destroy(ref);
    }
}

static void expect(int status, int code, const eg2d_blocks *set, const char *words);

/* Control terms on the blocks: the user's P and Q arrays of the single
 * block, cut with it, give the single block's controlled grid. */
static void set_arrays(eg2d_grid *g, int ni, int nj, block_map map) {
    double *P = malloc(sizeof(double) * (size_t)(ni * nj)), *Q = malloc(sizeof(double) * (size_t)(ni * nj));
    for (int j = 0; j < nj; ++j)
        for (int i = 0; i < ni; ++i) {
            int I, J;
            map(i, j, &I, &J, NULL);
            P[i + ni * j] = 0.4 * sin(3.0 * I / (NI - 1));  /* in the reference's index units */
            Q[i + ni * j] = -0.6 + 0.02 * J;
        }
    assert_int_equal(eg2d_set_source_arrays(g, P, Q), EG2D_OK);
    free(P), free(Q);
}

static void test_controls(void **state) {
    (void)state;
    eg2d_grid *ref = make_block(NI, NJ, map_left);
    int single, iterations, b;
    set_arrays(ref, NI, NJ, map_left);
    assert_int_equal(eg2d_set_tolerance(ref, 1e-13), EG2D_OK);
    assert_int_equal(eg2d_solve(ref), EG2D_OK);
    assert_int_equal(eg2d_get_iterations(ref, &single), EG2D_OK);
    eg2d_grid *left = make_block(MID + 1, NJ, map_left), *right = make_block(NI - MID, NJ, map_right);
    set_arrays(left, MID + 1, NJ, map_left);
    set_arrays(right, NI - MID, NJ, map_right);
    eg2d_blocks *set;
    assert_int_equal(eg2d_blocks_create(&set), EG2D_OK);
    assert_int_equal(eg2d_blocks_add(set, left, &b), EG2D_OK);
    assert_int_equal(eg2d_blocks_add(set, right, &b), EG2D_OK);
    assert_int_equal(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, NJ - 1, 1, EG2D_SIDE_IMIN, 0, NJ - 1), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(left, 1e-13), EG2D_OK);
    assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
    assert_int_equal(eg2d_blocks_get_run(set, &iterations, NULL, NULL), EG2D_OK);
    const double dl = distance_to(ref, left, MID + 1, NJ, map_left), dr = distance_to(ref, right, NI - MID, NJ, map_right);
    printf("source arrays: %d cycles (the single block %d), largest distance to the single block %.2g, %.2g\n",
           iterations, single, dl, dr);
    assert_true(dl < 1e-9 && dr < 1e-9);
    assert_true(iterations <= 2 * single);
    /* Laplace has no place for them: refused, naming the block. */
    assert_int_equal(eg2d_set_system(left, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    assert_int_equal(eg2d_set_system(right, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    expect(eg2d_blocks_solve(set), EG2D_ERR_STATE, set, "block 0 has control terms but the system is Laplace");
    eg2d_blocks_destroy(set);
    eg2d_destroy(left), eg2d_destroy(right), eg2d_destroy(ref);
}

/* The set's run on every block's run information: the solver, the levels
 * and a first event that says what was solved; a set that cannot coarsen
 * (3 cells across) says so in a second event, and still converges. */
static void test_run_events(void **state) {
    (void)state;
    /* 16 and 15 cells across coarsen alike (any size); 3 cannot. */
    const int heights[] = {NJ, NJ - 1, 4}, levels[] = {4, 4, 1};
    for (int h = 0; h < 3; ++h) {
        const int nj = heights[h];
        eg2d_grid *g[2];
        eg2d_blocks *set;
        int value, iteration, events;
        char message[512];
        assert_int_equal(bump_halves(NI, nj, MID, g, &set), EG2D_OK);
        assert_int_equal(eg2d_set_tolerance(g[0], 1e-12), EG2D_OK);
        assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
        for (int k = 0; k < 2; ++k) {
            assert_int_equal(eg2d_get_run_info(g[k], EG2D_RUN_SOLVER, &value), EG2D_OK);
            assert_int_equal(value, EG2D_SOLVER_MULTIGRID);
            assert_int_equal(eg2d_get_run_info(g[k], EG2D_RUN_LEVELS, &value), EG2D_OK);
            assert_int_equal(value, levels[h]);
            assert_int_equal(eg2d_get_run_info(g[k], EG2D_RUN_EVENTS, &events), EG2D_OK);
            assert_int_equal(events, levels[h] > 1 ? 1 : 2);
            assert_int_equal(eg2d_get_run_event(g[k], 0, &iteration, message, sizeof message), EG2D_OK);
            assert_non_null(strstr(message, "set of 2 blocks solved as one grid"));
        }
        if (levels[h] == 1) {
            assert_int_equal(eg2d_get_run_event(g[0], 1, &iteration, message, sizeof message), EG2D_OK);
            printf("%s\n", message);
            assert_non_null(strstr(message, "no coarser level below 1: block 0 has 16 x 3 cells"));
        }
        eg2d_blocks_destroy(set);
        eg2d_destroy(g[0]), eg2d_destroy(g[1]);
    }
}

static void expect(int status, int code, const eg2d_blocks *set, const char *words) {
    if (status != code || !strstr(eg2d_blocks_last_error(set), words))
        fail_msg("status %d (wanted %d): \"%s\" (wanted \"%s\")", status, code, eg2d_blocks_last_error(set), words);
}

static void test_errors(void **state) {
    (void)state;
    eg2d_grid *left = make_block(MID + 1, NJ, map_left), *right = make_block(NI - MID, NJ, map_right);
    eg2d_blocks *set;
    int b;
    assert_int_equal(eg2d_blocks_create(&set), EG2D_OK);
    expect(eg2d_blocks_solve(set), EG2D_ERR_STATE, set, "no blocks");
    assert_int_equal(eg2d_blocks_add(set, left, &b), EG2D_OK);
    expect(eg2d_blocks_add(set, left, &b), EG2D_ERR_ARGUMENT, set, "block 0 of this set already");
    expect(eg2d_blocks_add(set, NULL, &b), EG2D_ERR_ARGUMENT, set, "grid is NULL");
    assert_int_equal(eg2d_blocks_add(set, right, &b), EG2D_OK);
    expect(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, NJ - 1, 2, EG2D_SIDE_IMIN, 0, NJ - 1), EG2D_ERR_ARGUMENT, set,
           "block_b = 2: the set has blocks 0..1");
    expect(eg2d_blocks_join(set, 0, 7, 0, NJ - 1, 1, EG2D_SIDE_IMIN, 0, NJ - 1), EG2D_ERR_ARGUMENT, set, "side_a = 7");
    expect(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, NJ, 1, EG2D_SIDE_IMIN, 0, NJ), EG2D_ERR_ARGUMENT, set,
           "side IMAX of block 0 has nodes 0..16");
    expect(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, NJ - 1, 1, EG2D_SIDE_IMIN, 0, NJ - 2), EG2D_ERR_ARGUMENT, set,
           "has 17 nodes, block 1 side IMIN nodes 0..15 has 16");
    expect(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, 8, 0, EG2D_SIDE_IMAX, 12, 4), EG2D_ERR_ARGUMENT, set,
           "share nodes of the same side");
    /* Not connected, then a join at the wrong place: the coordinates disagree. */
    expect(eg2d_blocks_check(set), EG2D_ERR_STATE, set, "not connected: no chain of joins from block 0 to block 1");
    assert_int_equal(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, NJ - 1, 1, EG2D_SIDE_IMIN, NJ - 1, 0), EG2D_OK);
    expect(eg2d_blocks_check(set), EG2D_ERR_BOUNDARY, set, "apart (tolerance");
    expect(eg2d_blocks_join(set, 1, EG2D_SIDE_IMIN, 3, 5, 0, EG2D_SIDE_JMAX, 3, 5), EG2D_ERR_ARGUMENT, set,
           "block 1 side IMIN nodes 3..5 is joined already (to block 0 side IMAX nodes 0..16)");
    eg2d_blocks_destroy(set);

    /* A grid destroyed while in a set; controls and the variational system refused. */
    assert_int_equal(eg2d_blocks_create(&set), EG2D_OK);
    assert_int_equal(eg2d_blocks_add(set, left, &b), EG2D_OK);
    assert_int_equal(eg2d_blocks_add(set, right, &b), EG2D_OK);
    assert_int_equal(eg2d_blocks_join(set, 0, EG2D_SIDE_IMAX, 0, NJ - 1, 1, EG2D_SIDE_IMIN, 0, NJ - 1), EG2D_OK);
    assert_int_equal(eg2d_blocks_check(set), EG2D_OK);
    assert_int_equal(eg2d_set_system(right, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    expect(eg2d_blocks_check(set), EG2D_ERR_STATE, set, "block 1 solves the Laplace system, block 0 the Winslow");
    assert_int_equal(eg2d_set_system(right, EG2D_SYSTEM_WINSLOW), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(right, EG2D_SIDE_JMIN, 1e-3), EG2D_OK);
    assert_int_equal(eg2d_set_system(right, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    assert_int_equal(eg2d_set_system(left, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    expect(eg2d_blocks_solve(set), EG2D_ERR_STATE, set, "block 1 has control terms but the system is Laplace");
    expect(eg2d_blocks_get_run(set, NULL, NULL, NULL), EG2D_ERR_STATE, set, "has not run");
    assert_int_equal(eg2d_set_system(right, EG2D_SYSTEM_WINSLOW), EG2D_OK);
    assert_int_equal(eg2d_set_system(left, EG2D_SYSTEM_WINSLOW), EG2D_OK);
    assert_int_equal(eg2d_set_orthogonality(right, EG2D_ORTHO_NONE), EG2D_OK);
    assert_int_equal(eg2d_set_solver(left, EG2D_SOLVER_AF), EG2D_OK);
    expect(eg2d_blocks_solve(set), EG2D_ERR_UNSUPPORTED, set, "block 0's solver is \"af\": a set of blocks is solved by");
    assert_int_equal(eg2d_set_solver(left, EG2D_SOLVER_MULTIGRID), EG2D_OK);
    eg2d_destroy(right);
    expect(eg2d_blocks_solve(set), EG2D_ERR_STATE, set, "block 1 was destroyed");
    eg2d_blocks_destroy(set);
    eg2d_destroy(left);  /* after the set: the set let go of it */
    expect(eg2d_blocks_check(NULL), EG2D_ERR_ARGUMENT, NULL, "set is NULL");
}

/* Blocks' names (eg2d_blocks_set_name): "blockK" until named; the rule,
 * another block's name and a default name of another block refused by
 * name, and a refused name changes nothing. The writers' use of them is
 * checked by readers eg2d did not write (tests/io/blocks_formats.py). */
static void test_block_names(void **state) {
    (void)state;
    eg2d_grid *left = make_block(MID + 1, NJ, map_left), *right = make_block(NI - MID, NJ, map_right);
    eg2d_blocks *set;
    int b;
    assert_int_equal(eg2d_blocks_create(&set), EG2D_OK);
    assert_null(eg2d_blocks_name(set, 0));
    expect(eg2d_blocks_set_name(set, 0, "inlet"), EG2D_ERR_ARGUMENT, set, "block = 0: the set has no blocks");
    assert_int_equal(eg2d_blocks_add(set, left, &b), EG2D_OK);
    assert_int_equal(eg2d_blocks_add(set, right, &b), EG2D_OK);
    assert_string_equal(eg2d_blocks_name(set, 0), "block0");
    assert_string_equal(eg2d_blocks_name(set, 1), "block1");
    assert_null(eg2d_blocks_name(set, 2));
    assert_null(eg2d_blocks_name(set, -1));
    assert_null(eg2d_blocks_name(NULL, 0));
    assert_int_equal(eg2d_blocks_set_name(set, 0, "inlet-duct_2"), EG2D_OK);
    assert_string_equal(eg2d_blocks_name(set, 0), "inlet-duct_2");
    expect(eg2d_blocks_set_name(set, 1, "inlet-duct_2"), EG2D_ERR_ARGUMENT, set,
           "name \"inlet-duct_2\": block 0 has that name");
    expect(eg2d_blocks_set_name(set, 1, "2nd"), EG2D_ERR_ARGUMENT, set, "a letter first");
    expect(eg2d_blocks_set_name(set, 1, ""), EG2D_ERR_ARGUMENT, set, "1 to 32 letters, digits, '_' or '-'");
    expect(eg2d_blocks_set_name(set, 1, "a b"), EG2D_ERR_ARGUMENT, set, "name \"a b\"");
    expect(eg2d_blocks_set_name(set, 1, "abcdefghijabcdefghijabcdefghijabc"), EG2D_ERR_ARGUMENT, set, "1 to 32");
    expect(eg2d_blocks_set_name(set, 1, "block0"), EG2D_ERR_ARGUMENT, set,
           "\"block\" and a number name blocks by their index (this is block 1)");
    expect(eg2d_blocks_set_name(set, 1, NULL), EG2D_ERR_ARGUMENT, set, "name is NULL");
    expect(eg2d_blocks_set_name(set, 2, "outlet"), EG2D_ERR_ARGUMENT, set, "block = 2: the set has blocks 0..1");
    assert_string_equal(eg2d_blocks_name(set, 1), "block1");  /* nothing changed */
    assert_int_equal(eg2d_blocks_set_name(set, 1, "block1"), EG2D_OK);  /* its own default */
    assert_int_equal(eg2d_blocks_set_name(set, 1, "block"), EG2D_OK);
    assert_int_equal(eg2d_blocks_set_name(set, 0, "block1"), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_blocks_name(set, 0), "inlet-duct_2");
    expect(eg2d_blocks_set_name(NULL, 0, "x"), EG2D_ERR_ARGUMENT, NULL, "set is NULL");
    eg2d_blocks_destroy(set);
    eg2d_destroy(left);
    eg2d_destroy(right);
}

static void test_backward_facing_step(void **state) {
    (void)state;
    eg2d_grid *grids[3];
    eg2d_blocks *set;
    int iterations;
    double residual, before_at, before_near, at, near;
    assert_int_equal(step_blocks(25, 81, 41, 17, grids, &set), EG2D_OK);
    eg2d_grid *up = grids[0], *above = grids[1], *below = grids[2];
    for (int k = 0; k < 3; ++k) {
        eg2d_grid *g = k == 0 ? up : k == 1 ? above : below;
        assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    }
    assert_int_equal(eg2d_blocks_get_kinks(set, &before_at, &before_near), EG2D_OK);
    assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
    assert_int_equal(eg2d_blocks_get_run(set, &iterations, &residual, NULL), EG2D_OK);
    assert_int_equal(eg2d_blocks_get_kinks(set, &at, &near), EG2D_OK);
    printf("step: %d sweeps, residual %.2g; turns at the joins %.3g (nearby %.3g) degrees, TFI start %.3g (%.3g)\n",
           iterations, residual, at, near, before_at, before_near);
    for (int k = 0; k < 3; ++k) {
        double folded;
        assert_int_equal(eg2d_get_quality(k == 0 ? up : k == 1 ? above : below, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
        assert_true(folded == 0.0);
    }
    assert_true(at <= near);
    eg2d_blocks_destroy(set);
    eg2d_destroy(up), eg2d_destroy(above), eg2d_destroy(below);
}

/* The wall layer of side `side` of g: its first cells within 0.5% of h and
 * its lines within half a degree of the normal. */
static void expect_wall(eg2d_grid *g, int side, double h, const char *name) {
    double lo, hi, angle, nodes;
    assert_int_equal(eg2d_get_wall_layer(g, side, EG2D_WALL_NODES, &nodes), EG2D_OK);
    assert_int_equal(eg2d_get_wall_layer(g, side, EG2D_WALL_FIRST_MIN, &lo), EG2D_OK);
    assert_int_equal(eg2d_get_wall_layer(g, side, EG2D_WALL_FIRST_MAX, &hi), EG2D_OK);
    assert_int_equal(eg2d_get_wall_layer(g, side, EG2D_WALL_ANGLE, &angle), EG2D_OK);
    printf("%-12s first cells %.5g..%.5g (asked %.3g), %.3f degrees off the normal, %g nodes\n", name, lo, hi, h, angle,
           nodes);
    assert_true(nodes > 0.0);
    assert_true(fabs(lo / h - 1.0) < 5e-3 && fabs(hi / h - 1.0) < 5e-3);
    assert_true(angle < 0.5);
}

struct wall {
    int block, side;
    double h;
    const char *name;
};
static void expect_walls(eg2d_grid *const *grids, const struct wall *walls, int count) {
    for (int k = 0; k < count; ++k) expect_wall(grids[walls[k].block], walls[k].side, walls[k].h, walls[k].name);
}

static int has_event(eg2d_grid *g, const char *words) {
    int n = 0, it;
    char text[1024];
    assert_int_equal(eg2d_get_run_info(g, EG2D_RUN_EVENTS, &n), EG2D_OK);
    for (int k = 0; k < n; ++k) {
        assert_int_equal(eg2d_get_run_event(g, k, &it, text, (int)sizeof text), EG2D_OK);
        if (strstr(text, words)) return 1;
    }
    return 0;
}

static void expect_no_folds(eg2d_grid *const *grids, int count) {
    for (int k = 0; k < count; ++k) {
        double folded;
        assert_int_equal(eg2d_get_quality(grids[k], EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
        assert_true(folded == 0.0);
    }
}

/* The bump in two blocks, walls at its floor (1e-5) and top (1e-3): the
 * columns run from one block's floor to its top, the join a column too;
 * its TFI start folds over the bump. The first cells and normals as the
 * single block's graded layer gives them, the joins without kinks, and the
 * growth the bump's own spacing forces (its rows grow by 3 at the floor)
 * said in the run's events. */
static void test_walls_across_blocks(void **state) {
    (void)state;
    enum { BI = 129, BJ = 65 };
    eg2d_grid *grids[2];
    eg2d_blocks *set;
    double at, near;
    assert_int_equal(bump_halves(BI, BJ, (BI - 1) / 2, grids, &set), EG2D_OK);
    for (int b = 0; b < 2; ++b) {
        assert_int_equal(eg2d_set_system(grids[b], EG2D_SYSTEM_WINSLOW), EG2D_OK);
        assert_int_equal(eg2d_set_wall_spacing(grids[b], EG2D_SIDE_JMIN, 1e-5), EG2D_OK);
        assert_int_equal(eg2d_set_wall_spacing(grids[b], EG2D_SIDE_JMAX, 1e-3), EG2D_OK);
    }
    assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
    expect_no_folds(grids, 2);
    const struct wall walls[] = {{0, EG2D_SIDE_JMIN, 1e-5, "left floor"},
                                 {1, EG2D_SIDE_JMIN, 1e-5, "right floor"},
                                 {0, EG2D_SIDE_JMAX, 1e-3, "left top"},
                                 {1, EG2D_SIDE_JMAX, 1e-3, "right top"}};
    expect_walls(grids, walls, 4);
    assert_int_equal(eg2d_blocks_get_kinks(set, &at, &near), EG2D_OK);
    printf("bump with walls: turns at the join %.3g, nearby %.3g degrees\n", at, near);
    assert_true(at <= near);
    for (int b = 0; b < 2; ++b) {
        assert_true(has_event(grids[b], "wall layer (graded, set of blocks): 127 line(s)"));
        assert_true(has_event(grids[b], "folded cell(s); the layer is made on the set's grid"));
        assert_true(has_event(grids[b], "(more than 1.2: give the blocks more nodes across the walls"));
        /* the inlet's and outlet's points, 2.4e-4 off the floor */
        assert_true(has_event(grids[b], "line(s) of the boundary leave a wall with a first cell more than 2 times off"));
    }
    eg2d_blocks_destroy(set);
    eg2d_destroy(grids[0]), eg2d_destroy(grids[1]);
}

/* The step in three blocks with walls of 1e-5 at its floors, top and face
 * (block_domains.h's walled_step_blocks): the floor's lines continue
 * through the join at the step's height to the top, the row that continues
 * the upstream floor leaves the step's face; by multigrid and line SOR. */
static void test_walled_step(void **state) {
    (void)state;
    const int solvers[] = {EG2D_SOLVER_MULTIGRID, EG2D_SOLVER_LSOR};
    for (int k = 0; k < 2; ++k) {
        eg2d_grid *g[3];
        eg2d_blocks *set;
        double at, near;
        assert_int_equal(walled_step_blocks(1e-5, 33, 129, 97, 49, g, &set), EG2D_OK);
        assert_int_equal(eg2d_set_solver(g[0], solvers[k]), EG2D_OK);
        assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
        expect_no_folds(g, 3);
        const struct wall walls[] = {{0, EG2D_SIDE_JMIN, 1e-5, "upstream floor"},
                                     {0, EG2D_SIDE_JMAX, 1e-5, "upstream top"},
                                     {1, EG2D_SIDE_JMAX, 1e-5, "top"},
                                     {2, EG2D_SIDE_JMIN, 1e-5, "floor"},
                                     {2, EG2D_SIDE_IMIN, 1e-5, "step's face"}};
        expect_walls(g, walls, 5);
        assert_int_equal(eg2d_blocks_get_kinks(set, &at, &near), EG2D_OK);
        assert_true(at < 0.01 && near < 0.01); /* its blocks are rectangles: straight lines */
        assert_true(has_event(g[2], "wall layer (graded, set of blocks)"));
        assert_false(has_event(g[2], "line(s) of the boundary leave a wall"));
        eg2d_blocks_destroy(set);
        eg2d_destroy(g[0]), eg2d_destroy(g[1]), eg2d_destroy(g[2]);
    }
}

/* The walled step with the downstream floor's first cell varying along it
 * (eg2d_set_wall_spacing_nodes: 1e-5 at its ends, 2e-5 midway, 2.4% a node
 * off the step's face): every floor node's first cell is its own height
 * within 2%. The start (TFI of the sides spaced for 1e-5) is then no
 * longer the solution: it converges with multigrid from the start (a full
 * multigrid start would raise its residual, said). */
static void test_walled_step_heights_node_by_node(void **state) {
    (void)state;
    enum { NI = 129, NJ = 49 };
    eg2d_grid *g[3];
    eg2d_blocks *set;
    assert_int_equal(walled_step_blocks(1e-5, 33, NI, 97, NJ, g, &set), EG2D_OK);
    double h[NI];
    for (int k = 0; k < NI; ++k) h[k] = 1e-5 * (1.0 + sin(acos(-1.0) * k / (NI - 1.0)));
    assert_int_equal(eg2d_set_wall_spacing_nodes(g[2], EG2D_SIDE_JMIN, NI, h), EG2D_OK);
    if (eg2d_blocks_solve(set) != EG2D_OK) fail_msg("%s", eg2d_blocks_last_error(set));
    expect_no_folds(g, 3);
    static double x[NI * NJ], y[NI * NJ];
    assert_int_equal(eg2d_get_coordinates(g[2], x, y), EG2D_OK);
    /* (the last 8 nodes blend into the outlet side's own first cell, 1e-5;
     * they lie between) */
    for (int k = 1; k < NI - 1; ++k) {
        const double first = hypot(x[k + NI] - x[k], y[k + NI] - y[k]);
        const int ok = k < NI - 9 ? fabs(first / h[k] - 1) < 2e-2 : first > 1e-5 * 0.999 && first < h[NI - 10] * 1.001;
        if (!ok) fail_msg("floor node %d: first cell %g, asked %g", k, first, h[k]);
    }
    eg2d_blocks_destroy(set);
    eg2d_destroy(g[0]), eg2d_destroy(g[1]), eg2d_destroy(g[2]);
}

/* A block joined to itself is an O- or C-grid whose cut is a join: an
 * annulus (an ellipse in a circle) as one single block whose IMIN and IMAX
 * sides are the same radial line, joined, gives the O-grid's solution, and
 * NACA 0012's C-grid as one block whose wake halves on JMIN are joined gives
 * the C-grid's, each solver to the tolerance's size. */
static double largest_gap(const eg2d_grid *a, const eg2d_grid *b, int n) {
    double *xa = malloc(sizeof(double) * (size_t)n * 4), *ya = xa + n, *xb = ya + n, *yb = xb + n, d = 0.0;
    assert_int_equal(eg2d_get_coordinates(a, xa, ya), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(b, xb, yb), EG2D_OK);
    for (int k = 0; k < n; ++k) d = fmax(d, hypot(xa[k] - xb[k], ya[k] - yb[k]));
    free(xa);
    return d;
}

static void set_winslow(eg2d_grid *g, int solver) {
    assert_int_equal(eg2d_set_system(g, EG2D_SYSTEM_WINSLOW), EG2D_OK);
    assert_int_equal(eg2d_set_solver(g, solver), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-11), EG2D_OK);
}

static void test_block_joined_to_itself_o(void **state) {
    (void)state;
    enum { NI = 65, NJ = 33 };
    double xi[NI], yi[NI], xo[NI], yo[NI], xr[NJ], yr[NJ];
    for (int k = 0; k < NI; ++k) {
        const double t = k == NI - 1 ? 0.0 : 2.0 * acos(-1.0) * k / (NI - 1);
        xi[k] = cos(t), yi[k] = 0.6 * sin(t), xo[k] = 3.0 * cos(t), yo[k] = 3.0 * sin(t);
    }
    for (int k = 0; k < NJ; ++k) xr[k] = 1.0 + 2.0 * k / (NJ - 1), yr[k] = 0.0;
    const int solvers[] = {EG2D_SOLVER_MULTIGRID, EG2D_SOLVER_LSOR, EG2D_SOLVER_PSOR};
    for (int v = 0; v < 3; ++v) {
        eg2d_grid *o, *s;
        eg2d_blocks *set;
        int b;
        assert_int_equal(eg2d_create(NI, NJ, &o), EG2D_OK);
        assert_int_equal(eg2d_set_topology(o, EG2D_TOPO_O), EG2D_OK);
        assert_int_equal(eg2d_set_side(o, EG2D_SIDE_JMIN, xi, yi), EG2D_OK);
        assert_int_equal(eg2d_set_side(o, EG2D_SIDE_JMAX, xo, yo), EG2D_OK);
        set_winslow(o, solvers[v]);
        assert_int_equal(eg2d_solve(o), EG2D_OK);
        assert_int_equal(eg2d_create(NI, NJ, &s), EG2D_OK);
        assert_int_equal(eg2d_set_side(s, EG2D_SIDE_JMIN, xi, yi), EG2D_OK);
        assert_int_equal(eg2d_set_side(s, EG2D_SIDE_JMAX, xo, yo), EG2D_OK);
        assert_int_equal(eg2d_set_side(s, EG2D_SIDE_IMIN, xr, yr), EG2D_OK);
        assert_int_equal(eg2d_set_side(s, EG2D_SIDE_IMAX, xr, yr), EG2D_OK);
        set_winslow(s, solvers[v]);
        assert_int_equal(eg2d_blocks_create(&set), EG2D_OK);
        assert_int_equal(eg2d_blocks_add(set, s, &b), EG2D_OK);
        assert_int_equal(eg2d_blocks_join(set, 0, EG2D_SIDE_IMIN, 0, NJ - 1, 0, EG2D_SIDE_IMAX, 0, NJ - 1), EG2D_OK);
        if (eg2d_blocks_solve(set) != EG2D_OK) fail_msg("solver %d: %s", solvers[v], eg2d_blocks_last_error(set));
        const double gap = largest_gap(o, s, NI * NJ);
        if (!(gap < 1e-8)) fail_msg("solver %d: the set is %g from the O-grid", solvers[v], gap);
        eg2d_blocks_destroy(set);
        eg2d_destroy(o), eg2d_destroy(s);
    }
}

static void test_block_joined_to_itself_c(void **state) {
    (void)state;
    enum { NI = 129, NJ = 33, WAKE = 32 };
    static double x[NI * NJ], y[NI * NJ];
    double bx[4][NI], by[4][NI];
    const int solvers[] = {EG2D_SOLVER_MULTIGRID, EG2D_SOLVER_LSOR};
    for (int v = 0; v < 2; ++v) {
        eg2d_grid *c, *s;
        eg2d_blocks *set;
        int b;
        assert_int_equal(eg2d_create(NI, NJ, &c), EG2D_OK);
        assert_int_equal(domain_set_airfoil_c(c, "0012", WAKE, 5.0), EG2D_OK);
        set_winslow(c, solvers[v]);
        assert_int_equal(eg2d_initialize(c, EG2D_INIT_TFI), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(c, x, y), EG2D_OK);
        for (int i = 0; i < NI; ++i)
            bx[0][i] = x[i], by[0][i] = y[i], bx[2][i] = x[i + NI * (NJ - 1)], by[2][i] = y[i + NI * (NJ - 1)];
        for (int j = 0; j < NJ; ++j) bx[3][j] = x[NI * j], by[3][j] = y[NI * j], bx[1][j] = x[NI - 1 + NI * j], by[1][j] = y[NI - 1 + NI * j];
        assert_int_equal(eg2d_solve(c), EG2D_OK);
        assert_int_equal(eg2d_create(NI, NJ, &s), EG2D_OK);
        for (int side = 0; side < 4; ++side) assert_int_equal(eg2d_set_side(s, side, bx[side], by[side]), EG2D_OK);
        set_winslow(s, solvers[v]);
        assert_int_equal(eg2d_blocks_create(&set), EG2D_OK);
        assert_int_equal(eg2d_blocks_add(set, s, &b), EG2D_OK);
        assert_int_equal(eg2d_blocks_join(set, 0, EG2D_SIDE_JMIN, 0, WAKE, 0, EG2D_SIDE_JMIN, NI - 1, NI - 1 - WAKE),
                         EG2D_OK);
        if (eg2d_blocks_solve(set) != EG2D_OK) fail_msg("solver %d: %s", solvers[v], eg2d_blocks_last_error(set));
        const double gap = largest_gap(c, s, NI * NJ);
        if (!(gap < 1e-8)) fail_msg("solver %d: the set is %g from the C-grid", solvers[v], gap);
        eg2d_blocks_destroy(set);
        eg2d_destroy(c), eg2d_destroy(s);
    }
}

/* A held join (eg2d_blocks_hold_join) keeps its nodes where the blocks'
 * sides put them, its ends held vertices, and the kink measure leaves it
 * out; free, the bump's middle line moves. Bad indices are refused. */
static void test_held_join(void **state) {
    (void)state;
    enum { BI = 65, BJ = 33, MID = 32 };
    static double x0[BI * BJ], y0[BI * BJ], x[BI * BJ], y[BI * BJ];
    for (int held = 0; held < 2; ++held) {
        eg2d_grid *grids[2];
        eg2d_blocks *set;
        double at = -1, near = -1, moved = 0;
        assert_int_equal(bump_halves(BI, BJ, MID, grids, &set), EG2D_OK);
        expect(eg2d_blocks_hold_join(set, 1, 1), EG2D_ERR_ARGUMENT, set, "join = 1: the set has joins 0..0");
        expect(eg2d_blocks_hold_join(set, 0, 2), EG2D_ERR_ARGUMENT, set, "held = 2: must be 0 or 1");
        if (held) assert_int_equal(eg2d_blocks_hold_join(set, 0, 1), EG2D_OK);
        const int nj = BJ, ni = MID + 1; /* block 0: the left half; its IMAX is the join */
        assert_int_equal(eg2d_initialize(grids[0], EG2D_INIT_TFI), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(grids[0], x0, y0), EG2D_OK);
        assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(grids[0], x, y), EG2D_OK);
        for (int j = 0; j < nj; ++j) moved = fmax(moved, hypot(x[ni - 1 + ni * j] - x0[ni - 1 + ni * j], y[ni - 1 + ni * j] - y0[ni - 1 + ni * j]));
        assert_int_equal(eg2d_blocks_get_kinks(set, &at, &near), EG2D_OK);
        if (held) {
            assert_true(moved == 0.0);
            assert_true(at == 0.0 && near == 0.0); /* no free join to measure */
        } else {
            if (!(moved > 1e-3)) fail_msg("the free join moved %g", moved);
            assert_true(at > 0.0);
        }
        eg2d_blocks_destroy(set);
        eg2d_destroy(grids[0]), eg2d_destroy(grids[1]);
    }
}

/* A block initialised again alone after a solve: the set checks its joins
 * on the sides as given and starts again from TFI, to the same grid (it
 * failed the check: its joined nodes back on its sides, its neighbours'
 * where the solve left them). */
static void test_block_initialised_again(void **state) {
    (void)state;
    eg2d_grid *grids[3];
    eg2d_blocks *set;
    static double x0[81 * 41], y0[81 * 41], x[81 * 41], y[81 * 41]; /* block 1: 81 x 41 */
    assert_int_equal(step_blocks(25, 81, 41, 17, grids, &set), EG2D_OK);
    assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(grids[1], x0, y0), EG2D_OK);
    assert_int_equal(eg2d_initialize(grids[0], EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_blocks_check(set), EG2D_OK);
    if (eg2d_blocks_solve(set) != EG2D_OK) fail_msg("%s", eg2d_blocks_last_error(set));
    assert_int_equal(eg2d_get_coordinates(grids[1], x, y), EG2D_OK);
    double d = 0.0;
    for (int k = 0; k < 81 * 41; ++k) d = fmax(d, hypot(x[k] - x0[k], y[k] - y0[k]));
    if (!(d < 1e-7)) fail_msg("the second solve is %g from the first", d);
    eg2d_blocks_destroy(set);
    eg2d_destroy(grids[0]), eg2d_destroy(grids[1]), eg2d_destroy(grids[2]);
}

/* Block 0's monitor follows the set's run and can stop it. */
static int calls, stop_at;
static int count_and_stop(void *user, int iteration, double residual) {
    (void)user;
    assert_int_equal(iteration, calls + 1);
    assert_true(residual > 0.0);
    ++calls;
    return iteration == stop_at;
}
static void test_monitor(void **state) {
    (void)state;
    eg2d_grid *grids[3];
    eg2d_blocks *set;
    int iterations;
    assert_int_equal(step_blocks(25, 81, 41, 17, grids, &set), EG2D_OK);
    assert_int_equal(eg2d_set_monitor(grids[0], count_and_stop, NULL), EG2D_OK);
    calls = 0, stop_at = -1;
    assert_int_equal(eg2d_blocks_solve(set), EG2D_OK);
    assert_int_equal(eg2d_blocks_get_run(set, &iterations, NULL, NULL), EG2D_OK);
    assert_int_equal(calls, iterations);
    calls = 0, stop_at = 2;
    for (int k = 0; k < 3; ++k) assert_int_equal(eg2d_initialize(grids[k], EG2D_INIT_TFI), EG2D_OK);
    expect(eg2d_blocks_solve(set), EG2D_ERR_INTERRUPTED, set, "the monitor stopped the set's run at iteration 2");
    assert_int_equal(eg2d_blocks_get_run(set, &iterations, NULL, NULL), EG2D_OK);
    assert_int_equal(iterations, 2);
    assert_int_equal(calls, 2);
    eg2d_blocks_destroy(set);
    eg2d_destroy(grids[0]), eg2d_destroy(grids[1]), eg2d_destroy(grids[2]);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_set_is_the_single_block),
        cmocka_unit_test(test_inner_vertex),
        cmocka_unit_test(test_controls),
        cmocka_unit_test(test_run_events),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_block_names),
        cmocka_unit_test(test_backward_facing_step),
        cmocka_unit_test(test_walls_across_blocks),
        cmocka_unit_test(test_walled_step), cmocka_unit_test(test_walled_step_heights_node_by_node),
        cmocka_unit_test(test_block_joined_to_itself_o), cmocka_unit_test(test_block_joined_to_itself_c),
        cmocka_unit_test(test_held_join), cmocka_unit_test(test_block_initialised_again),
        cmocka_unit_test(test_monitor),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
