/* Ly & Norrison (2007) Table 2 (eg2d_bench --ogrid): an 87 x 31 O-grid around an
 * irregular body, every scheme stopped when E, the mean change of a node in
 * one iteration, is below 5e-5, and at the residual 1e-10. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "domains.h"

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

typedef struct {
    int e_iterations, iterations; /* to E < 5e-5; to the residual 1e-10 (-1: never) */
    double e_residual;
} ogrid_result;

static ogrid_result ogrid_run(int solver, double omega) {
    const int ni = 87, nj = 31;
    ogrid_result out = {-1, -1, 0};
    change_watch c;
    if (eg2d_create(ni, nj, &c.g) || domain_set_blob(c.g) || eg2d_set_solver(c.g, solver) ||
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

static void ogrid_row(const char *name, const char *label, double omega, ogrid_result r) {
    printf("| %s | %s", name, label);
    if (omega > 0) printf(" %.2f", omega);
    printf(" | %d | %.2e | %d |\n", r.e_iterations, r.e_residual, r.iterations);
}

void bench_ogrid(void) {
    int id;
    printf("Ly & Norrison (2007) Table 2 case: Winslow, 87x31 O-grid (irregular body inside r = 8), TFI start.\n"
           "E = mean node move of one iteration (the stop test of Ly & Norrison 2007: E < 5e-5); best omega scanned\n"
           "(point solvers 1.00..1.98 by 0.02, AF 0.1..3.0 by 0.1).\n\n");
    printf("| solver | omega | iterations to E < 5e-5 | residual there | iterations to residual 1e-10 |\n");
    printf("|---|---|---:|---:|---:|\n");
    for (id = 0; id < 100; ++id) {
        const char *name = eg2d_solver_name(id);
        ogrid_result r, best_e = {-1, -1, 0}, best_r = {-1, -1, 0};
        double w_e = 0, w_r = 0;
        int k;
        if (!name) continue;
        ogrid_row(name, "automatic", 0, ogrid_run(id, 0));
        for (k = 0; k < 50; ++k) {
            const double w = id == EG2D_SOLVER_AF ? 0.1 * (k + 1) : 1.0 + 0.02 * k;
            if (id == EG2D_SOLVER_AF && w > 3.0) break;
            r = ogrid_run(id, w);
            if (r.e_iterations > 0 && (best_e.e_iterations < 0 || r.e_iterations < best_e.e_iterations)) {
                best_e = r;
                w_e = w;
            }
            if (r.iterations > 0 && (best_r.iterations < 0 || r.iterations < best_r.iterations)) {
                best_r = r;
                w_r = w;
            }
        }
        ogrid_row(name, "best for E", w_e, best_e);
        ogrid_row(name, "best for 1e-10", w_r, best_r);
    }
}
