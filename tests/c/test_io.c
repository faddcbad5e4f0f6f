/* Files: Plot3D round trips through eg2d_read_plot3d for every variant,
 * reader and writer errors (paths, system reasons, line numbers), the
 * all-or-nothing rule under a write that fails half-way, point files, and
 * the CGNS plugin's absence ("test_io cgns-missing", run by ctest with
 * EG2D_PLUGIN_DIR pointing nowhere). Readers eg2d did not write check the
 * written files in tests/io/readback.py. */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

#define NI 17
#define NJ 11

static char dir[256];

static void assert_contains(const char *text, const char *part) {
    if (!strstr(text, part)) fail_msg("message \"%s\" does not contain \"%s\"", text, part);
}

static const char *in_dir(const char *name) {
    static char path[4][512];
    static int next;
    char *p = path[next++ % 4];
    snprintf(p, 512, "%s/%s", dir, name);
    return p;
}

static int exists(const char *path) { return access(path, F_OK) == 0; }

/* Files in dir whose name contains part. */
static int count_files(const char *part) {
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    assert_non_null(d);
    while ((e = readdir(d)))
        if (strstr(e->d_name, part)) ++n;
    closedir(d);
    return n;
}

static void write_text(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static eg2d_grid *converged(void) {
    eg2d_grid *g;
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "swan"), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    return g;
}

static void test_plot3d_round_trip(void **state) {
    static const int variants[] = {
        EG2D_FORMAT_PLOT3D,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_MULTI,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_BIG_ENDIAN,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI | EG2D_PLOT3D_BIG_ENDIAN,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_SINGLE,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_SINGLE | EG2D_PLOT3D_BIG_ENDIAN,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_NO_MARKERS,
        EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI | EG2D_PLOT3D_NO_MARKERS,
        EG2D_FORMAT_PLOT3D_ASCII,
        EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_3D,
        EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_MULTI,
        EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI,
    };
    static double x[NI * NJ], y[NI * NJ], rx[NI * NJ], ry[NI * NJ];
    eg2d_grid *g = converged(), *h;
    size_t v;
    int k;
    (void)state;
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (v = 0; v < sizeof variants / sizeof variants[0]; ++v) {
        const int single = variants[v] & EG2D_PLOT3D_SINGLE;
        int format = -1, nblocks = -1, ni = -1, nj = -1;
        double err = 0, r0, r1;
        assert_int_equal(eg2d_write(g, in_dir("rt.x"), variants[v]), EG2D_OK);
        /* Ask the size first, then read. */
        assert_int_equal(eg2d_read_plot3d(in_dir("rt.x"), 0, &format, &nblocks, &ni, &nj, NULL, NULL), EG2D_OK);
        assert_int_equal(format, variants[v]);
        assert_int_equal(nblocks, 1);
        assert_int_equal(ni, NI);
        assert_int_equal(nj, NJ);
        assert_int_equal(eg2d_read_plot3d(in_dir("rt.x"), 0, NULL, NULL, NULL, NULL, rx, ry), EG2D_OK);
        for (k = 0; k < NI * NJ; ++k) {
            const double e = fmax(fabs(rx[k] - x[k]), fabs(ry[k] - y[k]));
            err = e > err ? e : err;
        }
        if (single) assert_true(err < 1e-6);
        else assert_true(err == 0);
        /* The grid read back is a start grid: same residual. */
        assert_int_equal(eg2d_create(NI, NJ, &h), EG2D_OK);
        assert_int_equal(eg2d_set_coordinates(h, rx, ry), EG2D_OK);
        assert_int_equal(eg2d_get_residual(g, &r0), EG2D_OK);
        assert_int_equal(eg2d_get_residual(h, &r1), EG2D_OK);
        if (!single) assert_true(r0 == r1);
        eg2d_destroy(h);
        print_message("plot3d variant %#06x: read back as %#06x, max error %.2e\n", variants[v], format, err);
    }
    eg2d_destroy(g);
}

