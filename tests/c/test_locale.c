/* The host's locale: a host that calls setlocale with a
 * comma-decimal locale (GTK and Qt programs do) must get the same bytes from
 * every writer as under "C", and the readers must read them back. One
 * process writes every format under "C", switches to a comma locale (one
 * of kCommaLocales; .ci/install-deps generates de_DE.UTF-8), writes again
 * and compares file by file. */
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <ftw.h>
#include <locale.h>
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

#define NI 21
#define NJ 13

static const char *const kCommaLocales[] = {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "nl_NL.UTF-8"};

static const struct { const char *name; int format; } kFiles[] = {
    {"grid.x", EG2D_FORMAT_PLOT3D},
    {"grid_ascii.x", EG2D_FORMAT_PLOT3D_ASCII},
    {"grid_ascii_3d_multi.x", EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI},
    {"grid.vts", EG2D_FORMAT_VTS},
    {"grid.gmv", EG2D_FORMAT_GMV},
    {"grid.m", EG2D_FORMAT_MATLAB},
    {"grid.svg", EG2D_FORMAT_SVG},
    {"grid.su2", EG2D_FORMAT_SU2},
    {"report.txt", EG2D_FORMAT_REPORT},
    {"report.json", EG2D_FORMAT_REPORT_JSON},
    {"case", EG2D_FORMAT_OPENFOAM},
    {"grid.vtm", EG2D_FORMAT_VTM},
};
/* The OpenFOAM case's files (eg2d.h). */
static const char *const kCaseFiles[] = {
    "constant/polyMesh/points", "constant/polyMesh/faces",  "constant/polyMesh/owner",
    "constant/polyMesh/neighbour", "constant/polyMesh/boundary", "system/controlDict",
    "system/fvSchemes", "system/fvSolution",
};

static char dir[64];

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
    (void)st, (void)flag, (void)ftw;
    return remove(path);
}

static const char *join(char *buf, size_t size, const char *a, const char *b, const char *c) {
    snprintf(buf, size, "%s/%s/%s", a, b, c);
    return buf;
}

/* The whole file; NULL if it cannot be read. */
static char *slurp(const char *path, long *size) {
    FILE *f = fopen(path, "rb");
    char *b;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    *size = ftell(f);
    rewind(f);
    b = malloc((size_t)*size + 1);
    if (fread(b, 1, (size_t)*size, f) != (size_t)*size) *size = -1;
    b[*size < 0 ? 0 : *size] = '\0';
    fclose(f);
    return b;
}

static void assert_same_file(const char *sub) {
    char a[256], b[256];
    long na, nb;
    char *ca = slurp(join(a, sizeof a, dir, "c", sub), &na), *cb = slurp(join(b, sizeof b, dir, "comma", sub), &nb);
    if (!ca || !cb || na != nb || memcmp(ca, cb, (size_t)na) != 0) {
        const char *comma = cb ? strstr(cb, ",9") : NULL;
        print_error("%s differs under the comma locale (%ld vs %ld bytes)%s%.40s\n", sub, na, nb,
                    comma ? ": near " : "", comma ? comma - 8 : "");
        free(ca), free(cb);
        fail();
    }
    free(ca), free(cb);
}

static void write_all(eg2d_grid *g, const char *where) {
    char path[256];
    size_t k;
    snprintf(path, sizeof path, "%s/%s", dir, where);
    assert_int_equal(mkdir(path, 0700), 0);
    for (k = 0; k < sizeof kFiles / sizeof kFiles[0]; ++k) {
        join(path, sizeof path, dir, where, kFiles[k].name);
        if (eg2d_write(g, path, kFiles[k].format) != EG2D_OK) {
            print_error("%s: %s\n", path, eg2d_last_error(g));
            fail();
        }
    }
}

