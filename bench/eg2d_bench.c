/* eg2d_bench: iterations, time and residual of every solver of the library
 * on the benchmark cases (cases.c), as a markdown table and as JSON.
 *
 *   eg2d_bench [--cases swan,valley,...] [--sizes 65,129,257,513,1025]
 *              [--solvers psor,psor:1,af,...] [--system winslow|laplace]
 *              [--tolerance 1e-10] [--cap SECONDS] [--repeats N] [--json FILE]
 *   eg2d_bench --compare [--repeats N] [--json FILE]
 *              swan 129^2 point Gauss-Seidel (PSOR, omega = 1) against
 *              multigrid in one run; swan 1025^2 multigrid against the point
 *              Gauss-Seidel extrapolated from its sweeps at 65^2 and 129^2
 *   eg2d_bench --ogrid       Ly & Norrison (2007) Table 2: an 87x31 O-grid, E < 5e-5 and 1e-10
 *   eg2d_bench --sweep [--repeats N] [--svg FILE]
 *              multigrid at 2^k, 2^k+1, 2^k+2 and round sizes from 65 to
 *              1025 against the nearest 2^k+1 size (sweep.c)
 *   eg2d_bench --march       the hyperbolic march: NACA 0012 O-grid 257x129 to 100 chords
 *   eg2d_bench --wall        wall-resolved NACA 0012 O-grids: wall control, hybrid layer, march
 *   eg2d_bench --internal    wall-resolved internal flows (TMR flat plate, bump, bend, diffuser, pipe, cavity)
 *   eg2d_bench --blocks      a set of blocks (a backward-facing step) against one block of as many nodes (blocks.c)
 *   eg2d_bench --variational [--cases LIST] [--sizes LIST] [--grids LIST] [--cap S]
 *                            EG2D_SYSTEM_VARIATIONAL (V = aA + bS + cO + dW) against Winslow on
 *                            the course notes' domains at 65, 129, 257 (variational.c)
 *   eg2d_bench --quick       swan, annulus, NACA 0012 O and C at 65, 129, 250, every solver
 *                            (cap 10 CPU s): the same table in about 20 seconds
 *
 * Cases (cases.c): swan, valley, annulus, annulus-source, naca0012,
 * naca0012-c, naca0012-wall. A solver name may carry ":omega" (psor:1
 * is point Gauss-Seidel): eg2d_set_relaxation(omega) for that column.
 *
 * Every run: TFI start, eg2d_solve to the residual (NUMERICS.md), on this
 * one thread. Printed: wall seconds and the CPU seconds of this thread (the
 * machine may be shared: CPU time is the cost); iterations per CPU second;
 * the mean factor per iteration after the first, (r_end / r_1)^(1/(it-1))
 * (multigrid's first cycle is its full-multigrid start); work units, 1 WU =
 * the CPU time of one eg2d_get_residual on the same grid (a fine-grid
 * residual evaluation), measured after the run. A run whose CPU time passes
 * --cap seconds (default 60; or its wall time 5x that) is stopped by the
 * monitor and reported as "capped" with the iterations it did. With
 * --repeats N the times are medians of N runs. JSON has -1 where a value
 * is not finite (or undefined). A run that reaches the
 * residual with folded cells is reported as "folded". Solvers are found
 * NLopt-style: every id 0..99 with eg2d_solver_name(id) != NULL. Timings
 * belong here, never in the tests. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"

#define MAX_ITEMS 32

static double clock_of(clockid_t id) {
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
double bench_wall(void) { return clock_of(CLOCK_MONOTONIC); }
double bench_cpu(void) { return clock_of(CLOCK_THREAD_CPUTIME_ID); }

/*--------------------------------------------------------------------------
 * One run.
 *------------------------------------------------------------------------*/
typedef struct {
    double cpu0, wall0, cap, r1;
    int capped;
} watch;

static int stop_at_cap(void *user, int iteration, double residual) {
    watch *w = user;
    if (iteration == 1) w->r1 = residual;
    if (bench_cpu() - w->cpu0 > w->cap || bench_wall() - w->wall0 > 5 * w->cap) {
        w->capped = 1;
        return 1;
    }
    return 0;
}

typedef bench_result result;

