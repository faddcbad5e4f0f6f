/* eg2d_bench: iterations, time and residual of every solver of the library
 * on the benchmark cases of issue 3, as a markdown table and as JSON.
 *
 *   eg2d_bench [--cases swan,valley,annulus,naca0012,naca0012-c] [--sizes 65,129,257,513,1025]
 *              [--solvers psor,af,...] [--system winslow|laplace]
 *              [--tolerance 1e-10] [--cap SECONDS] [--repeats N] [--json FILE]
 *   eg2d_bench --seed004     seed 004 Table 2: an 87x31 O-grid, E < 5e-5 and 1e-10
 *
 * Every run: TFI start, eg2d_solve to the residual (NUMERICS.md). A run that
 * passes --cap seconds (default 60) is stopped by the monitor and reported
 * as "capped" with the iterations it did. With --repeats N the time is the
 * median of N runs. The mean convergence factor per iteration is
 * (r_end / r_start)^(1/iterations); for the multilevel solvers (nested,
 * multigrid) it is the figure of merit. Solvers are found NLopt-style: every
 * id 0..99 with eg2d_solver_name(id) != NULL. Timings belong here, never in
 * the tests. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "domains.h"
#include "eg2d.h"

#define MAX_ITEMS 32

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/*--------------------------------------------------------------------------
 * Cases. Each sets the boundary of a grid of the size it chooses.
 *------------------------------------------------------------------------*/
typedef struct {
    const char *name;
    int (*size_nj)(int n); /* nj for the size n (ni = n) */
    int (*set)(eg2d_grid *g);
} bench_case;

static int square(int n) { return n; }
static int half(int n) { return n / 2 + 1; }
static int set_swan(eg2d_grid *g) { return domain_set(g, "swan"); }
static int set_valley(eg2d_grid *g) { return domain_set(g, "valley"); }
static int set_annulus(eg2d_grid *g) { return domain_set_annulus(g, 1.0, 3.0); }
static int set_annulus_source(eg2d_grid *g) {
    const int status = domain_set_annulus(g, 1.0, 3.0);
    return status != EG2D_OK ? status : eg2d_add_line_source(g, EG2D_ETA, 0.0, 100.0, 0.2);
}
static int quarter(int n) { return n / 4 + 1; }
static int set_naca0012(eg2d_grid *g) { return domain_set_airfoil_o(g, "0012", 10.0); }
static int set_naca0012_c(eg2d_grid *g) {
    int ni, nj, status = eg2d_get_size(g, &ni, &nj);
    return status ? status : domain_set_airfoil_c(g, "0012", ni / 4, 5.0);
}

static const bench_case cases[] = {
    {"swan", square, set_swan},       /* seed 003 A4 */
    {"valley", square, set_valley},   /* seed 003 A1 */
    {"annulus", half, set_annulus},   /* O-grid, 1 <= r <= 3, n x (n/2+1) */
    {"naca0012", quarter, set_naca0012}, /* O-grid, sharp-TE NACA0012 in r = 10, n x (n/4+1) */
    {"naca0012-c", quarter, set_naca0012_c}, /* C-grid, n/4 wake points a side to x = 6, r = 5, n x (n/4+1) */
    /* The annulus with seed 004 eq 14's line attraction toward the inner wall
     * (mu = 100, kappa = 0.2): iterations against "annulus" are the cost of sources. */
    {"annulus-source", half, set_annulus_source},
};
#define N_CASES (sizeof cases / sizeof cases[0])

/*--------------------------------------------------------------------------
 * One run.
 *------------------------------------------------------------------------*/
typedef struct {
    double start, cap;
    int capped;
} watch;

static int stop_at_cap(void *user, int iteration, double residual) {
    watch *w = user;
    (void)iteration;
    (void)residual;
    if (now() - w->start > w->cap) {
        w->capped = 1;
        return 1;
    }
    return 0;
}

typedef struct {
    int iterations;
    double seconds, r0, residual;
    const char *status; /* "ok", "capped", "diverged", ... */
    char message[200];
} result;

