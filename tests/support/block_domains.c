#include "block_domains.h"

#include <math.h>
#include <stdlib.h>

static double tanh_cluster(double s, double beta) { return 1.0 + tanh(beta * (s - 1.0)) / tanh(beta); }
static double both_ends(double s, double beta) {
    return s <= 0.5 ? 0.5 * tanh_cluster(2.0 * s, beta) : 1.0 - 0.5 * tanh_cluster(2.0 * (1.0 - s), beta);
}

int block_rectangle(int ni, int nj, double x0, double x1, double y0, double y1, int cluster_x, int cluster_y,
                    eg2d_grid **grid) {
    int rc = eg2d_create(ni, nj, grid);
    if (rc) return rc;
    double *x = calloc((size_t)ni * (size_t)nj, sizeof(double)), *y = calloc((size_t)ni * (size_t)nj, sizeof(double));
    if (!x || !y) rc = EG2D_ERR_MEMORY;
    for (int j = 0; !rc && j < nj; ++j)
        for (int i = 0; i < ni; ++i) {
            const double s = (double)i / (ni - 1), t = (double)j / (nj - 1);
            const double sx = cluster_x > 0 ? tanh_cluster(s, 2.0) : cluster_x < 0 ? 1.0 - tanh_cluster(1.0 - s, 2.0) : s;
            const double ty = cluster_y ? both_ends(t, 2.5) : t;
            x[i + ni * j] = x0 + (x1 - x0) * sx;
            y[i + ni * j] = y0 + (y1 - y0) * ty;
        }
    if (!rc) rc = eg2d_set_boundary(*grid, x, y);
    free(x);
    free(y);
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
