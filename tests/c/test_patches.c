/* Boundary patches: the defaults of each topology, the user's stretches
 * completing to a cover of the boundary, the checks of eg2d_set_patch, and
 * what a C-grid's wake cut allows. The writers that use them are checked by
 * readers eg2d did not write (tests/io/solver_formats.py). */
#define _GNU_SOURCE
#include <dirent.h>
#include <ftw.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

typedef struct {
    int side, first, last, type;
    const char *name;
} expected;

/* The grid's resolved patches are exactly `n` rows of `want`. */
static void assert_patches(eg2d_grid *g, const expected *want, int n) {
    int count = -1, k;
    assert_int_equal(eg2d_get_patch_count(g, &count), EG2D_OK);
    assert_int_equal(count, n);
    for (k = 0; k < n; ++k) {
        int side, first, last, type;
        char name[40];
        assert_int_equal(eg2d_get_patch(g, k, &side, &first, &last, &type, name, sizeof name), EG2D_OK);
        if (side != want[k].side || first != want[k].first || last != want[k].last || type != want[k].type ||
            strcmp(name, want[k].name))
            fail_msg("patch %d: side %d [%d, %d] type %d \"%s\", expected side %d [%d, %d] type %d \"%s\"", k, side,
                     first, last, type, name, want[k].side, want[k].first, want[k].last, want[k].type, want[k].name);
    }
}

static void test_single_block(void **state) {
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_create(9, 7, &g), EG2D_OK);
    {
        const expected d[] = {{EG2D_SIDE_JMIN, 0, 8, EG2D_PATCH_WALL, "jmin"},
                              {EG2D_SIDE_IMAX, 0, 6, EG2D_PATCH_WALL, "imax"},
                              {EG2D_SIDE_JMAX, 0, 8, EG2D_PATCH_WALL, "jmax"},
                              {EG2D_SIDE_IMIN, 0, 6, EG2D_PATCH_WALL, "imin"}};
        assert_patches(g, d, 4);
    }
    /* A stretch of JMIN splits its default; IMIN and IMAX whole. */
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMIN, 2, 5, EG2D_PATCH_SYMMETRY, "axis"), EG2D_OK);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_IMIN, 0, 6, EG2D_PATCH_INFLOW, "inlet"), EG2D_OK);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_IMAX, 0, 6, EG2D_PATCH_OUTFLOW, "outlet"), EG2D_OK);
    {
        const expected d[] = {{EG2D_SIDE_JMIN, 0, 2, EG2D_PATCH_WALL, "jmin"},
                              {EG2D_SIDE_JMIN, 2, 5, EG2D_PATCH_SYMMETRY, "axis"},
                              {EG2D_SIDE_JMIN, 5, 8, EG2D_PATCH_WALL, "jmin"},
                              {EG2D_SIDE_IMAX, 0, 6, EG2D_PATCH_OUTFLOW, "outlet"},
                              {EG2D_SIDE_JMAX, 0, 8, EG2D_PATCH_WALL, "jmax"},
                              {EG2D_SIDE_IMIN, 0, 6, EG2D_PATCH_INFLOW, "inlet"}};
        assert_patches(g, d, 6);
    }
    /* The same range replaces; one name on two stretches needs one type. */
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMIN, 2, 5, EG2D_PATCH_WALL, "plate"), EG2D_OK);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 2, 5, EG2D_PATCH_WALL, "plate"), EG2D_OK);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 6, 8, EG2D_PATCH_FARFIELD, "plate"), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(g), "already used with type wall"));
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 6, 8, EG2D_PATCH_FARFIELD, "abcdefghijabcdefghijabcdefghijabc"),
                     EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(g), "must have 1 to 32 characters, has 33"));
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 6, 8, EG2D_PATCH_FARFIELD, "2nd"), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 6, 8, EG2D_PATCH_FARFIELD, "frontAndBack"), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 6, 8, -1, "x"), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 5, 5, EG2D_PATCH_WALL, "x"), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_patch(g, 4, 0, 1, EG2D_PATCH_WALL, "x"), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 0, 1, EG2D_PATCH_WALL, NULL), EG2D_ERR_ARGUMENT);
    {
        int count = 0;
        char name[3];
        assert_int_equal(eg2d_get_patch_count(g, &count), EG2D_OK);
        assert_int_equal(count, 8); /* the failed calls changed nothing */
        /* A short buffer gets the name cut short; NULL outputs are allowed. */
        assert_int_equal(eg2d_get_patch(g, 1, NULL, NULL, NULL, NULL, name, sizeof name), EG2D_OK);
        assert_string_equal(name, "pl");
        assert_int_equal(eg2d_get_patch(g, 8, NULL, NULL, NULL, NULL, NULL, 0), EG2D_ERR_ARGUMENT);
        assert_int_equal(eg2d_get_patch(g, 0, NULL, NULL, NULL, NULL, NULL, 5), EG2D_ERR_ARGUMENT);
    }
    assert_int_equal(eg2d_clear_patches(g), EG2D_OK);
    {
        int count = 0;
        assert_int_equal(eg2d_get_patch_count(g, &count), EG2D_OK);
        assert_int_equal(count, 4);
    }
    /* A new topology forgets the patches. */
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 0, 8, EG2D_PATCH_FARFIELD, "far"), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_O), EG2D_OK);
    {
        const expected d[] = {{EG2D_SIDE_JMIN, 0, 8, EG2D_PATCH_WALL, "wall"},
                              {EG2D_SIDE_JMAX, 0, 8, EG2D_PATCH_FARFIELD, "farfield"},
                              {EG2D_SIDE_IMIN, 0, 6, EG2D_PATCH_CUT, "cut"}};
        assert_patches(g, d, 3);
    }
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_IMAX, 0, 6, EG2D_PATCH_WALL, "x"), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
}

