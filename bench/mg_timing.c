/* Multigrid timing (not a test: timings vary with the machine and its load).
 * Winslow, TFI start, residual 1e-10 (NUMERICS.md), on the seed 003 domains
 * and the annulus O-grid (1 <= r <= 3) at 33^2 .. 1025^2. Prints per run:
 * cycles, CPU seconds of eg2d_solve on this thread, wall seconds, final
 * residual, the mean factor per cycle after the first (the FMG start), and
 * work units per cycle (1 WU = the CPU time of one fine-grid residual
 * evaluation, eg2d_get_residual, measured on the same grid).
 *   mg_timing [solver [max-size [omega]]]   one solver on every case
 *   mg_timing compare                        swan 129^2: point Gauss-Seidel
 *                                            (PSOR, omega = 1) vs multigrid
 * Environment SYS, MG_CYCLE, MG_PRE, MG_POST, MG_FMG, MG_COARSEST override
 * the system and multigrid parameters, for experiments.
 * Build: cc -O2 bench/mg_timing.c tests/support/domains.c -Iinclude
 *        -Itests/support -Lbuild/src -leg2d -lm */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "domains.h"
#include "eg2d.h"

static double clock_of(clockid_t id) {
    struct timespec t;
    clock_gettime(id, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}
static double cpu(void) { return clock_of(CLOCK_THREAD_CPUTIME_ID); }
static double wall(void) { return clock_of(CLOCK_MONOTONIC); }

static double first_residual;
static int monitor(void *user, int it, double r) {
    (void)user;
    if (it == 1) first_residual = r;
    if (getenv("HISTORY")) printf("  %d %.3e\n", it, r);
    return 0;
}

static void set_env_parameter(eg2d_grid *g, const char *name, int param) {
    if (getenv(name)) eg2d_set_parameter(g, param, atof(getenv(name)));
}

/* Returns the CPU seconds of the solve. */
static double run(const char *domain, int n, int solver, double omega) {
    eg2d_grid *g;
    double r0, r, c0, c1, w0, w1, tr, wu, factor;
    int it, k, status;
    eg2d_create(n, n, &g);
    if (!strcmp(domain, "annulus")) domain_set_annulus(g, 1.0, 3.0);
    else domain_set(g, domain);
    eg2d_initialize(g, EG2D_INIT_TFI);
    eg2d_set_solver(g, solver);
    eg2d_set_relaxation(g, omega);
    eg2d_set_tolerance(g, 1e-10);
    eg2d_set_max_iterations(g, 1000000);
    if (getenv("SYS")) eg2d_set_system(g, atoi(getenv("SYS")));
    set_env_parameter(g, "MG_CYCLE", EG2D_PARAM_MG_CYCLE);
    set_env_parameter(g, "MG_PRE", EG2D_PARAM_MG_PRE_SMOOTH);
    set_env_parameter(g, "MG_POST", EG2D_PARAM_MG_POST_SMOOTH);
    set_env_parameter(g, "MG_FMG", EG2D_PARAM_MG_FMG);
    set_env_parameter(g, "MG_COARSEST", EG2D_PARAM_MG_COARSEST);
    eg2d_get_residual(g, &r0);
    eg2d_set_monitor(g, monitor, NULL);
    w0 = wall();
    c0 = cpu();
    status = eg2d_solve(g);
    c1 = cpu();
    w1 = wall();
    eg2d_get_residual(g, &r);
    eg2d_get_iterations(g, &it);
    tr = cpu();
    for (k = 0; k < 10; ++k) eg2d_get_residual(g, &r);
    tr = (cpu() - tr) / 10;
    wu = (c1 - c0) / it / tr; /* includes the run loop's own residual per cycle */
    factor = it > 1 ? pow(r / first_residual, 1.0 / (it - 1)) : 0;
    printf("%-13s %5d^2 %-9s %6d it  cpu %8.4f s  wall %8.4f s  residual %.2e  factor %.3f  %5.1f WU/it %s\n",
           domain, n, eg2d_solver_name(solver), it, c1 - c0, w1 - w0, r, factor, wu,
           status ? eg2d_last_error(g) : "");
    eg2d_destroy(g);
    return c1 - c0;
}

int main(int argc, char **argv) {
    const int sizes[] = {33, 65, 129, 257, 513, 1025};
    const char *domains[] = {"swan", "valley", "dome", "almost-convex", "annulus"};
    int solver, maxn, d, s;
    double omega;
    if (argc > 1 && !strcmp(argv[1], "compare")) {
        const double t_gs = run("swan", 129, EG2D_SOLVER_PSOR, 1.0);
        const double t_mg = run("swan", 129, EG2D_SOLVER_MULTIGRID, 0.0);
        printf("swan 129^2: multigrid is %.0fx faster than point Gauss-Seidel (CPU time)\n", t_gs / t_mg);
        return 0;
    }
    solver = argc > 1 ? atoi(argv[1]) : EG2D_SOLVER_MULTIGRID;
    maxn = argc > 2 ? atoi(argv[2]) : 1025;
    omega = argc > 3 ? atof(argv[3]) : 0;
    for (d = 0; d < 5; ++d)
        for (s = 0; s < 6; ++s)
            if (sizes[s] <= maxn) run(domains[d], sizes[s], solver, omega);
    return 0;
}
