/* `eg2d airfoil`'s grid from a program: the NACA 0012 C-grid at y+ 1 for a
 * chord Reynolds number of 6e6, the wall resolved by the library's graded
 * hybrid layer, written as Plot3D. Node for node the file the command writes
 * (tests/examples_match_command.sh compares them at 385x97 and 1793x513):
 *   eg2d airfoil 0012 --size NIxNJ --yplus 1 --reynolds 6e6 --format plot3d
 * Usage: command_grid NI NJ FILE.xyz
 * Build: cc command_grid.c $(pkg-config --cflags --libs eg2d) -lm -o command_grid */
#include <eg2d.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: command_grid NI NJ FILE.xyz\n");
        return 2;
    }
    const int ni = atoi(argv[1]), nj = atoi(argv[2]);
    /* The first cell from y+ by the turbulent flat plate's skin friction,
     * Cf = (2 log10(Re) - 0.65)^-2.3 (Schlichting 1979), as the command. */
    const double re = 6e6, cf = pow(2 * log10(re) - 0.65, -2.3), h = 1.0 / (re * sqrt(cf / 2));
    eg2d_curve *section = NULL;
    eg2d_grid *g = NULL;
    if (eg2d_curve_naca4("0012", 0, &section) != EG2D_OK || eg2d_create(ni, nj, &g) != EG2D_OK) {
        fprintf(stderr, "%s\n", eg2d_last_error(NULL));
        return 1;
    }
    /* The section (with an airfoil grid's run: its tolerance and cycle) and
     * the wall's first cell (the wall control comes with it): the command's
     * grid. */
    int status = eg2d_set_airfoil(g, section, EG2D_TOPO_C);
    if (!status) status = eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h);
    if (!status) status = eg2d_solve(g);
    if (!status) status = eg2d_write(g, argv[3], EG2D_FORMAT_PLOT3D);
    if (status) {
        fprintf(stderr, "%s\n", eg2d_last_error(g));
        return 1;
    }
    int cut = 0, iterations = 0;
    eg2d_get_cut(g, &cut);
    eg2d_get_iterations(g, &iterations);
    printf("NACA 0012 C-grid %dx%d, first cell %.4g chords, %d cut nodes a side: %d cycles, written to %s\n", ni, nj,
           h, cut, iterations, argv[3]);
    eg2d_destroy(g);
    eg2d_curve_destroy(section);
    return 0;
}
