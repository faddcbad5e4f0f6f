/* Writes small grids of each topology in the solver-ready formats, for
 * solver_formats.py to check with readers eg2d did not write (meshio,
 * OpenFOAM's checkMesh, cgnscheck). Usage: write_solver_samples DIR [no-cgns].
 * Grids (NAME): "c", the NACA 0012 C-grid 65 x 17 with a wake of 16 points
 * (default patches); "o", the NACA 0012 O-grid 65 x 17 (default patches);
 * "single", the elliptic-grid course notes' valley 21 x 13 with the user's patches: JMIN
 * "bottom" wall, IMIN "inlet" inflow, IMAX "outlet" outflow, JMAX nodes
 * 0..10 "top" symmetry and 10..20 "lid" wall.
 * For each, with a span of 0.5: DIR/NAME.su2, DIR/NAME.cgns, the OpenFOAM
 * case DIR/NAME_foam, the one-cell-thick ASCII Plot3D DIR/NAME.p3d, the
 * reports DIR/NAME.report.txt and DIR/NAME.report.json,
 * and DIR/NAME.txt: "ni nj topology wake" (wake: the C-grid's trailing-edge
 * index, else 0), for the script's own counts. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "domains.h"
#include "eg2d.h"

static void check(int status, eg2d_grid *g, const char *what) {
    if (status != EG2D_OK) {
        fprintf(stderr, "%s: %s\n", what, eg2d_last_error(g));
        exit(1);
    }
}

static void write_as(eg2d_grid *g, const char *dir, const char *name, const char *suffix, int format) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s%s", dir, name, suffix);
    check(eg2d_write(g, path, format), g, path);
}

static void solve(eg2d_grid *g) {
    int rc;
    check(eg2d_set_tolerance(g, 1e-7), g, "tolerance");
    check(eg2d_set_max_iterations(g, 400), g, "max iterations");
    rc = eg2d_solve(g);
    /* A few hundred cycles are plenty for a file test: an unconverged but
     * unfolded grid is as good a sample as a converged one. */
    if (rc != EG2D_OK && rc != EG2D_ERR_NOT_CONVERGED) check(rc, g, "eg2d_solve");
}

int main(int argc, char **argv) {
    const char *names[3] = {"c", "o", "single"};
    int k, with_cgns = !(argc == 3 && !strcmp(argv[2], "no-cgns"));
    if (argc != 2 && with_cgns) {
        fprintf(stderr, "usage: write_solver_samples DIR [no-cgns]\n");
        return 2;
    }
    for (k = 0; k < 3; ++k) {
        eg2d_grid *g;
        int ni = k == 2 ? 21 : 65, nj = k == 2 ? 13 : 17, wake = 0;
        char path[4096];
        FILE *f;
        check(eg2d_create(ni, nj, &g), NULL, "eg2d_create");
        if (k == 0) {
            wake = 16;
            check(domain_set_airfoil_c(g, "0012", wake, 10), g, "C-grid");
        } else if (k == 1) {
            check(domain_set_airfoil_o(g, "0012", 10), g, "O-grid");
        } else {
            check(domain_set(g, "valley"), g, "valley");
            check(eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, ni - 1, EG2D_PATCH_WALL, "bottom"), g, "patch");
            check(eg2d_set_patch(g, EG2D_SIDE_IMIN, 0, nj - 1, EG2D_PATCH_INFLOW, "inlet"), g, "patch");
            check(eg2d_set_patch(g, EG2D_SIDE_IMAX, 0, nj - 1, EG2D_PATCH_OUTFLOW, "outlet"), g, "patch");
            check(eg2d_set_patch(g, EG2D_SIDE_JMAX, 0, 10, EG2D_PATCH_SYMMETRY, "top"), g, "patch");
            check(eg2d_set_patch(g, EG2D_SIDE_JMAX, 10, ni - 1, EG2D_PATCH_WALL, "lid"), g, "patch");
        }
        solve(g);
        check(eg2d_set_parameter(g, EG2D_PARAM_SPAN, 0.5), g, "span");
        write_as(g, argv[1], names[k], ".su2", EG2D_FORMAT_SU2);
        write_as(g, argv[1], names[k], ".p3d", EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_EXTRUDED);
        write_as(g, argv[1], names[k], ".report.txt", EG2D_FORMAT_REPORT);
        write_as(g, argv[1], names[k], ".report.json", EG2D_FORMAT_REPORT_JSON);
        write_as(g, argv[1], names[k], "_foam", EG2D_FORMAT_OPENFOAM);
        if (with_cgns) write_as(g, argv[1], names[k], ".cgns", EG2D_FORMAT_CGNS);
        snprintf(path, sizeof path, "%s/%s.txt", argv[1], names[k]);
        if (!(f = fopen(path, "w"))) return 1;
        fprintf(f, "%d %d %d %d\n", ni, nj, k == 0 ? EG2D_TOPO_C : k == 1 ? EG2D_TOPO_O : EG2D_TOPO_SINGLE, wake);
        fclose(f);
        eg2d_destroy(g);
    }
    return 0;
}
