/* TMR's plot3d 2-D grid (ASCII: nblocks, ni nj, then x then y, i fastest)
 * to an OpenFOAM case through libeg2d's writer, with the patches of
 * flat_plate.toml, so that both meshes of run.sh come from the same writer.
 *
 *     p2d_to_foam GRID.p2d CASE_DIR
 */
#include <eg2d.h>
#include <stdio.h>
#include <stdlib.h>

static int check(int status, eg2d_grid *g, const char *what)
{
    if (status != EG2D_OK) {
        fprintf(stderr, "p2d_to_foam: %s: %s: %s\n", what, eg2d_status_string(status), eg2d_last_error(g));
        exit(1);
    }
    return status;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: p2d_to_foam GRID.p2d CASE_DIR\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "r");
    if (!f) {
        perror(argv[1]);
        return 1;
    }
    int nb, ni, nj;
    if (fscanf(f, "%d %d %d", &nb, &ni, &nj) != 3 || nb != 1 || ni < 3 || nj < 3) {
        fprintf(stderr, "p2d_to_foam: %s: expected one 2-D block\n", argv[1]);
        return 1;
    }
    size_t n = (size_t)ni * (size_t)nj;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    if (!x || !y)
        return 1;
    for (size_t k = 0; k < n; k++)
        if (fscanf(f, "%lf", &x[k]) != 1) {
            fprintf(stderr, "p2d_to_foam: %s: short x\n", argv[1]);
            return 1;
        }
    for (size_t k = 0; k < n; k++)
        if (fscanf(f, "%lf", &y[k]) != 1) {
            fprintf(stderr, "p2d_to_foam: %s: short y\n", argv[1]);
            return 1;
        }
    fclose(f);

    /* the leading edge: the JMIN node at x = 0 */
    int le = -1;
    for (int i = 0; i < ni; i++)
        if (x[i] == 0.0)
            le = i;
    if (le <= 0 || le >= ni - 1) {
        fprintf(stderr, "p2d_to_foam: %s: no JMIN node at x = 0\n", argv[1]);
        return 1;
    }

    eg2d_grid *g = NULL;
    check(eg2d_create(ni, nj, &g), NULL, "eg2d_create");
    check(eg2d_set_coordinates(g, x, y), g, "eg2d_set_coordinates");
    check(eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, le, EG2D_PATCH_SYMMETRY, "symmetry"), g, "eg2d_set_patch");
    check(eg2d_set_patch(g, EG2D_SIDE_JMIN, le, ni - 1, EG2D_PATCH_WALL, "plate"), g, "eg2d_set_patch");
    check(eg2d_set_patch(g, EG2D_SIDE_IMIN, 0, nj - 1, EG2D_PATCH_INFLOW, "inflow"), g, "eg2d_set_patch");
    check(eg2d_set_patch(g, EG2D_SIDE_IMAX, 0, nj - 1, EG2D_PATCH_OUTFLOW, "outflow"), g, "eg2d_set_patch");
    check(eg2d_set_patch(g, EG2D_SIDE_JMAX, 0, ni - 1, EG2D_PATCH_FARFIELD, "top"), g, "eg2d_set_patch");
    check(eg2d_write(g, argv[2], EG2D_FORMAT_OPENFOAM), g, "eg2d_write");
    printf("p2d_to_foam: %s: %dx%d, leading edge at JMIN node %d -> %s\n", argv[1], ni, nj, le, argv[2]);
    eg2d_destroy(g);
    free(x);
    free(y);
    return 0;
}
