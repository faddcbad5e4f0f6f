/* Sets of blocks against one block of the same nodes (eg2d_bench --blocks):
 * the backward-facing step of tests/support/block_domains.h in three
 * blocks, solved as one grid by eg2d_blocks_solve (point SOR over the set),
 * beside a single rectangular block (no step) with as many nodes solved by point SOR
 * (EG2D_SOLVER_PSOR, automatic factor) and by multigrid, Winslow,
 * residual 1e-10. Columns: sweeps or cycles, CPU seconds (median of 3) and
 * CPU per node and iteration over the single block's PSOR, the turns at the
 * joins against nearby. */
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "block_domains.h"

static int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* One run: the set (solver < 0) or the single block with that solver. */
static double run_once(int ni_up, int ni_down, int nj_upper, int nj_lower, int solver, int *iterations, double *at,
                       double *near) {
    double t0, t;
    *at = *near = -1.0;
    if (solver < 0) {
        eg2d_grid *grids[3];
        eg2d_blocks *set;
        if (step_blocks(ni_up, ni_down, nj_upper, nj_lower, grids, &set)) return -1.0;
        eg2d_set_tolerance(grids[0], 1e-10);
        t0 = bench_cpu();
        const int rc = eg2d_blocks_solve(set);
        t = bench_cpu() - t0;
        eg2d_blocks_get_run(set, iterations, NULL, NULL);
        eg2d_blocks_get_kinks(set, at, near);
        if (rc) printf("<!-- the set: %s -->\n", eg2d_blocks_last_error(set));
        eg2d_blocks_destroy(set);
        for (int k = 0; k < 3; ++k) eg2d_destroy(grids[k]);
        return rc ? -1.0 : t;
    }
    /* The single block: a rectangle over the step's extent with as many nodes
     * (no step: an easier problem, the same unknowns per sweep). */
    eg2d_grid *g;
    const int ni = ni_up + ni_down - 1, nj = nj_upper + nj_lower - 1;
    if (block_rectangle(ni, nj, -4.0, 20.0, 0.0, 9.0, 0, 1, &g)) return -1.0;
    eg2d_set_tolerance(g, 1e-10);
    eg2d_set_solver(g, solver);
    t0 = bench_cpu();
    const int rc = eg2d_solve(g);
    t = bench_cpu() - t0;
    eg2d_get_iterations(g, iterations);
    eg2d_destroy(g);
    return rc ? -1.0 : t;
}

void bench_blocks(void) {
    static const int sizes[][4] = {{25, 81, 41, 17}, {49, 161, 81, 33}, {97, 321, 161, 65}};
    static const struct {
        const char *name;
        int solver;
    } ways[] = {{"set of 3 blocks, point SOR", -1}, {"one block, point SOR", EG2D_SOLVER_PSOR},
                {"one block, multigrid", EG2D_SOLVER_MULTIGRID}};
    printf("| nodes | grid | sweeps or cycles | CPU s | CPU per node and iteration / one block's PSOR | turn at joins / nearby (deg) |\n");
    printf("|---:|---|---:|---:|---:|---|\n");
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
        const int *z = sizes[s];
        const long nodes = (long)(z[0] + z[1] - 1) * (z[2] + z[3] - 1);
        double per[3], cpu[3], at = -1, near = -1;
        int its[3];
        for (size_t w = 0; w < 3; ++w) {
            double t[3];
            its[w] = 0;
            for (int r = 0; r < 3; ++r) t[r] = run_once(z[0], z[1], z[2], z[3], ways[w].solver, &its[w], w == 0 ? &at : &(double){0}, w == 0 ? &near : &(double){0});
            qsort(t, 3, sizeof t[0], by_value);
            cpu[w] = t[1];
            per[w] = t[1] / ((double)nodes * (its[w] > 0 ? its[w] : 1));
        }
        for (size_t w = 0; w < 3; ++w) {
            char turns[64] = "";
            if (w == 0) snprintf(turns, sizeof turns, "%.2f / %.2f", at, near);
            printf("| %ld | %s | %d | %.3f | %.2f | %s |\n", nodes, ways[w].name, its[w], cpu[w], per[w] / per[1], turns);
        }
    }
}