/* A multi-grid ASCII file as another tool would write it: two grids. */
static void test_plot3d_multi_block(void **state) {
    double x[6], y[6];
    int format, nblocks, ni, nj;
    (void)state;
    write_text(in_dir("two.x"), "2\n 2 2 1\n 3 2 1\n"
                                "0 1 0 1  0 0 1 1  0 0 0 0\n"
                                "5 6 7.0D+00 5 6 7  0 0 0 2 2 2  3 3 3 3 3 3\n"); /* Fortran's D exponent */
    assert_int_equal(eg2d_read_plot3d(in_dir("two.x"), 1, &format, &nblocks, &ni, &nj, x, y), EG2D_OK);
    assert_int_equal(format, EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI);
    assert_int_equal(nblocks, 2);
    assert_int_equal(ni, 3);
    assert_int_equal(nj, 2);
    assert_true(x[2] == 7 && y[3] == 2);
    assert_int_equal(eg2d_read_plot3d(in_dir("two.x"), 2, NULL, NULL, &ni, &nj, NULL, NULL), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(NULL), "block = 2:");
    assert_contains(eg2d_last_error(NULL), "has 2 grid(s)");
    /* A real 3D block (nk = 2) is not a 2D grid. */
    write_text(in_dir("k2.x"), "2 2 2\n0 1 0 1 0 1 0 1\n0 0 1 1 0 0 1 1\n0 0 0 0 1 1 1 1\n");
    assert_int_equal(eg2d_read_plot3d(in_dir("k2.x"), 0, NULL, NULL, &ni, &nj, NULL, NULL), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(NULL), "nk = 2");
}

static void test_plot3d_read_errors(void **state) {
    eg2d_grid *g = converged();
    char text[128];
    FILE *f;
    long size;
    (void)state;
    assert_int_equal(eg2d_read_plot3d(in_dir("missing.x"), 0, NULL, NULL, NULL, NULL, NULL, NULL), EG2D_ERR_IO);
    snprintf(text, sizeof text, "%s: cannot open: No such file or directory", in_dir("missing.x"));
    assert_string_equal(eg2d_last_error(NULL) + strlen("eg2d_read_plot3d: "), text);
    write_text(in_dir("bad.x"), "2 2\n0 1\n0 1 x 0 1 1\n");
    assert_int_equal(eg2d_read_plot3d(in_dir("bad.x"), 0, NULL, NULL, NULL, NULL, NULL, NULL), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(NULL), "line 3: \"x\" is not a number");
    write_text(in_dir("short.x"), "3 3\n0 1 2 0 1 2 0 1 2\n0 0 0 1 1 1 2 2\n");
    assert_int_equal(eg2d_read_plot3d(in_dir("short.x"), 0, NULL, NULL, NULL, NULL, NULL, NULL), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(NULL), "its 19 numbers fit no");
    /* A binary file cut short by one byte fits no layout. */
    assert_int_equal(eg2d_write(g, in_dir("cut.x"), EG2D_FORMAT_PLOT3D), EG2D_OK);
    f = fopen(in_dir("cut.x"), "rb+");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fclose(f);
    assert_int_equal(truncate(in_dir("cut.x"), size - 1), 0);
    assert_int_equal(eg2d_read_plot3d(in_dir("cut.x"), 0, NULL, NULL, NULL, NULL, NULL, NULL), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(NULL), "not a Plot3D grid file");
    {
        double xs[4];
        assert_int_equal(eg2d_read_plot3d(in_dir("cut.x"), 0, NULL, NULL, NULL, NULL, xs, NULL), EG2D_ERR_ARGUMENT);
        assert_string_equal(eg2d_last_error(NULL), "eg2d_read_plot3d: x and y must both be given or both be NULL");
    }
    assert_int_equal(eg2d_read_plot3d(NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(NULL), "eg2d_read_plot3d: path is NULL");
    eg2d_destroy(g);
}

static void test_write_errors(void **state) {
    eg2d_grid *g = converged(), *blank;
    char want[512];
    (void)state;
    /* A directory that does not exist: the path and the system's reason. */
    assert_int_equal(eg2d_write(g, "/nonexistent-eg2d-dir/grid.vts", EG2D_FORMAT_VTS), EG2D_ERR_IO);
    assert_string_equal(eg2d_last_error(g), "eg2d_write: /nonexistent-eg2d-dir/grid.vts: cannot create a file in its "
                                            "directory: No such file or directory");
    /* A directory where the file should be: refused before anything is written, nothing is left. */
    assert_int_equal(mkdir(in_dir("adir"), 0755), 0);
    assert_int_equal(eg2d_write(g, in_dir("adir"), EG2D_FORMAT_GMV), EG2D_ERR_IO);
    snprintf(want, sizeof want, "eg2d_write: %s: is a directory: not written, and not replaced", in_dir("adir"));
    assert_string_equal(eg2d_last_error(g), want);
    assert_int_equal(count_files(".eg2d-tmp-"), 0);
    /* Arguments. */
    assert_int_equal(eg2d_write(g, NULL, EG2D_FORMAT_VTS), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g), "eg2d_write: path is NULL");
    assert_int_equal(eg2d_write(g, in_dir("f"), 99), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g), "eg2d_write: format = 99: no such file format");
    assert_int_equal(eg2d_write(g, in_dir("f"), EG2D_FORMAT_VTS | EG2D_PLOT3D_3D), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g), "eg2d_write: format = 0x102: flags 0x100 do not apply to the vts format");
    assert_int_equal(eg2d_write(g, in_dir("f"), EG2D_FORMAT_PLOT3D_ASCII | EG2D_PLOT3D_SINGLE), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_SVG_QUALITY, EG2D_QUALITY_ORTHO_MAX_JMIN), EG2D_OK);
    assert_int_equal(eg2d_write(g, in_dir("f"), EG2D_FORMAT_SVG), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "svg_quality = 40 (ortho_max_jmin): a boundary summary");
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_SVG_QUALITY, 7), EG2D_OK);
    assert_int_equal(eg2d_write(g, in_dir("f"), EG2D_FORMAT_SVG), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "svg_quality = 7: no such quality metric");
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_SVG_QUALITY, -2), EG2D_ERR_ARGUMENT);
    assert_false(exists(in_dir("f")));
    assert_int_equal(count_files(".eg2d-tmp-"), 0);
    /* A grid with no interior yet. */
    assert_int_equal(eg2d_create(NI, NJ, &blank), EG2D_OK);
    assert_int_equal(domain_set(blank, "swan"), EG2D_OK);
    assert_int_equal(eg2d_write(blank, in_dir("f"), EG2D_FORMAT_VTS), EG2D_ERR_STATE);
    assert_false(exists(in_dir("f")));
    eg2d_destroy(blank);
    eg2d_destroy(g);
}

