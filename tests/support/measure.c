#include "measure.h"

#include <math.h>

#define MEASURE_PI 3.14159265358979323846

double measure_distance(const double *x, const double *y, int ni, int i0, int j0, int i1, int j1) {
    const int a = i0 + ni * j0, b = i1 + ni * j1;
    return hypot(x[b] - x[a], y[b] - y[a]);
}

void measure_wall_jmin(const double *x, const double *y, int ni, int periodic, int i_begin, int i_end,
                       double *max_dev, double *min_h, double *max_h) {
    int i;
    *max_dev = 0.0;
    *min_h = HUGE_VAL;
    *max_h = 0.0;
    for (i = i_begin; i < i_end; ++i) {
        int ip = i + 1, im = i - 1;
        double tx, ty, dx, dy, h, c, dev;
        if (periodic) {
            if (im < 0) im = ni - 2;
            if (ip > ni - 1) ip = 1;
        }
        tx = x[ip] - x[im];
        ty = y[ip] - y[im];
        dx = x[i + ni] - x[i];
        dy = y[i + ni] - y[i];
        h = hypot(dx, dy);
        c = (tx * dx + ty * dy) / (hypot(tx, ty) * h);
        dev = fabs(acos(c) * 180.0 / MEASURE_PI - 90.0);
        if (dev > *max_dev) *max_dev = dev;
        if (h < *min_h) *min_h = h;
        if (h > *max_h) *max_h = h;
    }
}
