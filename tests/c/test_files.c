/* Files and failures: eg2d_write respects what is at the path (a symbolic
 * link is followed and kept, a file keeps its mode and its hard links, a FIFO
 * or a character device is written in place, a directory is refused), and
 * the readers read regular files only, reject non-finite coordinates and
 * grids smaller than 2 x 2, and name the path. After every refused call the
 * path has the same type, mode and content as before. */
#include <errno.h>
#include <math.h>
#include <fcntl.h>
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

static char dir[256];
static const char *at(const char *name) {
    static char buf[4][512];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static eg2d_grid *swan9(void) {
    eg2d_grid *g;
    assert_int_equal(eg2d_create(9, 9, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "swan"), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    return g;
}

static long file_size(const char *p) {
    struct stat st;
    return stat(p, &st) == 0 ? (long)st.st_size : -1;
}

static void write_bytes(const char *p, const char *text) {
    FILE *f = fopen(p, "wb");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static int setup(void **state) {
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/eg2d_test_files_XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}
static int teardown(void **state) {
    char cmd[300];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    return system(cmd);
}

/* A link is followed: its target gets the grid, the link stays a link. */
static void test_write_through_a_link(void **state) {
    eg2d_grid *g = swan9();
    struct stat st;
    (void)state;
    write_bytes(at("target.xyz"), "old");
    assert_int_equal(symlink("target.xyz", at("link.xyz")), 0);
    assert_int_equal(eg2d_write(g, at("link.xyz"), EG2D_FORMAT_PLOT3D), EG2D_OK);
    assert_int_equal(lstat(at("link.xyz"), &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_int_equal(eg2d_write(g, at("direct.xyz"), EG2D_FORMAT_PLOT3D), EG2D_OK);
    assert_int_equal(file_size(at("target.xyz")), file_size(at("direct.xyz")));
    eg2d_destroy(g);
}

/* An existing file keeps its permissions, and its other hard links see the new grid. */
static void test_write_keeps_mode_and_links(void **state) {
    eg2d_grid *g = swan9();
    struct stat st;
    (void)state;
    write_bytes(at("m.vts"), "old");
    assert_int_equal(chmod(at("m.vts"), 0640), 0);
    assert_int_equal(eg2d_write(g, at("m.vts"), EG2D_FORMAT_VTS), EG2D_OK);
    assert_int_equal(stat(at("m.vts"), &st), 0);
    assert_int_equal(st.st_mode & 07777, 0640);
    write_bytes(at("a.xyz"), "old");
    assert_int_equal(link(at("a.xyz"), at("b.xyz")), 0);
    assert_int_equal(eg2d_write(g, at("a.xyz"), EG2D_FORMAT_PLOT3D), EG2D_OK);
    assert_int_equal(stat(at("b.xyz"), &st), 0);
    assert_int_equal((int)st.st_nlink, 2);
    assert_true(file_size(at("b.xyz")) > 100);
    eg2d_destroy(g);
}

/* A FIFO without a reader is refused (not replaced, and the call does not block);
 * with a reader it gets the bytes. A character device is written in place. */
static void test_write_to_fifo_and_device(void **state) {
    eg2d_grid *g = swan9();
    struct stat st;
    char buf[8192];
    int fd;
    ssize_t n;
    (void)state;
    assert_int_equal(mkfifo(at("pipe"), 0600), 0);
    assert_int_equal(eg2d_write(g, at("pipe"), EG2D_FORMAT_PLOT3D), EG2D_ERR_IO);
    assert_non_null(strstr(eg2d_last_error(g), "a FIFO with no reader: not written"));
    assert_int_equal(stat(at("pipe"), &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    fd = open(at("pipe"), O_RDONLY | O_NONBLOCK);
    assert_true(fd >= 0);
    assert_int_equal(eg2d_write(g, at("pipe"), EG2D_FORMAT_PLOT3D), EG2D_OK);
    n = read(fd, buf, sizeof buf);
    close(fd);
    assert_int_equal(n, 4 + 8 + 4 + 4 + 16 * 81 + 4); /* the whole 9 x 9 Plot3D file */
    assert_int_equal(eg2d_write(g, "/dev/null", EG2D_FORMAT_VTS), EG2D_OK);
    assert_int_equal(stat("/dev/null", &st), 0);
    assert_true(S_ISCHR(st.st_mode));
    eg2d_destroy(g);
}

/* A directory is refused before anything is written. */
static void test_write_to_a_directory(void **state) {
    eg2d_grid *g = swan9();
    struct stat st;
    char want[600];
    (void)state;
    assert_int_equal(mkdir(at("d.xyz"), 0755), 0);
    assert_int_equal(eg2d_write(g, at("d.xyz"), EG2D_FORMAT_PLOT3D), EG2D_ERR_IO);
    snprintf(want, sizeof want, "eg2d_write: %s: is a directory: not written, and not replaced", at("d.xyz"));
    assert_string_equal(eg2d_last_error(g), want);
    assert_int_equal(stat(at("d.xyz"), &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    eg2d_destroy(g);
}

/* Readers: a directory and a device are refused naming the path; a binary
 * NaN is refused with its byte offset; a 1 x n grid is no grid. */
static void test_read_bad_files(void **state) {
    int ni, nj;
    char want[600];
    FILE *f;
    int hdr[4] = {8, 3, 2, 8}, rec = 48;
    double v[6] = {0, 1, 2, 0, 1, 2}, w[6] = {0, 0, 0, 1, 1, 1};
    (void)state;
    assert_int_equal(eg2d_read_plot3d(dir, 0, NULL, NULL, &ni, &nj, NULL, NULL), EG2D_ERR_IO);
    snprintf(want, sizeof want, "eg2d_read_plot3d: %s: a directory, not a regular file: not read", dir);
    assert_string_equal(eg2d_last_error(NULL), want);
    assert_int_equal(eg2d_read_plot3d("/dev/zero", 0, NULL, NULL, &ni, &nj, NULL, NULL), EG2D_ERR_IO);
    assert_string_equal(eg2d_last_error(NULL), "eg2d_read_plot3d: /dev/zero: a device, not a regular file: not read");
    /* a 3 x 2 single-grid file with Fortran markers, one coordinate NaN */
    w[4] = NAN; /* not 0.0 / 0.0: the test runs with FP traps on (support/fp_traps.c) */
    /* bytes: markers 0-3 and 12-15, record marker 16, x 20-67, y 68-115: y[4] at 100 */
    f = fopen(at("nan.x"), "wb");
    fwrite(hdr, 4, 4, f);
    fwrite(&rec, 4, 1, f);
    fwrite(v, 8, 6, f);
    fwrite(w, 8, 6, f);
    fwrite(&rec, 4, 1, f);
    fclose(f);
    rec = 96;
    f = fopen(at("nan.x"), "r+b");
    fseek(f, 16, SEEK_SET);
    fwrite(&rec, 4, 1, f);
    fseek(f, 16 + 4 + 96, SEEK_SET);
    fwrite(&rec, 4, 1, f);
    fclose(f);
    assert_int_equal(eg2d_read_plot3d(at("nan.x"), 0, NULL, NULL, &ni, &nj, NULL, NULL), EG2D_ERR_IO);
    assert_non_null(strstr(eg2d_last_error(NULL), "nan.x: a non-finite coordinate (NaN) at byte offset 100"));
    /* ASCII 1 x 3 (and 3 x 1) are not grids */
    write_bytes(at("line.x"), "1 3\n0 0 0\n0 1 2\n");
    assert_int_equal(eg2d_read_plot3d(at("line.x"), 0, NULL, NULL, &ni, &nj, NULL, NULL), EG2D_ERR_IO);
    assert_non_null(strstr(eg2d_last_error(NULL), "not a Plot3D grid file"));
}

/* A boundary that encloses nothing is refused before any solve, and the
 * handle is unchanged: all points on one line, and the top lying on the bottom. */
static void test_flat_domains(void **state) {
    double xb[5], yb[5], xr[5], yr[5], xt[5], yt[5], xl[5], yl[5];
    int k, c;
    (void)state;
    for (c = 0; c < 2; ++c) {
        eg2d_grid *g;
        for (k = 0; k < 5; ++k) {
            const double s = k / 4.0;
            xb[k] = s; yb[k] = 0;            /* bottom */
            xt[k] = s; yt[k] = 0;            /* top on the bottom */
            xl[k] = 0; yl[k] = 0;            /* left and right sides of zero length */
            xr[k] = 1; yr[k] = 0;
            if (c == 1) { yb[k] = xb[k]; yt[k] = xt[k]; yr[k] = 1; xl[k] = 0; } /* all on y = x */
        }
        if (c == 1)
            for (k = 0; k < 5; ++k) { xr[k] = 1; yr[k] = 1; }
        assert_int_equal(eg2d_create(5, 5, &g), EG2D_OK);
        assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, xb, yb), EG2D_OK);
        assert_int_equal(eg2d_set_side(g, EG2D_SIDE_IMAX, xr, yr), EG2D_OK);
        assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMAX, xt, yt), EG2D_OK);
        assert_int_equal(eg2d_set_side(g, EG2D_SIDE_IMIN, xl, yl), EG2D_OK);
        assert_int_equal(eg2d_solve(g), EG2D_ERR_BOUNDARY);
        assert_non_null(strstr(eg2d_last_error(g), "the boundary encloses an area of 0 in a bounding box of diagonal"));
        assert_int_equal(eg2d_get_coordinates(g, xb, yb), EG2D_ERR_STATE); /* still no interior */
        eg2d_destroy(g);
    }
}

/* A boundary that crosses itself is refused before any solve, naming the two
 * segments and the point, and the handle is unchanged: a bow tie (IMIN and
 * IMAX as the two diagonals of the unit square) and an O-grid whose inner
 * circle pokes through the outer one. */
static void test_self_crossing_boundaries(void **state) {
    enum { N = 8, M = 33 };
    double xb[N], yb[N], xr[N], yr[N], xt[N], yt[N], xl[N], yl[N], xi[M], yi[M], xo[M], yo[M], x[N * N];
    int k;
    eg2d_grid *g;
    (void)state;
    for (k = 0; k < N; ++k) {
        const double s = k / (N - 1.0);
        xb[k] = s; yb[k] = 0;          /* bottom (0,0)-(1,0) */
        xl[k] = s; yl[k] = s;          /* left (0,0)-(1,1) */
        xr[k] = 1 - s; yr[k] = s;      /* right (1,0)-(0,1) */
        xt[k] = 1 - s; yt[k] = 1;      /* top (1,1)-(0,1) */
    }
    assert_int_equal(eg2d_create(N, N, &g), EG2D_OK);
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, xb, yb), EG2D_OK);
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_IMAX, xr, yr), EG2D_OK);
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMAX, xt, yt), EG2D_OK);
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_IMIN, xl, yl), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_ERR_BOUNDARY);
    /* the diagonals cross at (0.5, 0.5), between their nodes 3 and 4 of 0..7 */
    assert_string_equal(eg2d_last_error(g), "eg2d_initialize: the boundary crosses itself: IMAX segment 3-4 crosses "
                                            "IMIN segment 3-4 near (0.5, 0.5)");
    assert_int_equal(eg2d_solve(g), EG2D_ERR_BOUNDARY);
    assert_int_equal(eg2d_get_coordinates(g, x, x), EG2D_ERR_STATE); /* still no interior */
    eg2d_destroy(g);

    for (k = 0; k < M; ++k) { /* clockwise circles, the first point repeated at the end */
        const double t = -2 * 3.14159265358979323846 * k / (M - 1.0);
        xi[k] = cos(t); yi[k] = sin(t);
        xo[k] = 1.5 + 2 * cos(t); yo[k] = 2 * sin(t);
    }
    assert_int_equal(eg2d_create(M, 9, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_O), EG2D_OK);
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, xi, yi), EG2D_OK);
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMAX, xo, yo), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_ERR_BOUNDARY);
    assert_non_null(strstr(eg2d_last_error(g), "eg2d_solve: the boundary crosses itself: "));
    assert_non_null(strstr(eg2d_last_error(g), "JMIN segment"));
    assert_non_null(strstr(eg2d_last_error(g), "JMAX segment"));
    /* the outer circle moved out of the way: the same handle solves */
    for (k = 0; k < M; ++k) xo[k] -= 1.5;
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMAX, xo, yo), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    eg2d_destroy(g);
}

