/* Sets of blocks against single blocks (eg2d_bench --blocks), Winslow,
 * residual 1e-10, CPU seconds the median of 3:
 *   bump  the bump domain of tests/support/block_domains.h as one block and
 *         as two blocks joined down its middle: the same problem, so the
 *         set's multigrid against the single block's (cycles, CPU per node);
 *   step  the backward-facing step in three blocks (block_domains.h), and
 *         a rectangle over its extent with as many nodes in one block (no
 *         step: an easier problem with the same unknowns per cycle).
 * Sizes: the halving ones (2^k + 1), then sizes users pick (odd cell
 * counts, the set coarsened on its any-size axes). The last rows: the bump
 * with walls of 1e-5 (floor) and 1e-3 (top), the set's graded layer
 * against the single block's.
 * Point SOR rows at the smallest size only (thousands of sweeps above). The
 * last column: the largest turn of a grid line at the joins against the
 * largest one node into either block. */
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "block_domains.h"

static int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

typedef enum { BUMP_SET, BUMP_ONE, STEP_SET, STEP_RECTANGLE, BUMP_SET_WALLS, BUMP_ONE_WALLS } shape;

typedef struct {
    int iterations;
    double cpu, at, near;
    long nodes;
} outcome;

static void identity(int i, int j, int *I, int *J, const int *p) { (void)p, *I = i, *J = j; }

/* One run of shape s at size z (bump: ni, nj; step: ni_up, ni_down, nj_upper, nj_lower). */
static int run_once(shape s, const int *z, int solver, outcome *o) {
    eg2d_grid *grids[3] = {NULL, NULL, NULL}, *one = NULL;
    eg2d_blocks *set = NULL;
    int rc, n = 0;
    o->at = o->near = -1.0;
    switch (s) {
    case BUMP_SET:
    case BUMP_SET_WALLS: rc = bump_halves(z[0], z[1], (z[0] - 1) / 2, grids, &set), n = 2; break;
    case STEP_SET: rc = step_blocks(z[0], z[1], z[2], z[3], grids, &set), n = 3; break;
    case BUMP_ONE:
    case BUMP_ONE_WALLS: rc = bump_block(z[0], z[1], z[0], z[1], identity, NULL, &one); break;
    default: rc = block_rectangle(z[0] + z[1] - 1, z[2] + z[3] - 1, -4.0, 20.0, 0.0, 9.0, 0, 1, &one); break;
    }
    eg2d_grid *first = set ? grids[0] : one;
    /* walls: 1e-5 at the bump's floor, 1e-3 at the top, every block */
    for (int k = 0; !rc && (s == BUMP_SET_WALLS || s == BUMP_ONE_WALLS) && k < (set ? n : 1); ++k) {
        eg2d_grid *g = set ? grids[k] : one;
        if (!(rc = eg2d_set_system(g, EG2D_SYSTEM_WINSLOW)) && !(rc = eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, 1e-5)))
            rc = eg2d_set_wall_spacing(g, EG2D_SIDE_JMAX, 1e-3);
    }
    if (!rc) rc = eg2d_set_tolerance(first, 1e-10);
    if (!rc) rc = eg2d_set_solver(first, solver);
    const double t0 = bench_cpu();
    if (!rc) rc = set ? eg2d_blocks_solve(set) : eg2d_solve(one);
    o->cpu = bench_cpu() - t0;
    if (rc) printf("<!-- %s -->\n", set ? eg2d_blocks_last_error(set) : eg2d_last_error(one));
    o->nodes = 0;
    for (int k = 0; k < (set ? n : 1); ++k) {
        int ni = 0, nj = 0;
        eg2d_get_size(set ? grids[k] : one, &ni, &nj);
        o->nodes += (long)ni * nj;
    }
    if (set) {
        eg2d_blocks_get_run(set, &o->iterations, NULL, NULL);
        eg2d_blocks_get_kinks(set, &o->at, &o->near);
    } else {
        eg2d_get_iterations(one, &o->iterations);
    }
    eg2d_blocks_destroy(set);
    for (int k = 0; k < 3; ++k) eg2d_destroy(grids[k]);
    eg2d_destroy(one);
    return rc;
}