/* The CPU seconds of one residual evaluation: the mean of at least 3 and at
 * least 0.02 s of them (the clock's resolution is far below that). */
static double residual_seconds(const eg2d_grid *g) {
    const double c0 = bench_cpu();
    double r, c;
    int k = 0;
    do {
        eg2d_get_residual(g, &r);
        ++k;
        c = bench_cpu() - c0;
    } while (k < 3 || c < 0.02);
    return c / k;
}

static result run_once(const bench_case *c, int n, int nj, int solver, double omega, int system, double tol,
                       double cap) {
    result res;
    eg2d_grid *g = NULL;
    watch w;
    double folded;
    int status;
    memset(&res, 0, sizeof res);
    res.status = "error";
    if (eg2d_create(n, nj, &g) != EG2D_OK || c->set(g) != EG2D_OK || eg2d_set_solver(g, solver) ||
        eg2d_set_system(g, system) || eg2d_set_tolerance(g, tol) || eg2d_set_max_iterations(g, 1000000000) ||
        eg2d_set_relaxation(g, omega) || eg2d_set_parameter(g, EG2D_PARAM_FOLD_CHECK, 0) ||
        eg2d_initialize(g, EG2D_INIT_TFI) || eg2d_get_residual(g, &res.r0)) {
        snprintf(res.message, sizeof res.message, "%s", g ? eg2d_last_error(g) : eg2d_last_error(NULL));
        eg2d_destroy(g);
        return res;
    }
    w.cap = cap;
    w.capped = 0;
    w.r1 = NAN;
    eg2d_set_monitor(g, stop_at_cap, &w);
    w.wall0 = bench_wall();
    w.cpu0 = bench_cpu();
    status = eg2d_solve(g);
    res.cpu = bench_cpu() - w.cpu0;
    res.wall = bench_wall() - w.wall0;
    res.r1 = w.r1;
    eg2d_get_iterations(g, &res.iterations);
    eg2d_get_residual(g, &res.residual);
    eg2d_get_run_info(g, EG2D_RUN_LEVELS, &res.levels);
    eg2d_get_run_info(g, EG2D_RUN_LEVELS_BUILT, &res.levels_built);
    eg2d_get_run_info(g, EG2D_RUN_EVENTS, &res.events);
    if (res.events > 0 && !eg2d_get_run_event(g, 0, NULL, res.event, (int)sizeof res.event)) {
        char *q;
        for (q = res.event; *q; ++q)
            if (*q == '"' || *q == '\\') *q = '\''; /* as JSON text */
    }
    res.residual_cpu = residual_seconds(g);
    res.wall_spacing = bench_wall_spacing(g);
    if (eg2d_get_quality(g, EG2D_QUALITY_ASPECT_RATIO, &res.aspect_ratio)) res.aspect_ratio = NAN;
    /* the bench turns the library's fold check off to time every run to its
     * end, so a run that converged to a folded grid is flagged here */
    if (status == EG2D_OK) res.status = eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded) || folded > 0 ? "folded" : "ok";
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

/* Median times of `repeats` runs; a capped or failed run is not repeated. */
result bench_run(const bench_case *c, int n, int nj, int solver, double omega, int system, double tol, double cap,
                 int repeats) {
    double wall[99], cpu[99], wu[99];
    result res;
    int r;
    for (r = 0; r < repeats; ++r) {
        res = run_once(c, n, nj, solver, omega, system, tol, cap);
        wall[r] = res.wall;
        cpu[r] = res.cpu;
        wu[r] = res.residual_cpu;
        if (strcmp(res.status, "ok")) return res;
    }
    qsort(wall, (size_t)repeats, sizeof wall[0], cmp_double);
    qsort(cpu, (size_t)repeats, sizeof cpu[0], cmp_double);
    qsort(wu, (size_t)repeats, sizeof wu[0], cmp_double);
    res.wall = wall[repeats / 2];
    res.cpu = cpu[repeats / 2];
    res.residual_cpu = wu[repeats / 2];
    return res;
}

/*--------------------------------------------------------------------------
 * Output.
 *------------------------------------------------------------------------*/
static FILE *json;
static int json_first = 1;