static result run_once(const bench_case *c, int n, int solver, int system, double tol, double cap) {
    result res;
    eg2d_grid *g = NULL;
    watch w;
    int status;
    memset(&res, 0, sizeof res);
    res.status = "error";
    if (eg2d_create(n, c->size_nj(n), &g) != EG2D_OK || c->set(g) != EG2D_OK || eg2d_set_solver(g, solver) ||
        eg2d_set_system(g, system) || eg2d_set_tolerance(g, tol) || eg2d_set_max_iterations(g, 1000000000) ||
        eg2d_set_parameter(g, EG2D_PARAM_FOLD_CHECK, 0) || eg2d_initialize(g, EG2D_INIT_TFI) ||
        eg2d_get_residual(g, &res.r0)) {
        snprintf(res.message, sizeof res.message, "%s", g ? eg2d_last_error(g) : eg2d_last_error(NULL));
        eg2d_destroy(g);
        return res;
    }
    w.cap = cap;
    w.capped = 0;
    eg2d_set_monitor(g, stop_at_cap, &w);
    w.start = now();
    status = eg2d_solve(g);
    res.seconds = now() - w.start;
    eg2d_get_iterations(g, &res.iterations);
    eg2d_get_residual(g, &res.residual);
    if (status == EG2D_OK) res.status = "ok";
    else if (status == EG2D_ERR_INTERRUPTED && w.capped) res.status = "capped";
    else if (status == EG2D_ERR_DIVERGED) res.status = "diverged";
    else res.status = "failed";
    if (status != EG2D_OK) snprintf(res.message, sizeof res.message, "%s", eg2d_last_error(g));
    eg2d_destroy(g);
    return res;
}

static int cmp_double(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/*--------------------------------------------------------------------------
 * Seed 004 Table 2: an 87 x 31 O-grid around an irregular body, every scheme
 * stopped when E, the mean change of a node in one iteration, is below 5e-5.
 *------------------------------------------------------------------------*/
typedef struct {
    eg2d_grid *g;
    double *x, *y, e;
    size_t n;
    int e_iterations;  /* the first iteration with E < 5e-5 */
    double e_residual; /* the residual there */
} change_watch;

static int watch_change(void *user, int iteration, double residual) {
    change_watch *c = user;
    double *x = c->x + c->n, *y = c->y + c->n, sum = 0;
    size_t k;
    eg2d_get_coordinates(c->g, x, y);
    for (k = 0; k < c->n; ++k) sum += hypot(x[k] - c->x[k], y[k] - c->y[k]);
    memcpy(c->x, x, sizeof(double) * c->n);
    memcpy(c->y, y, sizeof(double) * c->n);
    c->e = sum / (double)c->n;
    if (c->e < 5e-5 && c->e_iterations < 0) {
        c->e_iterations = iteration;
        c->e_residual = residual;
    }
    return 0;
}

/* The body r = 1 + 0.25 cos 2t + 0.15 sin 3t + 0.08 cos 5t inside the circle r = 8. */
static int set_blob(eg2d_grid *g, int ni) {
    double *x = malloc(sizeof(double) * (size_t)ni * 2), *y = x + ni;
    int i, status;
    for (i = 0; i < ni; ++i) {
        const double t = 2 * 3.14159265358979323846 * i / (ni - 1);
        const double r = 1 + 0.25 * cos(2 * t) + 0.15 * sin(3 * t) + 0.08 * cos(5 * t);
        x[i] = r * cos(t);
        y[i] = r * sin(t);
    }
    x[ni - 1] = x[0];
    y[ni - 1] = y[0];
    status = eg2d_set_topology(g, EG2D_TOPO_O);
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    for (i = 0; i < ni; ++i) {
        const double t = 2 * 3.14159265358979323846 * i / (ni - 1);
        x[i] = 8 * cos(t);
        y[i] = 8 * sin(t);
    }
    x[ni - 1] = x[0];
    y[ni - 1] = y[0];
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_JMAX, x, y);
    free(x);
    return status;
}

typedef struct {
    int e_iterations, iterations; /* to E < 5e-5; to the residual 1e-10 (-1: never) */
    double e_residual;
} seed004_result;

static seed004_result seed004_run(int solver, double omega) {
    const int ni = 87, nj = 31;
    seed004_result out = {-1, -1, 0};
    change_watch c;
    if (eg2d_create(ni, nj, &c.g) || set_blob(c.g, ni) || eg2d_set_solver(c.g, solver) ||
        eg2d_initialize(c.g, EG2D_INIT_TFI)) {
        eg2d_destroy(c.g);
        return out;
    }
    if (omega > 0) {
        if (solver == EG2D_SOLVER_AF) eg2d_set_parameter(c.g, EG2D_PARAM_AF_RELAXATION, omega);
        else eg2d_set_relaxation(c.g, omega);
    }
    c.n = (size_t)ni * nj;
    c.x = malloc(sizeof(double) * c.n * 2);
    c.y = malloc(sizeof(double) * c.n * 2);
    c.e_iterations = -1;
    eg2d_get_coordinates(c.g, c.x, c.y);
    eg2d_set_monitor(c.g, watch_change, &c);
    eg2d_set_tolerance(c.g, 1e-10);
    eg2d_set_max_iterations(c.g, 20000);
    if (eg2d_solve(c.g) == EG2D_OK) eg2d_get_iterations(c.g, &out.iterations);
    out.e_iterations = c.e_iterations;
    out.e_residual = c.e_residual;
    free(c.x);
    free(c.y);
    eg2d_destroy(c.g);
    return out;
}

