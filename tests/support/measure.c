#include "measure.h"

#include <math.h>

#include "eg2d.h"

#define MEASURE_PI 3.14159265358979323846

double measure_distance(const double *x, const double *y, int ni, int i0, int j0, int i1, int j1) {
    const int a = i0 + ni * j0, b = i1 + ni * j1;
    return hypot(x[b] - x[a], y[b] - y[a]);
}

/* Array index of wall node k at depth m from `side`. */
static int node(int ni, int nj, int side, int k, int m) {
    switch (side) {
    case EG2D_SIDE_JMIN: return k + ni * m;
    case EG2D_SIDE_JMAX: return k + ni * (nj - 1 - m);
    case EG2D_SIDE_IMIN: return m + ni * k;
    default: return ni - 1 - m + ni * k;
    }
}

void measure_wall(const double *x, const double *y, int ni, int nj, int side, int periodic, int k_begin, int k_end,
                  double *max_dev, double *min_h, double *max_h) {
    const int n = (side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX) ? ni : nj;
    int k;
    *max_dev = 0.0;
    *min_h = HUGE_VAL;
    *max_h = 0.0;
    for (k = k_begin; k < k_end; ++k) {
        int kp = k + 1, km = k - 1, a, b, w, c;
        double tx, ty, dx, dy, h, cs, dev;
        if (periodic) {
            if (km < 0) km = n - 2;
            if (kp > n - 1) kp = 1;
        }
        a = node(ni, nj, side, km, 0);
        b = node(ni, nj, side, kp, 0);
        w = node(ni, nj, side, k, 0);
        c = node(ni, nj, side, k, 1);
        tx = x[b] - x[a];
        ty = y[b] - y[a];
        dx = x[c] - x[w];
        dy = y[c] - y[w];
        h = hypot(dx, dy);
        cs = (tx * dx + ty * dy) / (hypot(tx, ty) * h);
        dev = fabs(acos(cs) * 180.0 / MEASURE_PI - 90.0);
        if (dev > *max_dev) *max_dev = dev;
        if (h < *min_h) *min_h = h;
        if (h > *max_h) *max_h = h;
    }
}

void measure_angles(const double *x, const double *y, int ni, int nj, int single_block, double *mean,
                    double *largest, double *area_ratio) {
    double total = 0.0, sum = 0.0, amin = HUGE_VAL, amax = 0.0;
    long count = 0;
    int i, j, m, o;
    *largest = 0.0;
    for (j = 0; j + 1 < nj; ++j)
        for (i = 0; i + 1 < ni; ++i) {
            const int k = i + ni * j, c[4] = {k, k + 1, k + 1 + ni, k + ni};
            total += (x[c[2]] - x[c[0]]) * (y[c[3]] - y[c[1]]) - (y[c[2]] - y[c[0]]) * (x[c[3]] - x[c[1]]);
        }
    o = total < 0 ? -1 : 1;
    for (j = 0; j + 1 < nj; ++j)
        for (i = 0; i + 1 < ni; ++i) {
            const int k = i + ni * j, c[4] = {k, k + 1, k + 1 + ni, k + ni};
            const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
            const double area =
                0.5 * o * ((x[c[2]] - x[c[0]]) * (y[c[3]] - y[c[1]]) - (y[c[2]] - y[c[0]]) * (x[c[3]] - x[c[1]]));
            amin = fmin(amin, area);
            amax = fmax(amax, area);
            for (m = 0; m < 4; ++m) {
                const int n = c[(m + 1) % 4], p = c[(m + 3) % 4];
                const double ax = x[n] - x[c[m]], ay = y[n] - y[c[m]], bx = x[p] - x[c[m]], by = y[p] - y[c[m]];
                double d;
                if (single_block && (ci[m] == 0 || ci[m] == ni - 1) && (cj[m] == 0 || cj[m] == nj - 1)) continue;
                d = fabs(atan2(o * (ax * by - ay * bx), ax * bx + ay * by) * 180.0 / MEASURE_PI - 90.0);
                sum += d;
                ++count;
                *largest = fmax(*largest, d);
            }
        }
    *mean = count ? sum / count : 0.0;
    *area_ratio = amin > 0.0 ? amax / amin : HUGE_VAL;
}
