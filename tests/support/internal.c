#include "internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef void (*wall_fn)(double u, double *x, double *y);

static int size_of(const eg2d_grid *g, int *ni, int *nj) { return eg2d_get_size(g, ni, nj); }

/* JMIN and JMAX from two curves of u in [0, 1] (uniform in u), IMIN and
 * IMAX straight between their ends, uniform or (cluster > 0) with that
 * first and last spacing (Vinokur). */
static int set_channel(eg2d_grid *g, wall_fn lower, wall_fn upper, double cluster) {
    int ni, nj, st = size_of(g, &ni, &nj);
    if (st) return st;
    const int n = ni > nj ? ni : nj;
    double *x = malloc(sizeof(double) * (size_t)n), *y = malloc(sizeof(double) * (size_t)n),
           *t = malloc(sizeof(double) * (size_t)n);
    for (int i = 0; i < ni; ++i) lower((double)i / (ni - 1), &x[i], &y[i]);
    st = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    for (int i = 0; i < ni && !st; ++i) upper((double)i / (ni - 1), &x[i], &y[i]);
    if (!st) st = eg2d_set_side(g, EG2D_SIDE_JMAX, x, y);
    for (int end = 0; end < 2 && !st; ++end) {
        double x0, y0, x1, y1;
        lower(end, &x0, &y0);
        upper(end, &x1, &y1);
        const double width = hypot(x1 - x0, y1 - y0);
        for (int j = 0; j < nj; ++j) t[j] = (double)j / (nj - 1);
        if (cluster > 0) st = eg2d_distribution(EG2D_DIST_VINOKUR, nj, cluster / width, cluster / width, t);
        for (int j = 0; j < nj && !st; ++j) {
            const double s = t[j];
            x[j] = x0 + s * (x1 - x0);
            y[j] = y0 + s * (y1 - y0);
        }
        if (!st) st = eg2d_set_side(g, end ? EG2D_SIDE_IMAX : EG2D_SIDE_IMIN, x, y);
    }
    free(x);
    free(y);
    free(t);
    return st;
}

int domain_set_tmr(eg2d_grid *g, const char *data_dir, const char *name, int patches) {
    static const char *const side[4] = {"jmin", "imax", "jmax", "imin"};
    int st = EG2D_OK;
    for (int s = 0; s < 4 && !st; ++s) {
        char path[1024];
        snprintf(path, sizeof path, "%s/tmr/%s_%s.dat", data_dir, name, side[s]);
        st = eg2d_set_side_from_file(g, s, path);
    }
    if (st || !patches) return st;
    int ni, nj;
    size_of(g, &ni, &nj);
    const int a = ni == 137 ? 24 : 48, b = ni == 137 ? ni - 1 : 128;  /* TMR's viscous_solid stretch */
    st = eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, a, EG2D_PATCH_SYMMETRY, "upstream");
    if (!st) st = eg2d_set_patch(g, EG2D_SIDE_JMIN, a, b, EG2D_PATCH_WALL, "wall");
    if (!st && b < ni - 1) st = eg2d_set_patch(g, EG2D_SIDE_JMIN, b, ni - 1, EG2D_PATCH_SYMMETRY, "downstream");
    return st;
}

static void bend_point(double u, double r, double *x, double *y) {
    const double arc = 1.5 * M_PI / 2, s = u * (4 + arc);
    if (s < 2) {
        *x = s - 2;
        *y = r;
    } else if (s < 2 + arc) {
        const double t = M_PI / 2 - (s - 2) / 1.5;
        *x = r * cos(t);
        *y = r * sin(t);
    } else {
        *x = r;
        *y = -(s - 2 - arc);
    }
}
static void bend_inner(double u, double *x, double *y) { bend_point(u, 1, x, y); }
static void bend_outer(double u, double *x, double *y) { bend_point(u, 2, x, y); }
int domain_set_bend(eg2d_grid *g) { return set_channel(g, bend_inner, bend_outer, 0); }

static double smoothstep(double t) { return t < 0 ? 0 : t > 1 ? 1 : t * t * (3 - 2 * t); }
static void diffuser_wall(double u, double side, double *x, double *y) {
    *x = -2 + 10 * u;
    const double t = smoothstep(*x / 6);
    *y = 1.5 * t + side * (1 + t) / 2;
}
static void diffuser_lower(double u, double *x, double *y) { diffuser_wall(u, -1, x, y); }
static void diffuser_upper(double u, double *x, double *y) { diffuser_wall(u, 1, x, y); }
int domain_set_diffuser(eg2d_grid *g, double cluster) { return set_channel(g, diffuser_lower, diffuser_upper, cluster); }

static void channel_lower(double u, double *x, double *y) {
    *x = 4 * u;
    *y = 0;
}
static void channel_upper(double u, double *x, double *y) {
    *x = 4 * u;
    *y = 1;
}
int domain_set_channel(eg2d_grid *g) { return set_channel(g, channel_lower, channel_upper, 0); }

int domain_set_pipe(eg2d_grid *g) {
    int ni, nj, st = eg2d_set_topology(g, EG2D_TOPO_O);
    if (!st) st = size_of(g, &ni, &nj);
    if (st) return st;
    double *x = malloc(sizeof(double) * (size_t)ni), *y = malloc(sizeof(double) * (size_t)ni);
    for (int pass = 0; pass < 2 && !st; ++pass) {
        const double a = pass ? 2.0 : 0.5, b = pass ? 2.0 : 0.3;
        for (int i = 0; i < ni; ++i) {
            const double t = -2 * M_PI * i / (ni - 1);
            x[i] = i == ni - 1 ? a : a * cos(t);
            y[i] = i == ni - 1 ? 0.0 : b * sin(t);
        }
        st = eg2d_set_side(g, pass ? EG2D_SIDE_JMAX : EG2D_SIDE_JMIN, x, y);
    }
    free(x);
    free(y);
    return st;
}

int domain_set_cavity(eg2d_grid *g, double h) {
    int ni, nj, st = size_of(g, &ni, &nj);
    if (st) return st;
    const int n = ni > nj ? ni : nj;
    double *s = malloc(sizeof(double) * (size_t)n), *x = malloc(sizeof(double) * (size_t)n),
           *y = malloc(sizeof(double) * (size_t)n);
    for (int side = 0; side < 4 && !st; ++side) {
        const int along = side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX, m = along ? ni : nj;
        st = eg2d_distribution(EG2D_DIST_VINOKUR, m, h, h, s);
        for (int k = 0; k < m && !st; ++k) {
            const double fixed = side == EG2D_SIDE_IMAX || side == EG2D_SIDE_JMAX ? 1.0 : 0.0;
            x[k] = along ? s[k] : fixed;
            y[k] = along ? fixed : s[k];
        }
        if (!st) st = eg2d_set_side(g, side, x, y);
    }
    free(s);
    free(x);
    free(y);
    return st;
}
