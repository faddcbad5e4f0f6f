/* Writes a converged test grid in every format eg2d has, for readback.py to
 * read back with readers eg2d did not write (VTK, cgnscheck, Python's xml).
 * Usage: write_samples DIR [no-cgns]. Also writes DIR/reference.txt: "ni nj" and then
 * one "x y" line per node in Fortran order, printed here with %.17g (not by
 * an eg2d writer), and DIR/quality.txt: one line per per-cell metric, its
 * name and its (ni-1)*(nj-1) values from eg2d_get_cell_quality. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "domains.h"
#include "eg2d.h"

#define NI 21
#define NJ 13

static void check(int status, eg2d_grid *g, const char *what) {
    if (status != EG2D_OK) {
        fprintf(stderr, "%s: %s\n", what, eg2d_last_error(g));
        exit(1);
    }
}

static void write_as(eg2d_grid *g, const char *dir, const char *name, int format) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    check(eg2d_write(g, path, format), g, path);
}

int main(int argc, char **argv) {
    static const struct { const char *name; int format; } files[] = {
        {"grid.x", EG2D_FORMAT_PLOT3D},
        {"grid_3d.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D},
        {"grid_multi.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_MULTI},
        {"grid_3d_multi.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI},
        {"grid_be.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_BIG_ENDIAN},
        {"grid_3d_multi_be.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI | EG2D_PLOT3D_BIG_ENDIAN},
        {"grid_single.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_SINGLE},
        {"grid_stream.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_NO_MARKERS},
        {"grid_ascii.x", EG2D_FORMAT_PLOT3D_ASCII},
        {"grid_ascii_3d.x", EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_3D},
        {"grid_ascii_multi.x", EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_MULTI},
        {"grid_ascii_3d_multi.x", EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI},
        {"grid.vts", EG2D_FORMAT_VTS},
        {"grid.cgns", EG2D_FORMAT_CGNS},
        {"grid.gmv", EG2D_FORMAT_GMV},
        {"grid.m", EG2D_FORMAT_MATLAB},
        {"grid.svg", EG2D_FORMAT_SVG},
    };
    eg2d_grid *g;
    double x[NI * NJ], y[NI * NJ], q[(NI - 1) * (NJ - 1)];
    char path[4096];
    FILE *f;
    size_t k;
    int m, count, metric;
    const char *field, *written = "";
    if (argc != 2 && !(argc == 3 && !strcmp(argv[2], "no-cgns"))) {
        fprintf(stderr, "usage: write_samples DIR [no-cgns]\n");
        return 2;
    }
    check(eg2d_create(NI, NJ, &g), NULL, "eg2d_create");
    check(domain_set(g, "valley"), g, "domain_set");
    check(eg2d_set_tolerance(g, 1e-10), g, "tolerance");
    check(eg2d_solve(g), g, "eg2d_solve");
    for (k = 0; k < sizeof files / sizeof files[0]; ++k) {
        if (argc == 3 && files[k].format == EG2D_FORMAT_CGNS) continue;
        /* The SVG is coloured by skewness; the other files do not look at it. */
        check(eg2d_set_parameter(g, EG2D_PARAM_SVG_QUALITY, EG2D_QUALITY_SKEWNESS), g, "svg_quality");
        write_as(g, argv[1], files[k].name, files[k].format);
    }
    check(eg2d_set_parameter(g, EG2D_PARAM_SVG_QUALITY, -1), g, "svg_quality");
    write_as(g, argv[1], "grid_plain.svg", EG2D_FORMAT_SVG);
    check(eg2d_get_coordinates(g, x, y), g, "coordinates");
    snprintf(path, sizeof path, "%s/reference.txt", argv[1]);
    if (!(f = fopen(path, "w"))) return 1;
    fprintf(f, "%d %d\n", NI, NJ);
    for (k = 0; k < NI * NJ; ++k) fprintf(f, "%.17g %.17g\n", x[k], y[k]);
    fclose(f);
    snprintf(path, sizeof path, "%s/quality.txt", argv[1]);
    if (!(f = fopen(path, "w"))) return 1;
    /* Every per-cell field of the library's quality list, once (MIN_AREA and
       MAX_AREA share "area"), by its field name: what .vts and .gmv carry. */
    check(eg2d_list_count(EG2D_LIST_QUALITY, &count), NULL, "list count");
    for (m = 0; m < count; ++m) {
        check(eg2d_list_entry(EG2D_LIST_QUALITY, m, &metric, NULL), NULL, "list entry");
        if (!(field = eg2d_quality_cell_field(metric)) || !strcmp(field, written)) continue;
        written = field;
        check(eg2d_get_cell_quality(g, metric, q), g, "cell quality");
        fprintf(f, "%s", field);
        for (k = 0; k < (NI - 1) * (NJ - 1); ++k) fprintf(f, " %.17g", q[k]);
        fprintf(f, "\n");
    }
    fclose(f);
    eg2d_destroy(g);
    return 0;
}