/* A write that fails half-way (the file-size limit, EFBIG) leaves the file
 * that was there untouched and no temporary behind, for every format. */
static void test_failed_write_leaves_nothing(void **state) {
    static const int formats[] = {EG2D_FORMAT_PLOT3D, EG2D_FORMAT_PLOT3D_ASCII, EG2D_FORMAT_VTS, EG2D_FORMAT_GMV,
                                  EG2D_FORMAT_MATLAB, EG2D_FORMAT_SVG};
    eg2d_grid *g = converged();
    struct rlimit old, small;
    size_t k;
    (void)state;
    write_text(in_dir("keep.out"), "the old file\n");
    signal(SIGXFSZ, SIG_IGN);
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
    small = old;
    small.rlim_cur = 1000; /* bytes: every format above writes more for a 17 x 11 grid */
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &small), 0);
    for (k = 0; k < sizeof formats / sizeof formats[0]; ++k) {
        const int status = eg2d_write(g, in_dir("keep.out"), formats[k]);
        const char *msg = eg2d_last_error(g);
        setrlimit(RLIMIT_FSIZE, &old);
        assert_int_equal(status, EG2D_ERR_IO);
        assert_contains(msg, in_dir("keep.out"));
        assert_contains(msg, "File too large");
        assert_int_equal(count_files(".eg2d-tmp-"), 0);
        {
            char line[64] = "";
            FILE *f = fopen(in_dir("keep.out"), "r");
            assert_non_null(f);
            assert_non_null(fgets(line, sizeof line, f));
            fclose(f);
            assert_string_equal(line, "the old file\n");
        }
        setrlimit(RLIMIT_FSIZE, &small);
    }
    setrlimit(RLIMIT_FSIZE, &old);
    signal(SIGXFSZ, SIG_DFL);
    /* Without the limit the same call replaces the file. */
    assert_int_equal(eg2d_write(g, in_dir("keep.out"), EG2D_FORMAT_GMV), EG2D_OK);
    assert_int_equal(count_files(".eg2d-tmp-"), 0);
    eg2d_destroy(g);
}

