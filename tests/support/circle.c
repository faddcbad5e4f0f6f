#include "circle.h"

#include <math.h>
#include <stdlib.h>

#define CIRCLE_PI 3.14159265358979323846

int domain_set_circle(eg2d_grid *g) {
    int ni, nj, n, k, side, status;
    double *x, *y;
    if ((status = eg2d_get_size(g, &ni, &nj)) != EG2D_OK) return status;
    n = ni > nj ? ni : nj;
    x = malloc(sizeof(double) * (size_t)n);
    y = malloc(sizeof(double) * (size_t)n);
    if (!x || !y) {
        free(x);
        free(y);
        return EG2D_ERR_MEMORY;
    }
    for (side = 0; side < 4 && status == EG2D_OK; ++side) {
        const int m = (side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX) ? ni : nj;
        for (k = 0; k < m; ++k) {
            const double s = (double)k / (m - 1);
            double theta;
            switch (side) {
            case EG2D_SIDE_JMIN: theta = CIRCLE_PI / 2 * s; break;
            case EG2D_SIDE_IMAX: theta = CIRCLE_PI / 2 + CIRCLE_PI / 2 * s; break;
            case EG2D_SIDE_JMAX: theta = CIRCLE_PI + CIRCLE_PI / 2 * (1.0 - s); break;
            default: theta = 1.5 * CIRCLE_PI + CIRCLE_PI / 2 * (1.0 - s); break;
            }
            x[k] = cos(theta);
            y[k] = sin(theta);
        }
        status = eg2d_set_side(g, side, x, y);
    }
    free(x);
    free(y);
    return status;
}
