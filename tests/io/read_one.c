/* Reads one file with one of eg2d's readers, the way a caller does, and
 * prints the outcome: "EG2D_OK ..." or the status string and eg2d_last_error.
 * bounded_memory.py runs it under `ulimit -v` on files whose headers claim
 * far more than they hold.
 * Usage: read_one plot3d|points|side|airfoil PATH. Exit 0 unless it crashes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eg2d.h"

static int report(int status, const eg2d_grid *g) {
    if (status == EG2D_OK) printf("EG2D_OK\n");
    else printf("%.*s: %s\n", (int)strcspn(eg2d_status_string(status), ":"), eg2d_status_string(status),
                eg2d_last_error(g));
    return 0;
}

int main(int argc, char **argv) {
    const char *kind, *path;
    if (argc != 3) return 2;
    kind = argv[1];
    path = argv[2];
    if (strcmp(kind, "plot3d") == 0) { /* the size, then the block into arrays of that size */
        int ni = 0, nj = 0, status = eg2d_read_plot3d_into(path, 0, 0, NULL, NULL, &ni, &nj, NULL, NULL);
        double *x, *y;
        if (status != EG2D_OK) return report(status, NULL);
        x = malloc(sizeof(double) * (size_t)ni * (size_t)nj);
        y = malloc(sizeof(double) * (size_t)ni * (size_t)nj);
        status = eg2d_read_plot3d_into(path, 0, ni * nj, NULL, NULL, NULL, NULL, x, y);
        free(x);
        free(y);
        return report(status, NULL);
    }
    if (strcmp(kind, "points") == 0) {
        int n = 0;
        return report(eg2d_read_points(path, 0, &n, NULL, NULL), NULL);
    }
    if (strcmp(kind, "side") == 0) {
        eg2d_grid *g = NULL;
        int status = eg2d_create(9, 9, &g);
        if (status == EG2D_OK) status = eg2d_set_side_from_file(g, EG2D_SIDE_JMIN, path);
        report(status, g);
        eg2d_destroy(g);
        return 0;
    }
    if (strcmp(kind, "airfoil") == 0) {
        eg2d_curve *c = NULL;
        const int status = eg2d_curve_read_airfoil(path, &c);
        eg2d_curve_destroy(c);
        return report(status, NULL);
    }
    return 2;
}
