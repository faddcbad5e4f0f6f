#include "block_domains.h"

#include <math.h>
#include <stdlib.h>

static double tanh_cluster(double s, double beta) { return 1.0 + tanh(beta * (s - 1.0)) / tanh(beta); }
static double both_ends(double s, double beta) {
    return s <= 0.5 ? 0.5 * tanh_cluster(2.0 * s, beta) : 1.0 - 0.5 * tanh_cluster(2.0 * (1.0 - s), beta);
}

static int tensor_block(int ni, int nj, const double *xs, const double *ys, eg2d_grid **grid);

int block_rectangle(int ni, int nj, double x0, double x1, double y0, double y1, int cluster_x, int cluster_y,
                    eg2d_grid **grid) {
    double *xs = malloc(sizeof(double) * (size_t)ni), *ys = malloc(sizeof(double) * (size_t)nj);
    int rc = xs && ys ? EG2D_OK : EG2D_ERR_MEMORY;
    for (int i = 0; !rc && i < ni; ++i) {
        const double s = (double)i / (ni - 1);
        xs[i] = x0 + (x1 - x0) * (cluster_x > 0 ? tanh_cluster(s, 2.0) : cluster_x < 0 ? 1.0 - tanh_cluster(1.0 - s, 2.0) : s);
    }
    for (int j = 0; !rc && j < nj; ++j) {
        const double t = (double)j / (nj - 1);
        ys[j] = y0 + (y1 - y0) * (cluster_y ? both_ends(t, 2.5) : t);
    }
    if (!rc) rc = tensor_block(ni, nj, xs, ys, grid);
    else *grid = NULL;
    free(xs);
    free(ys);
    return rc;
}

int step_blocks(int ni_up, int ni_down, int nj_upper, int nj_lower, eg2d_grid *grids[3], eg2d_blocks **set) {
    int rc, b;
    grids[0] = grids[1] = grids[2] = NULL;
    *set = NULL;
    if ((rc = block_rectangle(ni_up, nj_upper, -4.0, 0.0, 1.0, 9.0, 1, 1, &grids[0])) ||
        (rc = block_rectangle(ni_down, nj_upper, 0.0, 20.0, 1.0, 9.0, -1, 1, &grids[1])) ||
        (rc = block_rectangle(ni_down, nj_lower, 0.0, 20.0, 0.0, 1.0, -1, 1, &grids[2])) || (rc = eg2d_blocks_create(set)))
        return rc;
    for (int k = 0; k < 3; ++k)
        if ((rc = eg2d_blocks_add(*set, grids[k], &b))) return rc;
    if ((rc = eg2d_blocks_join(*set, 0, EG2D_SIDE_IMAX, 0, nj_upper - 1, 1, EG2D_SIDE_IMIN, 0, nj_upper - 1)))
        return rc;
    return eg2d_blocks_join(*set, 1, EG2D_SIDE_JMIN, 0, ni_down - 1, 2, EG2D_SIDE_JMAX, 0, ni_down - 1);
}

void bump_point(int ni, int nj, int I, int J, double *x, double *y) {
    const double s = (double)J / (nj - 1);
    *x = 2.0 * I / (ni - 1);
    const double b = 0.25 * exp(-12.0 * (*x - 0.7) * (*x - 0.7));
    *y = b + (1.0 - b) * s * s;
}

int bump_block(int ni, int nj, int bni, int bnj, block_map map, const int *p, eg2d_grid **grid) {
    int rc = eg2d_create(bni, bnj, grid);
    for (int side = 0; !rc && side < 4; ++side) {
        const int n = (side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX) ? bni : bnj;
        double *x = malloc(sizeof(double) * (size_t)n), *y = malloc(sizeof(double) * (size_t)n);
        if (!x || !y) rc = EG2D_ERR_MEMORY;
        for (int q = 0; !rc && q < n; ++q) {
            int i = q, j = 0, I, J;
            if (side == EG2D_SIDE_JMAX) j = bnj - 1;
            if (side == EG2D_SIDE_IMIN) i = 0, j = q;
            if (side == EG2D_SIDE_IMAX) i = bni - 1, j = q;
            map(i, j, &I, &J, p);
            bump_point(ni, nj, I, J, &x[q], &y[q]);
        }
        if (!rc) rc = eg2d_set_side(*grid, side, x, y);
        free(x);
        free(y);
    }
    return rc;
}

static void shifted(int i, int j, int *I, int *J, const int *p) { *I = i + p[0], *J = j; }