static double factor_after_first(const result *r) {
    return r->iterations > 1 && r->r1 > 0 && r->residual > 0 ? pow(r->residual / r->r1, 1.0 / (r->iterations - 1))
                                                            : NAN;
}

static void print_header(void) {
    printf("| case | size | solver | iterations | wall s | CPU s | final residual | iterations/CPU s "
           "| factor/iteration | WU/iteration | WU | wall spacing | max aspect ratio | status |\n");
    printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
}

static void print_row(const char *case_name, int ni, int nj, const char *solver, const result *r) {
    const double factor = factor_after_first(r);
    const double wu = r->residual_cpu > 0 ? r->cpu / r->residual_cpu : NAN;
    const double rate = r->cpu > 0 ? r->iterations / r->cpu : 0.0;
    printf("| %s | %dx%d | %s | %d | %.3f | %.3f | %.2e | %.1f | %.4f | %.1f | %.0f | %.2e | %.3g | %s |\n",
           case_name, ni, nj, solver, r->iterations, r->wall, r->cpu, r->residual, rate, factor,
           r->iterations > 0 ? wu / r->iterations : NAN, wu, r->wall_spacing, r->aspect_ratio, r->status);
    if (r->message[0] && strcmp(r->status, "capped")) fprintf(stderr, "  %s\n", r->message);
    fflush(stdout);
    if (!json) return;
    fprintf(json,
            "%s\n  {\"case\": \"%s\", \"ni\": %d, \"nj\": %d, \"solver\": \"%s\", \"iterations\": %d, "
            "\"wall_seconds\": %.6f, \"cpu_seconds\": %.6f, \"start_residual\": %.6e, \"final_residual\": %.6e, "
            "\"iterations_per_cpu_second\": %.3f, \"factor_per_iteration\": %.6f, \"residual_cpu_seconds\": %.6e, "
            "\"work_units\": %.2f, \"wall_spacing\": %.6e, \"max_aspect_ratio\": %.6e, \"status\": \"%s\", "
            "\"levels\": %d, \"levels_built\": %d, \"events\": %d, \"first_event\": \"%s\"}",
            json_first ? "" : ",", case_name, ni, nj, solver, r->iterations, r->wall, r->cpu, r->r0, r->residual,
            rate, isfinite(factor) ? factor : -1.0, r->residual_cpu, isfinite(wu) ? wu : -1.0,
            isfinite(r->wall_spacing) ? r->wall_spacing : -1.0, isfinite(r->aspect_ratio) ? r->aspect_ratio : -1.0,
            r->status, r->levels, r->levels_built, r->events, r->event);
    json_first = 0;
}

/*--------------------------------------------------------------------------
 * --compare: the two speed targets (multigrid against Gauss-Seidel, AF against PSOR), measured in one run.
 *------------------------------------------------------------------------*/
