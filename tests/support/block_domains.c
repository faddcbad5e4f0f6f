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