#ifdef EG2D_TEST_HAVE_CGNS
static void test_cgns_with_plugin(void **state) {
    eg2d_grid *g = converged();
    (void)state;
    assert_int_equal(eg2d_write(g, in_dir("grid.cgns"), EG2D_FORMAT_CGNS), EG2D_OK);
    assert_true(exists(in_dir("grid.cgns")));
    assert_int_equal(eg2d_write(g, "/nonexistent-eg2d-dir/grid.cgns", EG2D_FORMAT_CGNS), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(g), "No such file or directory");
    eg2d_destroy(g);
}
#endif

static void test_cgns_missing_plugin(void **state) {
    eg2d_grid *g = converged();
    (void)state;
    assert_int_equal(eg2d_write(g, in_dir("grid.cgns"), EG2D_FORMAT_CGNS), EG2D_ERR_UNSUPPORTED);
    assert_contains(eg2d_last_error(g), "EG2D_FORMAT_CGNS needs the optional plugin libeg2d_cgns.so");
    if (getenv("EG2D_PLUGIN_DIR")) assert_contains(eg2d_last_error(g), "no-such-plugin-dir/libeg2d_cgns.so");
    assert_false(exists(in_dir("grid.cgns")));
    assert_int_equal(count_files(".eg2d-tmp-"), 0);
    /* The other formats do not need it. */
    assert_int_equal(eg2d_write(g, in_dir("grid.vts"), EG2D_FORMAT_VTS), EG2D_OK);
    eg2d_destroy(g);
}

/* The four sides of the quad domain as point files, in the styles people
 * write: comments, blank lines, commas, tabs, CRLF. */