static void compare(int repeats) {
    const bench_case *swan = bench_find_case("swan");
    const int W = EG2D_SYSTEM_WINSLOW;
    result gs65, gs129, mg129, gs1025, mg1025;
    double p, sweeps, gs_cpu;
    printf("Winslow, TFI start, residual 1e-10, swan (elliptic-grid course notes, A4); CPU s of this thread, "
           "median of %d\n\n", repeats);
    print_header();
    gs65 = bench_run(swan, 65, swan->size_nj(65), EG2D_SOLVER_PSOR, 1.0, W, 1e-10, 600, 1);
    print_row("swan", 65, 65, "psor:1", &gs65);
    gs129 = bench_run(swan, 129, swan->size_nj(129), EG2D_SOLVER_PSOR, 1.0, W, 1e-10, 600, repeats);
    print_row("swan", 129, 129, "psor:1", &gs129);
    mg129 = bench_run(swan, 129, swan->size_nj(129), EG2D_SOLVER_MULTIGRID, 0.0, W, 1e-10, 600, repeats);
    print_row("swan", 129, 129, "multigrid", &mg129);
    /* point Gauss-Seidel at 1025^2 takes hours: its cost per sweep is measured
     * over a few CPU seconds, its sweep count extrapolated below */
    gs1025 = run_once(swan, 1025, 1025, EG2D_SOLVER_PSOR, 1.0, W, 1e-10, 3.0);
    print_row("swan", 1025, 1025, "psor:1", &gs1025);
    mg1025 = bench_run(swan, 1025, swan->size_nj(1025), EG2D_SOLVER_MULTIGRID, 0.0, W, 1e-10, 600, repeats);
    print_row("swan", 1025, 1025, "multigrid", &mg1025);
    printf("\nswan 129^2, side by side: multigrid %.0fx faster than point Gauss-Seidel (PSOR, omega = 1) "
           "in CPU time, %.0fx in wall time (%d sweeps against %d cycles)\n",
           gs129.cpu / mg129.cpu, gs129.wall / mg129.wall, gs129.iterations, mg129.iterations);
    /* sweeps grow as n^p: p from 65^2 -> 129^2 (about 2: 4x per doubling) */
    p = log2((double)gs129.iterations / gs65.iterations);
    sweeps = gs129.iterations * pow(1024.0 / 128.0, p);
    gs_cpu = sweeps * gs1025.cpu / gs1025.iterations;
    printf("swan 1025^2: multigrid %.2f s CPU, %.2f s wall, %d cycles; point Gauss-Seidel extrapolated: "
           "%.0f sweeps (n^%.2f from 65^2 and 129^2) x %.4f CPU s per sweep (measured at 1025^2) = %.0f s, "
           "%.0fx the multigrid\n",
           mg1025.cpu, mg1025.wall, mg1025.iterations, sweeps, p, gs1025.cpu / gs1025.iterations, gs_cpu,
           gs_cpu / mg1025.cpu);
    if (json)
        fprintf(json,
                "\n], \"compare\": {\"speedup_129_cpu\": %.2f, \"speedup_129_wall\": %.2f, "
                "\"gs_sweeps_exponent\": %.4f, \"gs_1025_sweeps_extrapolated\": %.0f, "
                "\"gs_1025_cpu_seconds_extrapolated\": %.1f, \"mg_1025_cpu_seconds\": %.4f, "
                "\"speedup_1025_cpu_extrapolated\": %.0f",
                gs129.cpu / mg129.cpu, gs129.wall / mg129.wall, p, sweeps, gs_cpu, mg1025.cpu, gs_cpu / mg1025.cpu);
}

/*--------------------------------------------------------------------------
 * Options.
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

/* "name" or "name:omega" -> the solver id (-1 if none) and omega (0: automatic). */
static int parse_solver(const char *spec, double *omega) {
    const char *colon = strchr(spec, ':');
    const size_t len = colon ? (size_t)(colon - spec) : strlen(spec);
    int id;
    *omega = colon ? atof(colon + 1) : 0.0;
    for (id = 0; id < 100; ++id)
        if (eg2d_solver_name(id) && strlen(eg2d_solver_name(id)) == len && !strncmp(eg2d_solver_name(id), spec, len))
            return id;
    return -1;
}

static void usage(void) {
    fprintf(stderr, "usage: eg2d_bench [--cases LIST] [--sizes LIST] [--solvers LIST (name or name:omega)]\n"
                    "                  [--system winslow|laplace] [--tolerance T] [--cap CPU-SECONDS]\n"
                    "                  [--repeats N] [--json FILE]\n"
                    "                  [--compare | --ogrid | --march | --wall | --internal | --blocks | --variational]\n"
                    "       eg2d_bench --sweep [--repeats N (3)] [--svg FILE]\n"
                    "       eg2d_bench --quick [--repeats N] [--json FILE]   (a subset in about 20 s)\n");
}