/* A NACA 0012 C-grid 65 x 17 (wake 16) whose patch "early" covers JMIN
 * nodes 0..30, set before JMIN: domain_set_airfoil_c sets the topology,
 * which forgets patches, so the points come from a first grid and go in
 * with eg2d_set_coordinates (with_interior) or as JMIN alone. */
static eg2d_grid *c_grid_with_early_patch(int with_interior) {
    static double x[65 * 17], y[65 * 17];
    eg2d_grid *h, *g;
    assert_int_equal(eg2d_create(65, 17, &h), EG2D_OK);
    assert_int_equal(domain_set_airfoil_c(h, "0012", 16, 10), EG2D_OK);
    assert_int_equal(eg2d_initialize(h, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(h, x, y), EG2D_OK);
    eg2d_destroy(h);
    assert_int_equal(eg2d_create(65, 17, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_C), EG2D_OK);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, 30, EG2D_PATCH_WALL, "early"), EG2D_OK);
    if (with_interior) assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
    else assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_OK);
    return g;
}

static void test_c_grid(void **state) {
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_create(65, 17, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_C), EG2D_OK);
    {
        int count = -1;
        assert_int_equal(eg2d_get_patch_count(g, &count), EG2D_ERR_STATE);
        assert_int_equal(count, -1);
        assert_non_null(strstr(eg2d_last_error(g), "set JMIN before"));
    }
    assert_int_equal(domain_set_airfoil_c(g, "0012", 16, 10), EG2D_OK);
    {
        const expected d[] = {{EG2D_SIDE_JMIN, 0, 16, EG2D_PATCH_CUT, "wake"},
                              {EG2D_SIDE_JMIN, 16, 48, EG2D_PATCH_WALL, "wall"},
                              {EG2D_SIDE_JMIN, 48, 64, EG2D_PATCH_CUT, "wake"},
                              {EG2D_SIDE_IMAX, 0, 16, EG2D_PATCH_OUTFLOW, "outflow"},
                              {EG2D_SIDE_JMAX, 0, 64, EG2D_PATCH_FARFIELD, "farfield"},
                              {EG2D_SIDE_IMIN, 0, 16, EG2D_PATCH_OUTFLOW, "outflow"}};
        assert_patches(g, d, 6);
    }
    /* The wake is internal: no patch there; the airfoil may be split. */
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMIN, 10, 20, EG2D_PATCH_WALL, "x"), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(g), "wake cut is nodes [0, 16] and [48, 64]"));
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMIN, 16, 32, EG2D_PATCH_WALL, "lower"), EG2D_OK);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMIN, 32, 48, EG2D_PATCH_WALL, "upper"), EG2D_OK);
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMAX, 0, 16, EG2D_PATCH_FARFIELD, "farfield"), EG2D_OK);
    {
        const expected d[] = {{EG2D_SIDE_JMIN, 0, 16, EG2D_PATCH_CUT, "wake"},
                              {EG2D_SIDE_JMIN, 16, 32, EG2D_PATCH_WALL, "lower"},
                              {EG2D_SIDE_JMIN, 32, 48, EG2D_PATCH_WALL, "upper"},
                              {EG2D_SIDE_JMIN, 48, 64, EG2D_PATCH_CUT, "wake"},
                              {EG2D_SIDE_IMAX, 0, 16, EG2D_PATCH_OUTFLOW, "outflow"},
                              {EG2D_SIDE_JMAX, 0, 16, EG2D_PATCH_FARFIELD, "farfield"},
                              {EG2D_SIDE_JMAX, 16, 64, EG2D_PATCH_FARFIELD, "farfield"},
                              {EG2D_SIDE_IMIN, 0, 16, EG2D_PATCH_OUTFLOW, "outflow"}};
        assert_patches(g, d, 8);
    }
    eg2d_destroy(g);
    /* Set before JMIN, a patch is checked against the cut when it is used. */
    g = c_grid_with_early_patch(0);
    assert_int_equal(eg2d_get_patch_count(g, NULL), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(g), "side JMIN nodes [0, 30]: the C-grid's wake cut"));
    eg2d_destroy(g);
}