static void seed004_row(const char *name, const char *label, double omega, seed004_result r) {
    printf("| %s | %s", name, label);
    if (omega > 0) printf(" %.2f", omega);
    printf(" | %d | %.2e | %d |\n", r.e_iterations, r.e_residual, r.iterations);
}

static void seed004(void) {
    int id;
    printf("Seed 004 Table 2 case: Winslow, 87x31 O-grid (irregular body inside r = 8), TFI start.\n"
           "E = mean node move of one iteration (seed 004's stop: E < 5e-5); best omega scanned\n"
           "(point solvers 1.00..1.98 by 0.02, AF 0.1..3.0 by 0.1).\n\n");
    printf("| solver | omega | iterations to E < 5e-5 | residual there | iterations to residual 1e-10 |\n");
    printf("|---|---|---:|---:|---:|\n");
    for (id = 0; id < 100; ++id) {
        const char *name = eg2d_solver_name(id);
        seed004_result r, best_e = {-1, -1, 0}, best_r = {-1, -1, 0};
        double w_e = 0, w_r = 0;
        int k;
        if (!name) continue;
        seed004_row(name, "automatic", 0, seed004_run(id, 0));
        for (k = 0; k < 50; ++k) {
            const double w = id == EG2D_SOLVER_AF ? 0.1 * (k + 1) : 1.0 + 0.02 * k;
            if (id == EG2D_SOLVER_AF && w > 3.0) break;
            r = seed004_run(id, w);
            if (r.e_iterations > 0 && (best_e.e_iterations < 0 || r.e_iterations < best_e.e_iterations)) {
                best_e = r;
                w_e = w;
            }
            if (r.iterations > 0 && (best_r.iterations < 0 || r.iterations < best_r.iterations)) {
                best_r = r;
                w_r = w;
            }
        }
        seed004_row(name, "best for E", w_e, best_e);
        seed004_row(name, "best for 1e-10", w_r, best_r);
    }
}

/*--------------------------------------------------------------------------
 * Options and output.
 *------------------------------------------------------------------------*/
static int split(char *list, const char **items) {
    int n = 0;
    char *tok = strtok(list, ",");
    while (tok && n < MAX_ITEMS) {
        items[n++] = tok;
        tok = strtok(NULL, ",");
    }
    return n;
}

static void usage(void) {
    fprintf(stderr, "usage: eg2d_bench [--cases LIST] [--sizes LIST] [--solvers LIST] [--system winslow|laplace]\n"
                    "                  [--tolerance T] [--cap SECONDS] [--repeats N] [--json FILE] [--seed004]\n");
}