/* Switches the whole process to the first comma locale there is. */
static void comma_locale(void) {
    size_t k;
    for (k = 0; k < sizeof kCommaLocales / sizeof kCommaLocales[0]; ++k)
        if (setlocale(LC_ALL, kCommaLocales[k])) {
            assert_string_equal(localeconv()->decimal_point, ",");
            return;
        }
    print_error("no comma-decimal locale (de_DE.UTF-8: .ci/install-deps generates it)\n");
    fail();
}

static void test_files_and_readers(void **state) {
    eg2d_grid *g;
    eg2d_curve *curve;
    double x[NI * NJ], y[NI * NJ], rx[NI * NJ], ry[NI * NJ], px[3], py[3], cx[2][5], cy[2][5];
    int ni, nj, n, pass, k;
    char path[256];
    FILE *f;
    (void)state;
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    /* A wall patch, so the reports' wall lines are written too. */
    assert_int_equal(eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, NI - 1, EG2D_PATCH_WALL, "floor"), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    write_all(g, "c");
    snprintf(path, sizeof path, "%s/points.txt", dir);
    assert_non_null(f = fopen(path, "w"));
    fprintf(f, "# x y\n0.99875 -0.5e-3\n1.25, 2.5\n-3.125\t1e2\n");
    fclose(f);

    /* The airfoil file read under each locale: the same curve. */
    snprintf(path, sizeof path, "%s/naca0012_selig.dat", EG2D_TEST_DATA);
    for (pass = 0; pass < 2; ++pass) {
        if (pass == 1) comma_locale();
        if (eg2d_curve_read_airfoil(path, &curve) != EG2D_OK) {
            print_error("%s: %s\n", path, eg2d_last_error(NULL));
            fail();
        }
        for (k = 0; k < 5; ++k)
            assert_int_equal(eg2d_curve_evaluate(curve, 0.25 * k, &cx[pass][k], &cy[pass][k]), EG2D_OK);
        eg2d_curve_destroy(curve);
    }
    assert_memory_equal(cx[0], cx[1], sizeof cx[0]);
    assert_memory_equal(cy[0], cy[1], sizeof cy[0]);

    write_all(g, "comma");
    for (k = 0; k < (int)(sizeof kFiles / sizeof kFiles[0]); ++k)
        if (kFiles[k].format != EG2D_FORMAT_OPENFOAM) assert_same_file(kFiles[k].name);
    for (k = 0; k < (int)(sizeof kCaseFiles / sizeof kCaseFiles[0]); ++k) {
        char sub[128];
        snprintf(sub, sizeof sub, "case/%s", kCaseFiles[k]);
        assert_same_file(sub);
    }

    /* The readers, still under the comma locale: the grid's own numbers. */
    join(path, sizeof path, dir, "c", "grid_ascii.x");
    if (eg2d_read_plot3d_into(path, 0, NI * NJ, NULL, NULL, &ni, &nj, rx, ry) != EG2D_OK) {
        print_error("%s: %s\n", path, eg2d_last_error(NULL));
        fail();
    }
    assert_int_equal(ni, NI);
    assert_int_equal(nj, NJ);
    assert_memory_equal(rx, x, sizeof x);
    assert_memory_equal(ry, y, sizeof y);
    snprintf(path, sizeof path, "%s/points.txt", dir);
    if (eg2d_read_points(path, 3, &n, px, py) != EG2D_OK) {
        print_error("%s: %s\n", path, eg2d_last_error(NULL));
        fail();
    }
    assert_int_equal(n, 3);
    assert_true(px[0] == 0.99875 && py[0] == -0.5e-3 && px[1] == 1.25 && py[1] == 2.5);
    assert_true(px[2] == -3.125 && py[2] == 100.0);
    eg2d_destroy(g);
}

static int setup(void **state) {
    (void)state;
    strcpy(dir, "/tmp/eg2d_locale_XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state) {
    (void)state;
    setlocale(LC_ALL, "C");
    return nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_files_and_readers, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