/* Every cut of a written 6 x 5 grid, in every binary layout eg2d writes (2-D
 * and 3-D, single- and multi-grid, double and single precision, little and
 * big endian, with and without record markers): with record markers every
 * cut is refused. A marker-less file has no redundancy to check: a cut that
 * leaves exactly the bytes of the same grid at the other precision (or with
 * its nk = 1 read as a coordinate) cannot be told from such a file, but no
 * cut reads as a grid of another size (before: 1 x n grids). */
static void test_every_cut_is_refused(void **state) {
    const int variants[] = {0, EG2D_PLOT3D_3D, EG2D_PLOT3D_MULTI, EG2D_PLOT3D_SINGLE, EG2D_PLOT3D_BIG_ENDIAN,
                            EG2D_PLOT3D_NO_MARKERS, EG2D_PLOT3D_NO_MARKERS | EG2D_PLOT3D_SINGLE,
                            EG2D_PLOT3D_NO_MARKERS | EG2D_PLOT3D_MULTI | EG2D_PLOT3D_3D};
    char path[] = "/tmp/eg2d-cut-XXXXXX", cut[64];
    unsigned char *bytes;
    eg2d_grid *g;
    size_t v;
    long size, n, accepted = 0, tried = 0;
    int fd, fmt, nb, ri, rj;
    FILE *f;
    (void)state;
    assert_int_equal(eg2d_create(6, 5, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "swan"), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    snprintf(cut, sizeof cut, "%s.cut", path);
    for (v = 0; v < sizeof variants / sizeof variants[0]; ++v) {
        assert_int_equal(eg2d_write(g, path, EG2D_FORMAT_PLOT3D | variants[v]), EG2D_OK);
        size = file_size(path);
        assert_true(size > 0);
        bytes = malloc(size > 0 ? (size_t)size : 1);
        assert_non_null(bytes);
        f = fopen(path, "rb");
        assert_int_equal(fread(bytes, 1, (size_t)size, f), (size_t)size);
        fclose(f);
        assert_int_equal(eg2d_read_plot3d(path, 0, NULL, NULL, NULL, NULL, NULL, NULL), EG2D_OK);
        for (n = 1; n < size; ++n) {
            f = fopen(cut, "wb");
            assert_int_equal(fwrite(bytes, 1, (size_t)n, f), (size_t)n);
            fclose(f);
            ++tried;
            if (eg2d_read_plot3d(cut, 0, &fmt, &nb, &ri, &rj, NULL, NULL) != EG2D_ERR_IO) {
                print_message("flags 0x%x cut to %ld of %ld bytes is read as format 0x%x, %d grid(s), %d x %d\n",
                              variants[v], n, size, fmt, nb, ri, rj);
                if (variants[v] & EG2D_PLOT3D_NO_MARKERS) {
                    assert_true(ri == 6 && rj == 5 && nb == 1);
                    assert_true(fmt & EG2D_PLOT3D_NO_MARKERS);
                } else {
                    ++accepted;
                }
            }
        }
        free(bytes);
    }
    print_message("%ld cuts tried, %ld of the record-marker files read\n", tried, accepted);
    assert_int_equal(accepted, 0);
    unlink(path);
    unlink(cut);
    eg2d_destroy(g);
}

/* The read call that takes the caller's capacity refuses a block larger than it. */
static void test_read_with_capacity(void **state) {
    eg2d_grid *g = swan9();
    double x[81], y[81];
    int ni, nj;
    char want[600];
    (void)state;
    assert_int_equal(eg2d_write(g, at("cap.xyz"), EG2D_FORMAT_PLOT3D), EG2D_OK);
    assert_int_equal(eg2d_read_plot3d_into(at("cap.xyz"), 0, 81, NULL, NULL, &ni, &nj, x, y), EG2D_OK);
    assert_true(ni == 9 && nj == 9);
    assert_int_equal(eg2d_read_plot3d_into(at("cap.xyz"), 0, 80, NULL, NULL, NULL, NULL, x, y), EG2D_ERR_ARGUMENT);
    snprintf(want, sizeof want, "eg2d_read_plot3d_into: %s: grid 0 has 9 x 9 = 81 nodes, more than capacity = 80",
             at("cap.xyz"));
    assert_string_equal(eg2d_last_error(NULL), want);
    assert_int_equal(eg2d_read_plot3d_into(at("cap.xyz"), 0, -1, NULL, NULL, NULL, NULL, x, y), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_write_through_a_link),  cmocka_unit_test(test_write_keeps_mode_and_links),
        cmocka_unit_test(test_write_to_fifo_and_device), cmocka_unit_test(test_write_to_a_directory),
        cmocka_unit_test(test_read_bad_files),         cmocka_unit_test(test_flat_domains),
        cmocka_unit_test(test_self_crossing_boundaries),
        cmocka_unit_test(test_every_cut_is_refused),
        cmocka_unit_test(test_read_with_capacity),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