static int entries(const char *dir) {
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (!d) return -1;
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) ++n;
    closedir(d);
    return n;
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
    (void)st;
    (void)flag;
    (void)ftw;
    return remove(path);
}

static int read_file(const char *path, char *text, size_t size) {
    FILE *f = fopen(path, "r");
    size_t n;
    if (!f) return -1;
    n = fread(text, 1, size - 1, f);
    text[n] = '\0';
    fclose(f);
    return (int)n;
}

/* The OpenFOAM case directory: what is in the way, what a failed write
 * leaves (nothing), and that a case's own system/ files are kept. */
static void test_openfoam_case_directory(void **state) {
    char dir[] = "/tmp/eg2d-patches-XXXXXX", path[512], text[4096];
    eg2d_grid *g;
    FILE *f;
    (void)state;
    assert_non_null(mkdtemp(dir));
    assert_int_equal(eg2d_create(9, 7, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    /* A file where the case should be. */
    snprintf(path, sizeof path, "%s/case", dir);
    f = fopen(path, "w");
    assert_non_null(f);
    fclose(f);
    assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_OPENFOAM), EG2D_ERR_IO);
    assert_non_null(strstr(eg2d_last_error(g), "cannot make the directory: a file that is not a directory is in the way"));
    assert_int_equal(unlink(path), 0);
    /* No parent: nothing made. Flags: none taken. */
    snprintf(path, sizeof path, "%s/no/case", dir);
    assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_OPENFOAM), EG2D_ERR_IO);
    assert_non_null(strstr(eg2d_last_error(g), "No such file or directory"));
    snprintf(path, sizeof path, "%s/case", dir);
    assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_OPENFOAM | EG2D_PLOT3D_3D), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g), "eg2d_write: format = 0x108: the openfoam format takes no flags");
    assert_int_equal(entries(dir), 0);
    /* A case of the user's: its controlDict stays, the mesh is replaced. */
    assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_OPENFOAM), EG2D_OK);
    snprintf(path, sizeof path, "%s/case/system/controlDict", dir);
    f = fopen(path, "w");
    assert_non_null(f);
    fputs("// the user's own\n", f);
    fclose(f);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_SPAN, 0.125), EG2D_OK);
    snprintf(path, sizeof path, "%s/case", dir);
    assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_OPENFOAM), EG2D_OK);
    snprintf(path, sizeof path, "%s/case/system/controlDict", dir);
    assert_true(read_file(path, text, sizeof text) > 0);
    assert_string_equal(text, "// the user's own\n");
    snprintf(path, sizeof path, "%s/case/constant/polyMesh/points", dir);
    assert_true(read_file(path, text, sizeof text) > 0);
    assert_non_null(strstr(text, " 0.125)\n"));
    snprintf(path, sizeof path, "%s/case/constant/polyMesh", dir);
    assert_int_equal(entries(path), 5); /* points faces owner neighbour boundary: no temporaries */
    /* A patch on the wake cut, set before JMIN: the writers refuse and write nothing. */
    eg2d_destroy(g);
    {
        g = c_grid_with_early_patch(1);
        snprintf(path, sizeof path, "%s/c.su2", dir);
        assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_SU2), EG2D_ERR_ARGUMENT);
        assert_non_null(strstr(eg2d_last_error(g), "the C-grid's wake cut is nodes [0, 16] and [48, 64]"));
        snprintf(path, sizeof path, "%s/c_foam", dir);
        assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_OPENFOAM), EG2D_ERR_ARGUMENT);
        assert_int_equal(access(path, F_OK), -1);
        assert_int_equal(eg2d_clear_patches(g), EG2D_OK);
        assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_OPENFOAM), EG2D_OK);
        eg2d_destroy(g);
    }
    assert_int_equal(nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS), 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_single_block), cmocka_unit_test(test_c_grid),
                                       cmocka_unit_test(test_openfoam_case_directory)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
