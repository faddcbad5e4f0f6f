/* The airfoil reader on files as people download them: each kind
 * written here, into a temporary directory, from the NACA 0012 points of
 * tests/data/naca0012_selig.dat or of eg2d_curve_naca4, and read back as the
 * same curve as the standard Selig file, or refused naming the line. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "eg2d.h"

#define MAXP 64
#define NS 101 /* sampled points compared */

static char dir[] = "/tmp/eg2d-airfoil-file-XXXXXX";
static double sx[MAXP], sy[MAXP]; /* the Selig file's points: TE, upper, LE, lower, TE */
static int sn;
static double bx[MAXP], by[MAXP]; /* an open (blunt) NACA 0012 in Selig order */
static const int bn = 41;

static const char *path_of(const char *name) {
    static char p[256];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return p;
}

static int setup(void **state) {
    char path[512], line[256];
    FILE *f;
    eg2d_curve *c;
    double x[MAXP], y[MAXP];
    int k;
    (void)state;
    if (!mkdtemp(dir)) return -1;
    snprintf(path, sizeof path, "%s/naca0012_selig.dat", EG2D_TEST_DATA);
    f = fopen(path, "r");
    if (!f || !fgets(line, sizeof line, f)) return -1; /* the name line */
    while (sn < MAXP && fscanf(f, "%lf %lf", &sx[sn], &sy[sn]) == 2) ++sn;
    fclose(f);
    if (eg2d_curve_naca4("0012", 0, &c) != EG2D_OK) return -1;
    if (eg2d_curve_points(c, bn, EG2D_DIST_UNIFORM, 0, 0, x, y) != EG2D_OK) return -1;
    eg2d_curve_destroy(c);
    for (k = 0; k < bn; ++k) bx[k] = x[bn - 1 - k], by[k] = y[bn - 1 - k]; /* upper first, like Selig */
    return sn == 49 ? 0 : -1;
}

static int teardown(void **state) {
    char cmd[300];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd);
}

/* Writes `head`, then points idx[0..n) of (x, y) as "x<sep>y<end>", then `tail`. */
static const char *write_file(const char *name, const char *head, const double *x, const double *y, const int *idx,
                              int n, const char *sep, const char *end, const char *tail) {
    const char *p = path_of(name);
    FILE *f = fopen(p, "wb");
    int k;
    assert_non_null(f);
    fputs(head, f);
    for (k = 0; k < n; ++k) fprintf(f, "%.17g%s%.17g%s", x[idx[k]], sep, y[idx[k]], end);
    fputs(tail, f);
    fclose(f);
    return p;
}

static int order[MAXP], reversed[MAXP];
static void orders(int n) {
    int k;
    for (k = 0; k < n; ++k) order[k] = k, reversed[k] = n - 1 - k;
}

static void sample(const char *path, double *x, double *y) {
    eg2d_curve *c = NULL;
    const int rc = eg2d_curve_read_airfoil(path, &c);
    if (rc != EG2D_OK) print_message("%s\n", eg2d_last_error(NULL));
    assert_int_equal(rc, EG2D_OK);
    assert_int_equal(eg2d_curve_points(c, NS, EG2D_DIST_UNIFORM, 0, 0, x, y), EG2D_OK);
    eg2d_curve_destroy(c);
}

/* The largest distance between the sampled points of two files. */
static double distance(const char *a, const char *b) {
    double xa[NS], ya[NS], xb[NS], yb[NS], d = 0;
    int k;
    sample(a, xa, ya);
    sample(b, xb, yb);
    for (k = 0; k < NS; ++k) d = fmax(d, hypot(xa[k] - xb[k], ya[k] - yb[k]));
    return d;
}

static char standard[256];
static const char *standard_selig(void) {
    orders(sn);
    snprintf(standard, sizeof standard, "%s",
             write_file("standard.dat", "NACA 0012\n", sx, sy, order, sn, " ", "\n", ""));
    return standard;
}

static void refused(const char *path, const char *part1, const char *part2) {
    eg2d_curve *c = (eg2d_curve *)1;
    const char *msg;
    assert_int_equal(eg2d_curve_read_airfoil(path, &c), EG2D_ERR_ARGUMENT);
    assert_null(c);
    msg = eg2d_last_error(NULL);
    print_message("%s\n", msg);
    assert_non_null(strstr(msg, part1));
    if (part2) assert_non_null(strstr(msg, part2));
}

