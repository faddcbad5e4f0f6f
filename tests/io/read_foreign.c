/* Reads the Plot3D files plot3d_fortran wrote (with gfortran's own I/O) via
 * eg2d_read_plot3d: the variant detected, the size, the coordinates against
 * the formula, and the grid as a start grid for eg2d_set_coordinates.
 * Usage: read_foreign DIR. Prints one line per file; exit 0 if all agree. */
#include <math.h>
#include <stdio.h>

#include "eg2d.h"

#define NI 7
#define NJ 5

int main(int argc, char **argv) {
    static const struct { const char *name; int format; double tol; } files[] = {
        {"f_2d.x", EG2D_FORMAT_PLOT3D, 0},
        {"f_3d_multi.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI, 0},
        {"f_2d_single.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_SINGLE, 1e-6},
        {"f_3d_ascii.x", EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_3D, 1e-15},
        {"f_3d_stream.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_NO_MARKERS, 0},
    };
    double x[NI * NJ], y[NI * NJ];
    int f, bad = 0;
    if (argc != 2) return 2;
    for (f = 0; f < (int)(sizeof files / sizeof files[0]); ++f) {
        char path[2048];
        int format = -1, nblocks = -1, ni = -1, nj = -1, i, j, status;
        double err = 0;
        eg2d_grid *g;
        snprintf(path, sizeof path, "%s/%s", argv[1], files[f].name);
        status = eg2d_read_plot3d(path, 0, &format, &nblocks, &ni, &nj, x, y);
        if (status != EG2D_OK) {
            printf("FAIL %s: %s\n", files[f].name, eg2d_last_error(NULL));
            bad = 1;
            continue;
        }
        for (j = 0; j < NJ; ++j)
            for (i = 0; i < NI; ++i) {
                const double xe = (i + 1) + 0.25 * (j + 1), ye = 0.5 * (j + 1) + 0.01 * (i + 1) * (i + 1);
                const double e = fmax(fabs(x[i + NI * j] - xe), fabs(y[i + NI * j] - ye)) / fmax(1, fabs(xe));
                err = e > err ? e : err;
            }
        status = eg2d_create(ni, nj, &g) || eg2d_set_coordinates(g, x, y);
        eg2d_destroy(g);
        if (format != files[f].format || nblocks != 1 || ni != NI || nj != NJ || err > files[f].tol || status) {
            printf("FAIL %s: format %#x (want %#x), %d block(s), %d x %d, error %.2e, start grid %d\n", files[f].name,
                   format, files[f].format, nblocks, ni, nj, err, status);
            bad = 1;
        } else {
            printf("ok   %s: format %#x, %d x %d, max relative error %.2e, accepted as a start grid\n", files[f].name,
                   format, ni, nj, err);
        }
    }
    return bad;
}
