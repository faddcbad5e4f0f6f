#include "airfoil.h"

#include <math.h>
#include <stdlib.h>

#define AIRFOIL_PI 3.14159265358979323846

void airfoil_naca4_point(const char *digits, double theta, double *px, double *py) {
    const double m = (digits[0] - '0') / 100.0, p = (digits[1] - '0') / 10.0;
    const double t = ((digits[2] - '0') * 10 + (digits[3] - '0')) / 100.0;
    const double x = 0.5 * (1.0 + cos(theta));
    const int upper = sin(theta) >= 0.0;
    /* Thickness (standard formula, closed trailing edge). */
    const double yt = 5.0 * t *
                      (0.2969 * sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
    double yc = 0.0, dyc = 0.0, th;
    if (m > 0.0 && p > 0.0) {
        if (x < p) {
            yc = m / (p * p) * (2 * p * x - x * x);
            dyc = 2 * m / (p * p) * (p - x);
        } else {
            yc = m / ((1 - p) * (1 - p)) * ((1 - 2 * p) + 2 * p * x - x * x);
            dyc = 2 * m / ((1 - p) * (1 - p)) * (p - x);
        }
    }
    th = atan(dyc);
    if (upper) {
        *px = x - yt * sin(th);
        *py = yc + yt * cos(th);
    } else {
        *px = x + yt * sin(th);
        *py = yc - yt * cos(th);
    }
}

int airfoil_set_naca4_ogrid(eg2d_grid *g, const char *digits, double r_outer) {
    int ni, nj, i, status;
    double *x, *y;
    if ((status = eg2d_get_size(g, &ni, &nj)) != EG2D_OK) return status;
    if ((status = eg2d_set_topology(g, EG2D_TOPO_O)) != EG2D_OK) return status;
    x = malloc(sizeof(double) * (size_t)ni);
    y = malloc(sizeof(double) * (size_t)ni);
    if (!x || !y) {
        free(x);
        free(y);
        return EG2D_ERR_MEMORY;
    }
    for (i = 0; i < ni; ++i) airfoil_naca4_point(digits, 2.0 * AIRFOIL_PI * i / (ni - 1), &x[i], &y[i]);
    x[ni - 1] = x[0];
    y[ni - 1] = y[0];
    status = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    for (i = 0; i < ni && status == EG2D_OK; ++i) {
        const double a = 2.0 * AIRFOIL_PI * i / (ni - 1);
        x[i] = 0.5 + r_outer * cos(a);
        y[i] = r_outer * sin(a);
    }
    x[ni - 1] = x[0];
    y[ni - 1] = y[0];
    if (status == EG2D_OK) status = eg2d_set_side(g, EG2D_SIDE_JMAX, x, y);
    free(x);
    free(y);
    return status;
}