int bump_halves(int ni, int nj, int mid, eg2d_grid *grids[2], eg2d_blocks **set) {
    const int zero = 0;
    int rc, b;
    grids[0] = grids[1] = NULL;
    *set = NULL;
    if ((rc = bump_block(ni, nj, mid + 1, nj, shifted, &zero, &grids[0])) ||
        (rc = bump_block(ni, nj, ni - mid, nj, shifted, &mid, &grids[1])) || (rc = eg2d_blocks_create(set)) ||
        (rc = eg2d_blocks_add(*set, grids[0], &b)) || (rc = eg2d_blocks_add(*set, grids[1], &b)))
        return rc;
    return eg2d_blocks_join(*set, 0, EG2D_SIDE_IMAX, 0, nj - 1, 1, EG2D_SIDE_IMIN, 0, nj - 1);
}

/* A rectangle whose nodes are xs[i], ys[j]. */
static int tensor_block(int ni, int nj, const double *xs, const double *ys, eg2d_grid **grid) {
    int rc = eg2d_create(ni, nj, grid);
    if (rc) return rc;
    double *x = calloc((size_t)ni * (size_t)nj, sizeof(double)), *y = calloc((size_t)ni * (size_t)nj, sizeof(double));
    if (!x || !y) rc = EG2D_ERR_MEMORY;
    for (int j = 0; !rc && j < nj; ++j)
        for (int i = 0; i < ni; ++i) {
            x[i + ni * j] = xs[i];
            y[i + ni * j] = ys[j];
        }
    if (!rc) rc = eg2d_set_boundary(*grid, x, y);
    free(x);
    free(y);
    return rc;
}

/* n nodes from a to b, Vinokur's spacings first and last (lengths). */
static int spaced(int n, double a, double b, double first, double last, double *out) {
    const int rc = eg2d_distribution(EG2D_DIST_VINOKUR, n, first / (b - a), last / (b - a), out);
    for (int k = 0; !rc && k < n; ++k) out[k] = a + (b - a) * out[k];
    return rc;
}

int walled_step_blocks(double h, int ni_up, int ni_down, int nj_upper, int nj_lower, eg2d_grid *grids[3],
                       eg2d_blocks **set) {
    int rc, b;
    grids[0] = grids[1] = grids[2] = NULL;
    *set = NULL;
    double *xu = malloc(sizeof(double) * (size_t)ni_up), *xd = malloc(sizeof(double) * (size_t)ni_down);
    double *yu = malloc(sizeof(double) * (size_t)nj_upper), *yl = malloc(sizeof(double) * (size_t)nj_lower);
    const double mid = h > 0.0 ? h : 0.6 / (nj_lower - 1);  /* at the step's height, y = 1: the shear layer */
    if (!xu || !xd || !yu || !yl) rc = EG2D_ERR_MEMORY;
    else if (!(rc = spaced(ni_up, -4.0, 0.0, 0.5, h, xu)) && !(rc = spaced(ni_down, 0.0, 20.0, h, 1.0, xd)) &&
             !(rc = spaced(nj_upper, 1.0, 9.0, mid, h, yu)) && !(rc = spaced(nj_lower, 0.0, 1.0, h, mid, yl)) &&
             !(rc = tensor_block(ni_up, nj_upper, xu, yu, &grids[0])) &&
             !(rc = tensor_block(ni_down, nj_upper, xd, yu, &grids[1])) &&
             !(rc = tensor_block(ni_down, nj_lower, xd, yl, &grids[2])) && !(rc = eg2d_blocks_create(set))) {
        for (int k = 0; !rc && k < 3; ++k) rc = eg2d_blocks_add(*set, grids[k], &b);
        if (!rc) rc = eg2d_blocks_join(*set, 0, EG2D_SIDE_IMAX, 0, nj_upper - 1, 1, EG2D_SIDE_IMIN, 0, nj_upper - 1);
        if (!rc) rc = eg2d_blocks_join(*set, 1, EG2D_SIDE_JMIN, 0, ni_down - 1, 2, EG2D_SIDE_JMAX, 0, ni_down - 1);
        const struct { int block, side; } walls[] = {{0, EG2D_SIDE_JMIN}, {0, EG2D_SIDE_JMAX}, {1, EG2D_SIDE_JMAX},
                                                     {2, EG2D_SIDE_JMIN}, {2, EG2D_SIDE_IMIN}};
        for (int k = 0; !rc && h > 0.0 && k < 5; ++k) rc = eg2d_set_wall_spacing(grids[walls[k].block], walls[k].side, h);
        for (int k = 0; !rc && k < 3; ++k) rc = eg2d_set_system(grids[k], EG2D_SYSTEM_WINSLOW);
    }
    free(xu);
    free(xd);
    free(yu);
    free(yl);
    return rc;
}