/* The first point is a point, not a name: the same curve with or without a name line. */
static void test_headerless_selig(void **state) {
    const char *std = standard_selig(), *p;
    (void)state;
    p = write_file("headerless.dat", "", sx, sy, order, sn, " ", "\n", "");
    assert_true(distance(std, p) == 0.0);
    p = write_file("header3.dat", "NASA SC(2)-0714\nSupercritical airfoil, t/c 14%\n  x/c   y/c\n\n", sx, sy, order, sn,
                   " ", "\n", "");
    assert_true(distance(std, p) == 0.0);
    p = write_file("notes.dat", "NACA 0012\n", sx, sy, order, sn, " ", "\n",
                   "\nNotes: smoothed 1996\nsource: a collection\n");
    assert_true(distance(std, p) == 0.0);
    p = write_file("crlf.dat", "NACA 0012\r\n\r\n", sx, sy, order, sn, ",\t", "\r\n", "\r\n");
    assert_true(distance(std, p) == 0.0);
    p = write_file("tabs.dat", "\xEF\xBB\xBF", sx, sy, order, sn, "\t", " \t\n", ""); /* UTF-8 BOM, no name */
    assert_true(distance(std, p) == 0.0);
    order[sn] = sn - 1; /* the closing point twice */
    p = write_file("dup.dat", "NACA 0012\n", sx, sy, order, sn + 1, " ", "\n", "");
    assert_true(distance(std, p) == 0.0);
}

/* Lednicer: upper surface LE -> TE, then lower LE -> TE, after the counts. */
static const char *lednicer(const char *name, int nu, int nl) {
    const int le = sn / 2; /* 24: (0, 0) */
    int idx[MAXP], k, n = 0;
    char head[64];
    for (k = le; k >= 0; --k) idx[n++] = k;
    for (k = le; k < sn; ++k) idx[n++] = k;
    snprintf(head, sizeof head, "NACA 0012\n%d. %d.\n\n", nu, nl);
    return write_file(name, head, sx, sy, idx, n, "  ", "\n", "");
}

static void test_lednicer(void **state) {
    const char *std = standard_selig();
    (void)state;
    assert_true(distance(std, lednicer("lednicer.dat", 25, 25)) == 0.0);
    refused(lednicer("lie_sum.dat", 25, 26), "announces 25 + 26 points but has 50",
            "the lower surface starts at line 29");
    refused(lednicer("lie_split.dat", 24, 26), "announces 24 + 26 points but has 50 (25 + 25", "correct the counts");
}

/* The C-grid (boundary and TFI) round a file equals the standard file's. */
static void same_grid(const char *a, const char *b) {
    enum { NI = 65, NJ = 17 };
    static double xa[NI * NJ], ya[NI * NJ], xb[NI * NJ], yb[NI * NJ];
    const char *paths[2] = {a, b};
    double *xs[2] = {xa, xb}, *ys[2] = {ya, yb}, d = 0;
    int k;
    for (k = 0; k < 2; ++k) {
        eg2d_grid *g;
        eg2d_curve *c;
        assert_int_equal(eg2d_curve_read_airfoil(paths[k], &c), EG2D_OK);
        assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
        assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_C), EG2D_OK);
        assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, xs[k], ys[k]), EG2D_OK);
        eg2d_destroy(g);
        eg2d_curve_destroy(c);
    }
    for (k = 0; k < NI * NJ; ++k) d = fmax(d, hypot(xa[k] - xb[k], ya[k] - yb[k]));
    print_message("C-grid %dx%d: largest node distance %.3g\n", NI, NJ, d);
    assert_true(d < 1e-12);
    assert_true(xa[0] > 50); /* the outflow behind the trailing edge, not before the leading edge */
}

/* Reversed, and from the leading edge: the same curve as the standard order. */
static void same_in_any_order(const double *x, const double *y, int n, int le, int closed) {
    const char *std, *p;
    int idx[2 * MAXP], k, m = 0;
    orders(n);
    std = write_file("std_order.dat", "", x, y, order, n, " ", "\n", "");
    p = write_file("rev.dat", "reversed\n", x, y, reversed, n, " ", "\n", "");
    print_message("reversed: %.3g\n", distance(std, p));
    assert_true(distance(std, p) < 1e-12);
    for (k = le; k < n; ++k) idx[m++] = k;
    for (k = closed; k <= le; ++k) idx[m++] = k; /* LE again at the end */
    p = write_file("le.dat", "from the leading edge\n", x, y, idx, m, " ", "\n", "");
    print_message("from the leading edge: %.3g\n", distance(std, p));
    assert_true(distance(std, p) < 1e-12);
    p = write_file("le_open.dat", "", x, y, idx, m - 1, " ", "\n", ""); /* LE only once */
    assert_true(distance(std, p) < 1e-12);
    for (k = 0; k < m; ++k) order[k] = idx[m - 1 - k];
    p = write_file("le_rev.dat", "", x, y, order, m, " ", "\n", "");
    assert_true(distance(std, p) < 1e-12);
    same_grid(std, p);
}