int main(int argc, char **argv) {
    const char *case_names[MAX_ITEMS], *size_list[MAX_ITEMS], *solver_names[MAX_ITEMS];
    char cases_arg[256] = "swan,valley,annulus", sizes_arg[256] = "65,129,257,513,1025", solvers_arg[512] = "";
    const char *json_path = NULL;
    double tol = 1e-10, cap = 60;
    int repeats = 1, system = EG2D_SYSTEM_WINSLOW, n_cases, n_sizes, n_solvers = 0, a, ci, si, vi, first = 1;
    FILE *json = NULL;

    for (a = 1; a < argc; ++a) {
        const char *opt = argv[a], *val = a + 1 < argc ? argv[a + 1] : NULL;
        if (!strcmp(opt, "--seed004")) {
            seed004();
            return 0;
        }
        if (!val) {
            usage();
            return 2;
        }
        ++a;
        if (!strcmp(opt, "--cases")) snprintf(cases_arg, sizeof cases_arg, "%s", val);
        else if (!strcmp(opt, "--sizes")) snprintf(sizes_arg, sizeof sizes_arg, "%s", val);
        else if (!strcmp(opt, "--solvers")) snprintf(solvers_arg, sizeof solvers_arg, "%s", val);
        else if (!strcmp(opt, "--system")) system = !strcmp(val, "laplace") ? EG2D_SYSTEM_LAPLACE : EG2D_SYSTEM_WINSLOW;
        else if (!strcmp(opt, "--tolerance")) tol = atof(val);
        else if (!strcmp(opt, "--cap")) cap = atof(val);
        else if (!strcmp(opt, "--repeats")) repeats = atoi(val);
        else if (!strcmp(opt, "--json")) json_path = val;
        else {
            usage();
            return 2;
        }
    }
    if (repeats < 1 || repeats > 99 || !(cap > 0) || !(tol > 0)) {
        usage();
        return 2;
    }
    n_cases = split(cases_arg, case_names);
    n_sizes = split(sizes_arg, size_list);
    if (solvers_arg[0]) n_solvers = split(solvers_arg, solver_names);
    else {
        int id;
        for (id = 0; id < 100 && n_solvers < MAX_ITEMS; ++id)
            if (eg2d_solver_name(id)) solver_names[n_solvers++] = eg2d_solver_name(id);
    }
    for (vi = 0; vi < n_solvers; ++vi) { /* every name must be known before any run */
        int id, known = 0;
        for (id = 0; id < 100; ++id) known |= eg2d_solver_name(id) && !strcmp(eg2d_solver_name(id), solver_names[vi]);
        if (!known) {
            fprintf(stderr, "no solver %s in this library\n", solver_names[vi]);
            return 2;
        }
    }
    if (json_path && !(json = fopen(json_path, "w"))) {
        perror(json_path);
        return 1;
    }
    if (json) fprintf(json, "{\"system\": \"%s\", \"tolerance\": %g, \"cap_seconds\": %g, \"repeats\": %d, \"runs\": [",
                      system ? "winslow" : "laplace", tol, cap, repeats);

    printf("%s, TFI start, residual %g, cap %g s, median of %d\n\n", system ? "Winslow" : "Laplace", tol, cap, repeats);
    printf("| case | size | solver | iterations | seconds | final residual | iterations/s | factor/iteration | status |\n");
    printf("|---|---|---|---:|---:|---:|---:|---:|---|\n");
    for (ci = 0; ci < n_cases; ++ci) {
        const bench_case *c = NULL;
        size_t k;
        for (k = 0; k < N_CASES; ++k)
            if (!strcmp(cases[k].name, case_names[ci])) c = &cases[k];
        if (!c) {
            fprintf(stderr, "no case %s\n", case_names[ci]);
            return 2;
        }
        for (si = 0; si < n_sizes; ++si) {
            const int n = atoi(size_list[si]);
            for (vi = 0; vi < n_solvers; ++vi) {
                int id, solver = -1, r;
                double secs[99], factor;
                result res;
                for (id = 0; id < 100; ++id)
                    if (eg2d_solver_name(id) && !strcmp(eg2d_solver_name(id), solver_names[vi])) solver = id;
                if (solver < 0) {
                    fprintf(stderr, "no solver %s in this library\n", solver_names[vi]);
                    return 2;
                }
                for (r = 0; r < repeats; ++r) {
                    res = run_once(c, n, solver, system, tol, cap);
                    secs[r] = res.seconds;
                    if (strcmp(res.status, "ok")) break; /* a capped or failed run is not repeated */
                }
                if (r == repeats) {
                    qsort(secs, (size_t)repeats, sizeof secs[0], cmp_double);
                    res.seconds = secs[repeats / 2];
                }
                factor = res.iterations > 0 && res.r0 > 0 && res.residual > 0
                             ? pow(res.residual / res.r0, 1.0 / res.iterations) : NAN;
                printf("| %s | %dx%d | %s | %d | %.3f | %.2e | %.1f | %.4f | %s |\n", c->name, n, c->size_nj(n),
                       solver_names[vi], res.iterations, res.seconds, res.residual,
                       res.seconds > 0 ? res.iterations / res.seconds : 0.0, factor, res.status);
                if (res.message[0] && strcmp(res.status, "capped")) fprintf(stderr, "  %s\n", res.message);
                fflush(stdout);
                if (json) {
                    fprintf(json,
                            "%s\n  {\"case\": \"%s\", \"ni\": %d, \"nj\": %d, \"solver\": \"%s\", \"iterations\": %d, "
                            "\"seconds\": %.6f, \"start_residual\": %.6e, \"final_residual\": %.6e, "
                            "\"iterations_per_second\": %.3f, \"factor_per_iteration\": %.6f, \"status\": \"%s\"}",
                            first ? "" : ",", c->name, n, c->size_nj(n), solver_names[vi], res.iterations,
                            res.seconds, res.r0, res.residual, res.seconds > 0 ? res.iterations / res.seconds : 0.0,
                            isnan(factor) ? -1.0 : factor, res.status);
                    first = 0;
                }
            }
        }
    }
    if (json) {
        fprintf(json, "\n]}\n");
        fclose(json);
    }
    return 0;
}
