/* Multigrid timing: swan (seed 003), valley and the annulus O-grid, Winslow,
 * TFI start, to the residual 1e-10; prints cycles, seconds, final residual,
 * the mean factor per cycle and the work units per cycle (1 WU = one
 * fine-grid residual evaluation, timed here with eg2d_get_residual).
 * Usage: mg_timing [solver-id [max-size]]   (not a test: timings vary). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "domains.h"
#include "eg2d.h"

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int record[1000], nrec;
static double resid[1000];
static int monitor(void *user, int it, double r) {
    (void)user;
    if (nrec < 1000) { record[nrec] = it; resid[nrec++] = r; }
    return 0;
}

static void run(const char *domain, int n, int solver, double omega) {
    eg2d_grid *g;
    double r0, r, t0, t1, tr, wu, factor;
    int it, k, status;
    eg2d_create(n, n, &g);
    if (!strcmp(domain, "annulus")) domain_set_annulus(g, 1.0, 3.0);
    else domain_set(g, domain);
    eg2d_initialize(g, EG2D_INIT_TFI);
    eg2d_set_solver(g, solver);
    eg2d_set_relaxation(g, omega);
    eg2d_set_tolerance(g, 1e-10);
    /* Optional overrides from the environment, for experiments. */
    if (getenv("SYS")) eg2d_set_system(g, atoi(getenv("SYS")));
    if (getenv("MG_CYCLE")) eg2d_set_parameter(g, EG2D_PARAM_MG_CYCLE, atof(getenv("MG_CYCLE")));
    if (getenv("MG_PRE")) eg2d_set_parameter(g, EG2D_PARAM_MG_PRE_SMOOTH, atof(getenv("MG_PRE")));
    if (getenv("MG_POST")) eg2d_set_parameter(g, EG2D_PARAM_MG_POST_SMOOTH, atof(getenv("MG_POST")));
    if (getenv("MG_FMG")) eg2d_set_parameter(g, EG2D_PARAM_MG_FMG, atof(getenv("MG_FMG")));
    if (getenv("MG_COARSEST")) eg2d_set_parameter(g, EG2D_PARAM_MG_COARSEST, atof(getenv("MG_COARSEST")));
    eg2d_set_max_iterations(g, 1000000);
    eg2d_get_residual(g, &r0);
    nrec = 0;
    eg2d_set_monitor(g, monitor, NULL);
    t0 = now();
    status = eg2d_solve(g);
    t1 = now();
    eg2d_get_residual(g, &r);
    eg2d_get_iterations(g, &it);
    /* One WU: the time of one residual evaluation on the fine grid. */
    tr = now();
    for (k = 0; k < 5; ++k) eg2d_get_residual(g, &r);
    tr = (now() - tr) / 5;
    wu = (t1 - t0) / it / tr; /* includes the run loop's own residual per cycle */
    factor = it > 1 ? pow(r / resid[0], 1.0 / (it - 1)) : 0;
    printf("%-8s %5d^2 %-9s %6d it %9.4f s  res %.2e (start %.2e, after it 1 %.2e)  factor %.3f  %.1f WU/it  %s\n",
           domain, n, eg2d_solver_name(solver), it, t1 - t0, r, r0, resid[0], factor, wu,
           status ? eg2d_last_error(g) : "");
    if (getenv("HISTORY"))
        for (k = 0; k < nrec; ++k) printf("  %d %.3e %.3f\n", record[k], resid[k], k ? resid[k] / resid[k - 1] : 0.0);
    eg2d_destroy(g);
}

int main(int argc, char **argv) {
    const int sizes[] = {33, 65, 129, 257, 513, 1025};
    const char *domains[] = {"swan", "valley", "annulus"};
    int solver = argc > 1 ? atoi(argv[1]) : EG2D_SOLVER_MULTIGRID;
    int maxn = argc > 2 ? atoi(argv[2]) : 1025;
    double omega = argc > 3 ? atof(argv[3]) : 0;
    int d, s;
    for (d = 0; d < 3; ++d)
        for (s = 0; s < 6; ++s)
            if (sizes[s] <= maxn) run(domains[d], sizes[s], solver, omega);
    return 0;
}