static void test_any_order(void **state) {
    (void)state;
    same_in_any_order(sx, sy, sn, sn / 2, 1); /* sharp: the TE point first and last */
    same_in_any_order(bx, by, bn, bn / 2, 0); /* blunt: the base closes the outline */
}

/* Shifted by 1e6 the first point is whole numbers > 1, yet a point of the outline. */
static void test_shifted(void **state) {
    double x[MAXP], y[MAXP], xa[NS], ya[NS], xb[NS], yb[NS], d = 0;
    int k;
    (void)state;
    for (k = 0; k < sn; ++k) x[k] = sx[k] + 1e6, y[k] = sy[k] + 1e6;
    orders(sn);
    sample(standard_selig(), xa, ya);
    sample(write_file("shifted.dat", "shifted\n", x, y, order, sn, " ", "\n", ""), xb, yb);
    for (k = 0; k < NS; ++k) d = fmax(d, hypot(xb[k] - 1e6 - xa[k], yb[k] - 1e6 - ya[k]));
    print_message("shifted by 1e6: %.3g from the standard file\n", d);
    assert_true(d < 1e-8);
}

static void test_bad_lines(void **state) {
    char *big = malloc(6000), msg_line[32];
    const char *p;
    FILE *f;
    int k;
    (void)state;
    assert_non_null(big);
    memset(big, '7', 5999);
    big[5999] = 0;
    p = path_of("long.dat");
    f = fopen(p, "wb");
    assert_non_null(f);
    fprintf(f, "name\n1 0\n0.5 0.1\n%s\n0 0\n0.5 -0.1\n1 0\n", big);
    fclose(f);
    refused(p, "line 4: longer than 4096 bytes", "\"777777777777777777777777777777777777777777777777777777777777\"...");
    assert_true(strlen(eg2d_last_error(NULL)) < 200 + strlen(p));
    free(big);
    p = path_of("binary.dat");
    f = fopen(p, "wb");
    assert_non_null(f);
    fputs("name\n1 0\n0.5 0.1\n", f);
    fwrite("\x01\xff\x00garbage\x7f\"", 1, 12, f);
    for (k = 0; k < 100; ++k) fputc('A' + k % 26, f);
    fputs("\n0 0\n0.5 -0.1\n1 0\n", f);
    fclose(f);
    refused(p, "line 4: not text (control bytes): \"\\x01\\xFF\\x00garbage\\x7F\\\"ABCDEF", "\"...");
    for (k = 0; eg2d_last_error(NULL)[k]; ++k) assert_true((unsigned char)eg2d_last_error(NULL)[k] >= 0x20);
    p = path_of("middle.dat");
    f = fopen(p, "w");
    assert_non_null(f);
    fputs("name\n1 0\n0.5 0.1\n0.3 0.1 0.2\n0 0\n0.5 -0.1\n1 0\n", f);
    fclose(f);
    snprintf(msg_line, sizeof msg_line, "line %d: \"0.3 0.1 0.2\"", 4);
    refused(p, msg_line, "is not a pair of numbers");
    p = path_of("nan.dat");
    f = fopen(p, "w");
    assert_non_null(f);
    fputs("1 0\n0.5 0.1\nnan 0\n0.5 -0.1\n1 0\n", f);
    fclose(f);
    refused(p, "line 3: non-finite coordinate", NULL);
    orders(sn); /* a name of two numbers is neither a point nor counts */
    refused(write_file("numbername.dat", "2032 12\n", sx, sy, order, sn, " ", "\n", ""),
            "line 1: (2032, 12) lies far off the outline", "not Lednicer's counts");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_headerless_selig), cmocka_unit_test(test_lednicer), cmocka_unit_test(test_any_order),
        cmocka_unit_test(test_shifted),          cmocka_unit_test(test_bad_lines),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