int main(int argc, char **argv) {
    const char *case_names[MAX_ITEMS], *size_list[MAX_ITEMS], *solver_names[MAX_ITEMS];
    char cases_arg[256] = "swan,valley,annulus", sizes_arg[256] = "65,129,257,513,1025", solvers_arg[512] = "";
    const char *json_path = NULL;
    double tol = 1e-10, cap = 60;
    int repeats = 1, system = EG2D_SYSTEM_WINSLOW, n_cases, n_sizes, n_solvers = 0, a, ci, si, vi, do_compare = 0;

    for (a = 1; a < argc; ++a) {
        const char *opt = argv[a], *val = a + 1 < argc ? argv[a + 1] : NULL;
        if (!strcmp(opt, "--ogrid")) {
            bench_ogrid();
            return 0;
        }
        if (!strcmp(opt, "--sweep")) {
            /* --sweep [--repeats N] [--svg FILE], in that order */
            const char *svg = NULL;
            int rep = 3, b;
            for (b = a + 1; b + 1 < argc; b += 2) {
                if (!strcmp(argv[b], "--repeats")) rep = atoi(argv[b + 1]);
                else if (!strcmp(argv[b], "--svg")) svg = argv[b + 1];
            }
            if (rep < 1 || rep > 99) {
                usage();
                return 2;
            }
            bench_sweep(rep, svg);
            return 0;
        }
        if (!strcmp(opt, "--march")) {
            bench_march();
            return 0;
        }
        if (!strcmp(opt, "--internal")) {
            bench_internal();
            return 0;
        }
        if (!strcmp(opt, "--blocks")) {
            bench_blocks();
            return 0;
        }
        if (!strcmp(opt, "--wall")) {
            bench_walls();
            return 0;
        }
        if (!strcmp(opt, "--variational")) {
            /* --variational [--cases LIST] [--sizes LIST] [--grids LIST] [--cap S] */
            const char *vc = NULL, *vs = NULL, *vg = NULL;
            double vcap = 20.0;
            int b;
            for (b = a + 1; b + 1 < argc; b += 2) {
                if (!strcmp(argv[b], "--cases")) vc = argv[b + 1];
                else if (!strcmp(argv[b], "--sizes")) vs = argv[b + 1];
                else if (!strcmp(argv[b], "--grids")) vg = argv[b + 1];
                else if (!strcmp(argv[b], "--cap")) vcap = atof(argv[b + 1]);
            }
            if (!(vcap > 0)) {
                usage();
                return 2;
            }
            bench_variational(vc, vs, vg, vcap);
            return 0;
        }
        if (!strcmp(opt, "--quick")) {
            /* A representative subset in about 20 seconds, to compare a change:
             * a single block, an O-grid, the NACA 0012 O- and C-grids, every
             * solver, at two 2^k+1 sizes and a round one. */
            snprintf(cases_arg, sizeof cases_arg, "%s", "swan,annulus,naca0012,naca0012-c");
            snprintf(sizes_arg, sizeof sizes_arg, "%s", "65,129,250");
            cap = 10;
            continue;
        }
        if (!strcmp(opt, "--compare")) {
            do_compare = 1;
            continue;
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
        double omega;
        if (parse_solver(solver_names[vi], &omega) < 0 || omega < 0 || omega >= 2) {
            fprintf(stderr, "no solver %s in this library (or omega outside [0, 2))\n", solver_names[vi]);
            return 2;
        }
    }
    for (ci = 0; ci < n_cases; ++ci)
        if (!bench_find_case(case_names[ci])) {
            fprintf(stderr, "no case %s\n", case_names[ci]);
            return 2;
        }
    if (json_path && !(json = fopen(json_path, "w"))) {
        perror(json_path);
        return 1;
    }
    if (json) fprintf(json, "{\"system\": \"%s\", \"tolerance\": %g, \"cap_cpu_seconds\": %g, \"repeats\": %d, \"runs\": [",
                      system ? "winslow" : "laplace", do_compare ? 1e-10 : tol, do_compare ? 600 : cap, repeats);
    if (do_compare) compare(repeats);
    else {
        printf("%s, TFI start, residual %g, cap %g CPU s, times: median of %d\n\n", system ? "Winslow" : "Laplace", tol,
               cap, repeats);
        print_header();
        for (ci = 0; ci < n_cases; ++ci) {
            const bench_case *c = bench_find_case(case_names[ci]);
            for (si = 0; si < n_sizes; ++si) {
                const int n = atoi(size_list[si]);
                for (vi = 0; vi < n_solvers; ++vi) {
                    double omega;
                    const int solver = parse_solver(solver_names[vi], &omega);
                    const result res = bench_run(c, n, c->size_nj(n), solver, omega, system, tol, cap, repeats);
                    print_row(c->name, n, c->size_nj(n), solver_names[vi], &res);
                }
            }
        }
    }
    if (json) {
        fprintf(json, do_compare ? "}}\n" : "\n]}\n");
        fclose(json);
    }
    return 0;
}