static outcome median(shape s, const int *z, int solver) {
    outcome o[3];
    double t[3];
    for (int r = 0; r < 3; ++r) {
        if (run_once(s, z, solver, &o[r])) o[r].cpu = -1.0;
        t[r] = o[r].cpu;
    }
    qsort(t, 3, sizeof t[0], by_value);
    o[0].cpu = t[1];
    return o[0];
}

static void row(const char *name, const outcome *o, const outcome *ref) {
    char turns[64] = "";
    if (o->at >= 0) snprintf(turns, sizeof turns, "%.2f / %.2f", o->at, o->near);
    const double per = o->cpu / ((double)o->nodes * (o->iterations > 0 ? o->iterations : 1));
    const double per_ref = ref->cpu / ((double)ref->nodes * (ref->iterations > 0 ? ref->iterations : 1));
    char ratio[32] = "-", per_ratio[32] = "-";  /* none against a run of no iteration (a start kept exactly) */
    if (ref->iterations > 0) {
        snprintf(ratio, sizeof ratio, "%.2f", (double)o->iterations / ref->iterations);
        snprintf(per_ratio, sizeof per_ratio, "%.2f", per / per_ref);
    }
    printf("| %ld | %s | %d | %s | %.3f | %s | %s |\n", o->nodes, name, o->iterations, ratio, o->cpu, per_ratio, turns);
}

void bench_blocks(void) {
    /* the halving sizes, then sizes users pick (odd cell counts) */
    static const int bumps[][2] = {{129, 65}, {257, 129}, {513, 257}, {250, 100}, {385, 129}};
    static const int steps[][4] = {{25, 81, 41, 17}, {49, 161, 81, 33}, {97, 321, 161, 65}, {61, 361, 90, 37}};
    printf("| nodes | grid | iterations | / one block's | CPU s | CPU per node and iteration / one block's | turn at joins / nearby (deg) |\n");
    printf("|---:|---|---:|---:|---:|---:|---|\n");
    for (int k = 0; k < 5; ++k) {
        const outcome one = median(BUMP_ONE, bumps[k], EG2D_SOLVER_MULTIGRID);
        const outcome set = median(BUMP_SET, bumps[k], EG2D_SOLVER_MULTIGRID);
        row("bump, one block, multigrid", &one, &one);
        row("bump, two blocks, multigrid", &set, &one);
        if (k == 0) {
            const outcome sor1 = median(BUMP_ONE, bumps[k], EG2D_SOLVER_PSOR);
            const outcome sor2 = median(BUMP_SET, bumps[k], EG2D_SOLVER_PSOR);
            row("bump, one block, point SOR", &sor1, &sor1);
            row("bump, two blocks, point SOR", &sor2, &sor1);
        }
    }
    for (int k = 0; k < 4; ++k) {
        const outcome one = median(STEP_RECTANGLE, steps[k], EG2D_SOLVER_MULTIGRID);
        const outcome set = median(STEP_SET, steps[k], EG2D_SOLVER_MULTIGRID);
        row("rectangle, one block, multigrid", &one, &one);
        row("step, three blocks, multigrid", &set, &one);
        if (k == 0) {
            const outcome sor = median(STEP_SET, steps[k], EG2D_SOLVER_PSOR);
            row("step, three blocks, point SOR", &sor, &one);
        }
    }
    /* The graded wall layer: the set's (set_wall_layer) against the single block's. */
    for (int k = 1; k < 5; k += 2) {
        const outcome one = median(BUMP_ONE_WALLS, bumps[k], EG2D_SOLVER_MULTIGRID);
        const outcome set = median(BUMP_SET_WALLS, bumps[k], EG2D_SOLVER_MULTIGRID);
        row("bump, walls 1e-5 and 1e-3, one block, multigrid", &one, &one);
        row("bump, walls 1e-5 and 1e-3, two blocks, multigrid", &set, &one);
    }
}