static void test_point_files(void **state) {
    enum { N = 9 };
    static const char *names[4] = {"jmin.txt", "imax.txt", "jmax.txt", "imin.txt"};
    double want_x[N * N], want_y[N * N], got_x[N * N], got_y[N * N], px[N], py[N];
    eg2d_grid *a, *b;
    int s, k, n;
    (void)state;
    assert_int_equal(eg2d_create(N, N, &a), EG2D_OK);
    assert_int_equal(domain_set(a, "quad"), EG2D_OK);
    assert_int_equal(eg2d_initialize(a, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(a, want_x, want_y), EG2D_OK);
    for (s = 0; s < 4; ++s) {
        FILE *f = fopen(in_dir(names[s]), "w");
        assert_non_null(f);
        fprintf(f, "# side %d of the quad\n\n", s);
        for (k = 0; k < N; ++k) {
            const int node = s == 0 ? k : s == 1 ? N - 1 + N * k : s == 2 ? k + N * (N - 1) : N * k;
            fprintf(f, k % 3 == 0 ? "%.17g, %.17g  # a point\r\n" : k % 3 == 1 ? "\t%.17g\t%.17g\n" : "%.17g %.17g\n",
                    want_x[node], want_y[node]);
        }
        fclose(f);
    }
    assert_int_equal(eg2d_read_points(in_dir("jmax.txt"), 0, &n, NULL, NULL), EG2D_OK);
    assert_int_equal(n, N);
    assert_int_equal(eg2d_read_points(in_dir("jmax.txt"), N, &n, px, py), EG2D_OK);
    assert_true(px[3] == want_x[3 + N * (N - 1)] && py[3] == want_y[3 + N * (N - 1)]);
    assert_int_equal(eg2d_read_points(in_dir("jmax.txt"), N - 1, &n, px, py), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(NULL), "holds 9 points, more than capacity = 8");
    assert_int_equal(eg2d_create(N, N, &b), EG2D_OK);
    for (s = 0; s < 4; ++s) assert_int_equal(eg2d_set_side_from_file(b, s, in_dir(names[s])), EG2D_OK);
    assert_int_equal(eg2d_initialize(b, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(b, got_x, got_y), EG2D_OK);
    for (k = 0; k < N * N; ++k) assert_true(got_x[k] == want_x[k] && got_y[k] == want_y[k]);
    eg2d_destroy(a);
    eg2d_destroy(b);
}

static void test_point_file_errors(void **state) {
    eg2d_grid *g;
    char want[512];
    int n;
    (void)state;
    assert_int_equal(eg2d_create(5, 4, &g), EG2D_OK);
    write_text(in_dir("p1.txt"), "# x y\n0 0\n1 0\n\n2 abc\n3 0\n");
    assert_int_equal(eg2d_set_side_from_file(g, EG2D_SIDE_JMIN, in_dir("p1.txt")), EG2D_ERR_IO);
    snprintf(want, sizeof want, "eg2d_set_side_from_file: %s:5: \"2 abc\": expected two numbers x y", in_dir("p1.txt"));
    assert_string_equal(eg2d_last_error(g), want);
    write_text(in_dir("p2.txt"), "0 0\n1 0 7\n");
    assert_int_equal(eg2d_read_points(in_dir("p2.txt"), 0, NULL, NULL, NULL), EG2D_ERR_ARGUMENT); /* n, x, y NULL */
    assert_int_equal(eg2d_set_side_from_file(g, EG2D_SIDE_JMIN, in_dir("p2.txt")), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(g), "p2.txt:2: \"1 0 7\": unexpected \"7\" after the two numbers x y");
    write_text(in_dir("p3.txt"), "# nothing\n\n");
    assert_int_equal(eg2d_set_side_from_file(g, EG2D_SIDE_JMIN, in_dir("p3.txt")), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(g), "p3.txt: no points in the file");
    write_text(in_dir("p4.txt"), "0 0\n1 0\n2 0\n3 nan\n4 0\n");
    assert_int_equal(eg2d_set_side_from_file(g, EG2D_SIDE_JMIN, in_dir("p4.txt")), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(g), "p4.txt:4: \"3 nan\": the point is not finite");
    write_text(in_dir("p5.txt"), "0 0\n1 0\n2 0\n3 0\n");
    assert_int_equal(eg2d_set_side_from_file(g, EG2D_SIDE_JMIN, in_dir("p5.txt")), EG2D_ERR_BOUNDARY);
    assert_contains(eg2d_last_error(g), "p5.txt holds 4 points; side JMIN has 5");
    assert_int_equal(eg2d_set_side_from_file(g, EG2D_SIDE_IMAX, in_dir("p5.txt")), EG2D_OK); /* nj = 4 */
    assert_int_equal(eg2d_set_side_from_file(g, 4, in_dir("p5.txt")), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_O), EG2D_OK);
    assert_int_equal(eg2d_set_side_from_file(g, EG2D_SIDE_IMIN, in_dir("p5.txt")), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "side IMIN: the O-grid topology has no such side");
    assert_int_equal(eg2d_set_side_from_file(g, EG2D_SIDE_JMIN, in_dir("none.txt")), EG2D_ERR_IO);
    assert_contains(eg2d_last_error(g), "none.txt: cannot open: No such file or directory");
    /* A device (a wrong path in a case file) is refused before anything is read. */
    assert_int_equal(eg2d_read_points("/dev/zero", 0, &n, NULL, NULL), EG2D_ERR_IO);
    assert_string_equal(eg2d_last_error(NULL), "eg2d_read_points: /dev/zero: a device, not a regular file: not read");
    /* A last line without a newline still counts. */
    write_text(in_dir("p6.txt"), "0 0\n1 0.5");
    assert_int_equal(eg2d_read_points(in_dir("p6.txt"), 0, &n, NULL, NULL), EG2D_OK);
    assert_int_equal(n, 2);
    eg2d_destroy(g);
}

static int make_dir(void **state) {
    (void)state;
    snprintf(dir, sizeof dir, "%s/eg2d_test_io_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    return mkdtemp(dir) ? 0 : -1;
}

static int remove_dir(void **state) {
    char cmd[512];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

int main(int argc, char **argv) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plot3d_round_trip), cmocka_unit_test(test_plot3d_multi_block),
        cmocka_unit_test(test_plot3d_read_errors), cmocka_unit_test(test_write_errors),
        cmocka_unit_test(test_failed_write_leaves_nothing),
#ifdef EG2D_TEST_HAVE_CGNS
        cmocka_unit_test(test_cgns_with_plugin),
#else
        cmocka_unit_test(test_cgns_missing_plugin),
#endif
        cmocka_unit_test(test_point_files), cmocka_unit_test(test_point_file_errors),
    };
    const struct CMUnitTest missing[] = {cmocka_unit_test(test_cgns_missing_plugin)};
    if (argc > 1 && !strcmp(argv[1], "cgns-missing")) return cmocka_run_group_tests(missing, make_dir, remove_dir);
    return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
