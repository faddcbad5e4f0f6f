/* Curves, arc length, distributions, airfoils and side directions: each
 * checked against an independent computation (test-side quadrature, closed
 * forms, a second file format). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eg2d.h"

#define PI 3.14159265358979323846

static double *alloc(int n) {
    double *p = malloc(sizeof(double) * (size_t)n);
    assert_non_null(p);
    return p;
}

/* A circle of radius 2 about (1, -1), traversed at a non-uniform speed. */
static void circle_fn(void *user, double t, double *x, double *y) {
    const double th = 2 * PI * (t + 0.1 * sin(2 * PI * t));
    (void)user;
    *x = 1 + 2 * cos(th);
    *y = -1 + 2 * sin(th);
}

static void test_circle_arc_length_points(void **state) {
    const int n = 37;
    double *x = alloc(n), *y = alloc(n), L, worst = 0;
    eg2d_curve *c;
    int k;
    (void)state;
    assert_int_equal(eg2d_curve_function(circle_fn, NULL, &c), EG2D_OK);
    assert_int_equal(eg2d_curve_length(c, &L), EG2D_OK);
    assert_true(fabs(L - 4 * PI) < 1e-10 * 4 * PI);
    assert_int_equal(eg2d_curve_points(c, n, EG2D_DIST_UNIFORM, 0, 0, x, y), EG2D_OK);
    for (k = 1; k < n; ++k) { /* the arc between points is 2 * (angle step) */
        double d = atan2(y[k] + 1, x[k] - 1) - atan2(y[k - 1] + 1, x[k - 1] - 1);
        if (d < 0) d += 2 * PI;
        worst = fmax(worst, fabs(2 * d - L / (n - 1)) / (L / (n - 1)));
    }
    print_message("circle: arc-length spacing relative error %.2e\n", worst);
    assert_true(worst < 1e-8);
    eg2d_curve_destroy(c);
    free(x);
    free(y);
}

/* An arc of length L turning by 2 radians, starting at (x0, 0.3), t
 * proportional to its arc length: a piece much shorter than its distance from
 * the origin (a short formula side, say a leg 1e-5 long at a trailing edge). */
struct small_arc { double x0, L; };
static void small_arc_fn(void *user, double t, double *x, double *y) {
    const struct small_arc *a = user;
    *x = a->x0 + a->L * sin(2 * t) / 2;
    *y = 0.3 + a->L * (1 - cos(2 * t)) / 2;
}

/* The arc length of such a piece cannot converge to 1e-14 of its length
 * (its points carry round-off of 1e-16 of their distance from the origin,
 * which its finite differences multiply): it converges to that round-off
 * instead, where it used to fail after 65536 panels. */
static void test_small_curve_far_from_origin(void **state) {
    static const double lengths[3] = {1.65e-4, 1e-5, 1e-7}, origins[3] = {0.89, 10, 1000};
    int a, b, k;
    (void)state;
    for (a = 0; a < 3; ++a)
        for (b = 0; b < 3; ++b) {
            struct small_arc arc = {origins[b], lengths[a]};
            /* the points' round-off over the length: eps r / L */
            const double floor = 2.2e-16 * origins[b] / lengths[a];
            double L, worst = 0;
            eg2d_curve *c;
            assert_int_equal(eg2d_curve_function(small_arc_fn, &arc, &c), EG2D_OK);
            assert_int_equal(eg2d_curve_length(c, &L), EG2D_OK);
            for (k = 0; k <= 50; ++k) {
                double x, y, xe, ye;
                assert_int_equal(eg2d_curve_evaluate(c, k / 50.0, &x, &y), EG2D_OK);
                small_arc_fn(&arc, k / 50.0, &xe, &ye);
                worst = fmax(worst, hypot(x - xe, y - ye) / arc.L);
            }
            print_message("arc %g at x = %g: length error %.1e, point error %.1e of its length (round-off %.1e)\n",
                          arc.L, arc.x0, fabs(L - arc.L) / arc.L, worst, floor);
            assert_true(fabs(L - arc.L) <= fmax(1e-10, 1e3 * floor) * arc.L);
            assert_true(worst <= fmax(1e-10, 1e3 * floor));
            eg2d_curve_destroy(c);
        }
}

/* NACA0012 (sharp TE) on one surface as a function of phi, x = (1 - cos phi)/2:
 * the test's own arc length Lambda(phi) from the leading edge by composite
 * 8-point Gauss-Legendre. */
static void naca_phi(double phi, double *x, double *y) {
    const double xc = 0.5 * (1 - cos(phi));
    *x = xc;
    *y = 0.6 * (0.2969 * sin(0.5 * phi) - 0.1260 * xc - 0.3516 * xc * xc + 0.2843 * xc * xc * xc -
                0.1036 * xc * xc * xc * xc);
}
static double naca_speed(double phi) {
    const double h = 1e-4;
    double x1, y1, x2, y2, x3, y3, x4, y4;
    naca_phi(phi - 2 * h, &x1, &y1);
    naca_phi(phi - h, &x2, &y2);
    naca_phi(phi + h, &x3, &y3);
    naca_phi(phi + 2 * h, &x4, &y4);
    return hypot((x1 - 8 * x2 + 8 * x3 - x4) / (12 * h), (y1 - 8 * y2 + 8 * y3 - y4) / (12 * h));
}
static double naca_lambda(double phi) {
    static const double g[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    const int panels = 400;
    double sum = 0;
    int p, k;
    for (p = 0; p < panels; ++p) {
        const double a = phi * p / panels, b = phi * (p + 1) / panels, m = 0.5 * (a + b), h = 0.5 * (b - a);
        for (k = 0; k < 4; ++k) sum += h * w[k] * (naca_speed(m - h * g[k]) + naca_speed(m + h * g[k]));
    }
    return sum;
}

static void test_naca0012_arc_length_points(void **state) {
    const int n = 41;
    double *x = alloc(n), *y = alloc(n), *s = alloc(n), L, half, worst = 0;
    eg2d_curve *c;
    int k;
    (void)state;
    assert_int_equal(eg2d_curve_naca4("0012", EG2D_NACA_CLOSED_TE, &c), EG2D_OK);
    assert_int_equal(eg2d_curve_length(c, &L), EG2D_OK);
    half = naca_lambda(PI);
    assert_true(fabs(L - 2 * half) < 1e-10 * L);
    assert_int_equal(eg2d_curve_points(c, n, EG2D_DIST_UNIFORM, 0, 0, x, y), EG2D_OK);
    assert_true(fabs(x[0] - 1) < 1e-14 && fabs(y[0]) < 1e-14);
    assert_true(fabs(x[(n - 1) / 2]) < 1e-14);      /* leading edge in the middle */
    assert_true(y[5] < 0 && y[n - 6] > 0);          /* lower surface first */
    for (k = 0; k < n; ++k) { /* arc length from the TE along the lower surface */
        const double phi = acos(fmax(-1.0, fmin(1.0, 1 - 2 * x[k])));
        s[k] = k <= (n - 1) / 2 ? half - naca_lambda(phi) : half + naca_lambda(phi);
    }
    for (k = 1; k < n; ++k) worst = fmax(worst, fabs((s[k] - s[k - 1]) / (L / (n - 1)) - 1));
    print_message("NACA0012: length %.12f, arc-length spacing relative error %.2e\n", L, worst);
    assert_true(worst < 1e-8);
    eg2d_curve_destroy(c);
    free(x);
    free(y);
    free(s);
}

static void test_polyline_and_spline(void **state) {
    const double px[3] = {0, 3, 3}, py[3] = {0, 0, 4};
    double x[8], y[8], L;
    eg2d_curve *c;
    int k;
    (void)state;
    assert_int_equal(eg2d_curve_polyline(3, px, py, &c), EG2D_OK);
    assert_int_equal(eg2d_curve_length(c, &L), EG2D_OK);
    assert_true(fabs(L - 7) < 1e-13);
    assert_int_equal(eg2d_curve_points(c, 8, EG2D_DIST_UNIFORM, 0, 0, x, y), EG2D_OK);
    for (k = 0; k < 8; ++k) { /* s = k: x = min(k, 3), y = max(k - 3, 0) */
        assert_true(fabs(x[k] - fmin(k, 3)) < 1e-12);
        assert_true(fabs(y[k] - fmax(k - 3, 0)) < 1e-12);
    }
    eg2d_curve_destroy(c);
    { /* a periodic spline through 64 points of the unit circle: length 2 pi to O(h^4) */
        double cx[65], cy[65];
        for (k = 0; k <= 64; ++k) {
            cx[k] = cos(2 * PI * k / 64);
            cy[k] = sin(2 * PI * k / 64);
        }
        cx[64] = cx[0];
        cy[64] = cy[0];
        assert_int_equal(eg2d_curve_spline(65, cx, cy, &c), EG2D_OK);
        assert_int_equal(eg2d_curve_length(c, &L), EG2D_OK);
        print_message("periodic spline circle, 64 intervals: length error %.2e\n", fabs(L - 2 * PI));
        assert_true(fabs(L - 2 * PI) < 1e-6);
        assert_int_equal(eg2d_curve_evaluate(c, 0.25, &x[0], &y[0]), EG2D_OK);
        assert_true(fabs(x[0]) < 1e-6 && fabs(y[0] - 1) < 1e-6);
        eg2d_curve_destroy(c);
    }
}

static void test_distributions_end_spacings(void **state) {
    const int n = 21, N = n - 1;
    double s[21];
    int k;
    (void)state;
    {
        const double beta = 3;
        assert_int_equal(eg2d_distribution(EG2D_DIST_EXPONENTIAL, n, beta, 0, s), EG2D_OK);
        assert_true(fabs(s[1] - (exp(beta / N) - 1) / (exp(beta) - 1)) < 1e-14);
        assert_true(fabs((1 - s[N - 1]) - (exp(beta) - exp(beta * (N - 1) / N)) / (exp(beta) - 1)) < 1e-14);
        assert_true(s[1] < 1.0 / N && 1 - s[N - 1] > 1.0 / N); /* clusters at s = 0 */
    }
    {
        const double d = 4, first = 1 + tanh(d * (1.0 / N - 1) / 2) / tanh(d / 2);
        const double last = -tanh(-d / (2.0 * N)) / tanh(d / 2);
        assert_int_equal(eg2d_distribution(EG2D_DIST_TANH_ONE, n, d, 0, s), EG2D_OK);
        assert_true(fabs(s[1] - first) < 1e-14 && fabs((1 - s[N - 1]) - last) < 1e-14);
        assert_true(first < 1.0 / N && last > 1.0 / N);
    }
    {
        const double b = 3, c = 0.5, A = tanh(-b * c), B = tanh(b * (1 - c));
        assert_int_equal(eg2d_distribution(EG2D_DIST_TANH_TWO, n, b, c, s), EG2D_OK);
        assert_true(fabs(s[1] - (tanh(b * (1.0 / N - c)) - A) / (B - A)) < 1e-14);
        assert_true(fabs(s[N / 2] - 0.5) < 1e-14);                 /* symmetric about c = 1/2 */
        assert_true(fabs(s[1] - (1 - s[N - 1])) < 1e-14);
        assert_true(s[N / 2 + 1] - s[N / 2] > s[1] - s[0]);        /* sparsest at u = c */
    }
    { /* c = 1 is eq 2.13 with delta = 2b */
        double t[21];
        assert_int_equal(eg2d_distribution(EG2D_DIST_TANH_TWO, n, 1.5, 1.0, s), EG2D_OK);
        assert_int_equal(eg2d_distribution(EG2D_DIST_TANH_ONE, n, 3.0, 0, t), EG2D_OK);
        for (k = 0; k < n; ++k) assert_true(fabs(s[k] - t[k]) < 1e-14);
    }
    assert_int_equal(eg2d_distribution(EG2D_DIST_UNIFORM, n, 0, 0, s), EG2D_OK);
    for (k = 0; k < n; ++k) assert_true(fabs(s[k] - (double)k / N) < 1e-15);
}

static void check_vinokur(int n, double ds0, double ds1) {
    double *s = alloc(n), e0, e1;
    int k;
    assert_int_equal(eg2d_distribution(EG2D_DIST_VINOKUR, n, ds0, ds1, s), EG2D_OK);
    e0 = fabs((s[1] - s[0]) / ds0 - 1);
    e1 = fabs((s[n - 1] - s[n - 2]) / ds1 - 1);
    print_message("Vinokur n = %d, spacings %.1e, %.1e: relative errors %.1e, %.1e\n", n, ds0, ds1, e0, e1);
    assert_true(e0 < 1e-6 && e1 < 1e-6);
    assert_true(s[0] == 0 && s[n - 1] == 1);
    for (k = 1; k < n; ++k) assert_true(s[k] > s[k - 1]);
    free(s);
}

static void test_vinokur_hits_both_spacings(void **state) {
    double x[33], y[33];
    const double px[2] = {0, 10}, py[2] = {0, 0};
    eg2d_curve *c;
    (void)state;
    check_vinokur(41, 1e-3, 5e-2);    /* B > 1: the tanh branch */
    check_vinokur(65, 1e-5, 1e-4);    /* strong stretching both ends */
    check_vinokur(11, 0.15, 0.12);    /* B < 1: the tan branch */
    check_vinokur(21, 0.05, 0.05);    /* B = 1: uniform */
    /* On a curve the spacings are in its length units. */
    assert_int_equal(eg2d_curve_polyline(2, px, py, &c), EG2D_OK);
    assert_int_equal(eg2d_curve_points(c, 33, EG2D_DIST_VINOKUR, 0.01, 0.5, x, y), EG2D_OK);
    assert_true(fabs((x[1] - x[0]) / 0.01 - 1) < 1e-6);
    assert_true(fabs((x[32] - x[31]) / 0.5 - 1) < 1e-6);
    eg2d_curve_destroy(c);
}

static void test_distribution_errors(void **state) {
    double s[5];
    (void)state;
    assert_int_equal(eg2d_distribution(99, 5, 0, 0, s), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "distribution = 99"));
    assert_int_equal(eg2d_distribution(EG2D_DIST_VINOKUR, 5, 0.6, 0.5, s), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "leave no room"));
    assert_int_equal(eg2d_distribution(EG2D_DIST_EXPONENTIAL, 5, 0, 0, s), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "beta = 0"));
    assert_int_equal(eg2d_distribution(EG2D_DIST_TANH_TWO, 5, 2, 1.5, s), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "c = 1.5"));
    assert_int_equal(eg2d_distribution(EG2D_DIST_UNIFORM, 1, 0, 0, s), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_distribution(EG2D_DIST_UNIFORM, 5, 0, 0, NULL), EG2D_ERR_ARGUMENT);
}

/* The solved parameter gives the wanted first spacing (through eg2d_distribution,
 * to 1e-10 relative) for every function and several n. */
static void check_first_spacing(int dist, int n, double first, double p2) {
    double *s = alloc(n), p1 = 0, err;
    const int rc = eg2d_distribution_parameter(dist, n, first, p2, &p1);
    if (rc != EG2D_OK) fail_msg("dist %d n %d first %g p2 %g: %s", dist, n, first, p2, eg2d_last_error(NULL));
    assert_int_equal(eg2d_distribution(dist, n, p1, p2, s), EG2D_OK);
    err = fabs((s[1] - s[0]) / first - 1);
    if (!(err < 1e-10)) fail_msg("dist %d n %d first %g p2 %g: p1 %.17g gives %.17g (relative error %.1e)", dist, n,
                                 first, p2, p1, s[1] - s[0], err);
    free(s);
}

static void test_distribution_parameter(void **state) {
    static const int ns[] = {5, 17, 65, 257, 1025};
    static const double below[] = {1e-12, 1e-8, 1e-5, 1e-3}; /* fractions of the uniform 1/(n-1) */
    size_t a, b;
    double p1;
    (void)state;
    for (a = 0; a < sizeof ns / sizeof ns[0]; ++a) {
        const int n = ns[a];
        const double uniform = 1.0 / (n - 1);
        for (b = 0; b < sizeof below / sizeof below[0]; ++b) {
            const double h = below[b] * uniform;
            check_first_spacing(EG2D_DIST_EXPONENTIAL, n, h, 0);
            check_first_spacing(EG2D_DIST_TANH_ONE, n, h, 0);
            check_first_spacing(EG2D_DIST_TANH_TWO, n, h, 0.5);
            check_first_spacing(EG2D_DIST_TANH_TWO, n, h, 1.0);
            check_first_spacing(EG2D_DIST_VINOKUR, n, h, 0.5 * uniform);
        }
        check_first_spacing(EG2D_DIST_EXPONENTIAL, n, 0.5 * uniform, 0);
        check_first_spacing(EG2D_DIST_TANH_ONE, n, 0.999 * uniform, 0);
        check_first_spacing(EG2D_DIST_EXPONENTIAL, n, 3 * uniform, 0); /* beta < 0 widens the first interval */
        check_first_spacing(EG2D_DIST_TANH_TWO, n, 3 * uniform, 0.0);   /* c = 0 clusters at s = 1 */
    }
    /* TANH_TWO with 1/(n-1) < c < 1/2: the first spacing rises, then falls with b; the smallest b is given */
    assert_int_equal(eg2d_distribution_parameter(EG2D_DIST_TANH_TWO, 11, 0.15, 0.2, &p1), EG2D_OK);
    check_first_spacing(EG2D_DIST_TANH_TWO, 11, 0.15, 0.2);
    {
        double q = 0, s[11];
        assert_int_equal(eg2d_distribution_parameter(EG2D_DIST_TANH_TWO, 11, 1e-4, 0.2, &q), EG2D_OK);
        assert_true(q > p1); /* the same c reaches small spacings on the falling side */
        assert_int_equal(eg2d_distribution(EG2D_DIST_TANH_TWO, 11, p1 * 0.5, 0.2, s), EG2D_OK);
        assert_true(s[1] > 0.1 && s[1] < 0.15); /* below the answer it has not risen to 0.15 yet */
    }
}

/* Unreachable spacings: EG2D_ERR_ARGUMENT naming first_spacing, *p1 untouched. */
static void check_unreachable(int dist, int n, double first, double p2, const char *says) {
    double p1 = -123.5;
    assert_int_equal(eg2d_distribution_parameter(dist, n, first, p2, &p1), EG2D_ERR_ARGUMENT);
    assert_true(p1 == -123.5);
    if (!strstr(eg2d_last_error(NULL), says)) fail_msg("\"%s\" lacks \"%s\"", eg2d_last_error(NULL), says);
}

static void test_distribution_parameter_errors(void **state) {
    (void)state;
    check_unreachable(EG2D_DIST_TANH_ONE, 11, 0.1, 0, "first_spacing = 0.1 is the uniform spacing");
    check_unreachable(EG2D_DIST_EXPONENTIAL, 11, 0.1, 0, "that is EG2D_DIST_UNIFORM");
    check_unreachable(EG2D_DIST_TANH_TWO, 11, 0.1, 0.5, "first_spacing = 0.1 is the uniform spacing");
    check_unreachable(EG2D_DIST_TANH_ONE, 11, 0.2, 0, "first_spacing = 0.2: not reachable with n = 11");
    check_unreachable(EG2D_DIST_TANH_TWO, 11, 0.2, 0.5, "over tanh strength b in (0, 350]");
    check_unreachable(EG2D_DIST_TANH_TWO, 11, 0.01, 0.0, "and c = 0: over tanh strength b");
    check_unreachable(EG2D_DIST_TANH_TWO, 11, 0.3, 0.2, "stays within"); /* above the rise's peak */
    check_unreachable(EG2D_DIST_EXPONENTIAL, 11, 1e-300, 0, "over exponential beta in [-700, 700]");
    check_unreachable(EG2D_DIST_EXPONENTIAL, 1001, 0.9, 0, "0.503415]"); /* beta = -700 */
    check_unreachable(EG2D_DIST_TANH_ONE, 101, 1e-310, 0, "not reachable");
    check_unreachable(EG2D_DIST_VINOKUR, 11, 0.6, 0.5, "leave no room");
    check_unreachable(EG2D_DIST_UNIFORM, 11, 0.1, 0, "has no parameter");
    check_unreachable(99, 11, 0.01, 0, "distribution = 99");
    check_unreachable(EG2D_DIST_TANH_TWO, 11, 0.01, 1.5, "c = 1.5");
    check_unreachable(EG2D_DIST_TANH_ONE, 1, 0.01, 0, "n = 1");
    check_unreachable(EG2D_DIST_TANH_ONE, 11, 0, 0, "first_spacing = 0: must be in (0, 1)");
    check_unreachable(EG2D_DIST_TANH_ONE, 11, NAN, 0, "first_spacing = nan");
    check_unreachable(EG2D_DIST_TANH_ONE, 11, 0.01, INFINITY, "p2 = inf");
    assert_int_equal(eg2d_distribution_parameter(EG2D_DIST_TANH_ONE, 11, 0.01, 0, NULL), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "p1 is NULL"));
}

static void test_airfoil_files(void **state) {
    eg2d_curve *selig, *led, *naca, *c = (eg2d_curve *)1;
    double xs[61], ys[61], xl[61], yl[61], xn[61], yn[61], dev = 0;
    int k;
    char path[1024];
    FILE *f;
    (void)state;
    snprintf(path, sizeof path, "%s/naca0012_selig.dat", EG2D_TEST_DATA);
    assert_int_equal(eg2d_curve_read_airfoil(path, &selig), EG2D_OK);
    snprintf(path, sizeof path, "%s/naca0012_lednicer.dat", EG2D_TEST_DATA);
    assert_int_equal(eg2d_curve_read_airfoil(path, &led), EG2D_OK);
    assert_int_equal(eg2d_curve_naca4("0012", EG2D_NACA_CLOSED_TE, &naca), EG2D_OK);
    assert_int_equal(eg2d_curve_points(selig, 61, EG2D_DIST_UNIFORM, 0, 0, xs, ys), EG2D_OK);
    assert_int_equal(eg2d_curve_points(led, 61, EG2D_DIST_UNIFORM, 0, 0, xl, yl), EG2D_OK);
    assert_int_equal(eg2d_curve_points(naca, 61, EG2D_DIST_UNIFORM, 0, 0, xn, yn), EG2D_OK);
    for (k = 0; k < 61; ++k) {
        assert_true(fabs(xs[k] - xl[k]) < 1e-12 && fabs(ys[k] - yl[k]) < 1e-12); /* the two formats agree */
        dev = fmax(dev, hypot(xs[k] - xn[k], ys[k] - yn[k]));
    }
    print_message("Selig file (49 points) vs analytic NACA0012: largest distance %.2e\n", dev);
    assert_true(dev < 2e-3);
    assert_true(ys[10] < 0 && ys[50] > 0); /* oriented like eg2d_curve_naca4 */
    eg2d_curve_destroy(selig);
    eg2d_curve_destroy(led);
    eg2d_curve_destroy(naca);
    assert_int_equal(eg2d_curve_read_airfoil("/nonexistent/eg2d.dat", &c), EG2D_ERR_IO);
    assert_null(c);
    assert_non_null(strstr(eg2d_last_error(NULL), "/nonexistent/eg2d.dat"));
    f = tmpfile();
    assert_non_null(f);
    {
        char tmpl[] = "/tmp/eg2d_airfoil_XXXXXX";
        int fd = mkstemp(tmpl);
        FILE *w;
        assert_true(fd >= 0);
        w = fdopen(fd, "w");
        fputs("bad\n1 0\n0.5 0.1 junk\n0 0\n0.5 -0.1\n1 0\n", w);
        fclose(w);
        assert_int_equal(eg2d_curve_read_airfoil(tmpl, &c), EG2D_ERR_ARGUMENT);
        assert_non_null(strstr(eg2d_last_error(NULL), "line 3"));
        remove(tmpl);
    }
    fclose(f);
    assert_int_equal(eg2d_curve_naca4("00a2", 0, &c), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_curve_naca4("2012", 0, &c), EG2D_ERR_ARGUMENT); /* camber without position */
    assert_int_equal(eg2d_curve_naca4("0012", 0, &c), EG2D_OK);          /* open TE: not closed */
    assert_int_equal(eg2d_curve_evaluate(c, 1.0, &xs[0], &ys[0]), EG2D_OK);
    assert_true(fabs(ys[0] - 0.6 * (0.2969 - 0.1260 - 0.3516 + 0.2843 - 0.1015)) < 1e-14);
    eg2d_curve_destroy(c);
}

static void test_first_cell_height(void **state) {
    double h1, h2;
    (void)state;
    /* Re = 1e6: Cf = (12 - 0.65)^-2.3 = 3.7451e-3, height = 1/(1e6 sqrt(Cf/2)) = 2.3108e-5 */
    assert_int_equal(eg2d_first_cell_height(1.0, 1e6, 1.0, &h1), EG2D_OK);
    assert_true(fabs(h1 / 2.310788718418812e-05 - 1) < 1e-12);
    assert_int_equal(eg2d_first_cell_height(2.0, 1e6, 3.0, &h2), EG2D_OK);
    assert_true(fabs(h2 / (6 * h1) - 1) < 1e-14);
    assert_int_equal(eg2d_first_cell_height(1.0, 10, 1.0, &h1), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "Reynolds number 10"));
    assert_int_equal(eg2d_first_cell_height(-1.0, 1e6, 1.0, &h1), EG2D_ERR_ARGUMENT);
}

static void line_fn(void *user, double t, double *x, double *y) {
    const double *p = (const double *)user; /* x0, y0, x1, y1 */
    *x = p[0] + t * (p[2] - p[0]);
    *y = p[1] + t * (p[3] - p[1]);
}

static void test_opposite_sides_direction(void **state) {
    eg2d_grid *g;
    eg2d_curve *bottom, *top, *left;
    const double b[4] = {0, 0, 1, 0}, t_rev[4] = {1, 1, 0, 1}, l[4] = {0, 0, 0, 1};
    double x[9 * 5], y[9 * 5];
    (void)state;
    assert_int_equal(eg2d_curve_function(line_fn, (void *)b, &bottom), EG2D_OK);
    assert_int_equal(eg2d_curve_function(line_fn, (void *)t_rev, &top), EG2D_OK);
    assert_int_equal(eg2d_curve_function(line_fn, (void *)l, &left), EG2D_OK);
    assert_int_equal(eg2d_create(9, 5, &g), EG2D_OK);
    assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMIN, bottom, EG2D_DIST_UNIFORM, 0, 0, 0), EG2D_OK);
    /* Opposite side only: detected from the direction. */
    assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMAX, top, EG2D_DIST_UNIFORM, 0, 0, 0), EG2D_ERR_BOUNDARY);
    assert_non_null(strstr(eg2d_last_error(g), "runs against the grid"));
    assert_non_null(strstr(eg2d_last_error(g), "side JMIN"));
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_ERR_STATE); /* the failed call set nothing */
    assert_non_null(strstr(eg2d_last_error(g), "IMAX, JMAX, IMIN"));
    /* With an adjacent side set: detected from the corner. */
    assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_IMIN, left, EG2D_DIST_UNIFORM, 0, 0, 0), EG2D_OK);
    assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMAX, top, EG2D_DIST_UNIFORM, 0, 0, 0), EG2D_ERR_BOUNDARY);
    assert_non_null(strstr(eg2d_last_error(g), "corner it shares with side IMIN"));
    assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMAX, top, EG2D_DIST_UNIFORM, 0, 0, EG2D_CURVE_ORIENT), EG2D_OK);
    assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_IMAX, left, EG2D_DIST_UNIFORM, 0, 0, 0), EG2D_ERR_BOUNDARY);
    assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMAX, top, EG2D_DIST_UNIFORM, 0, 0, 8), EG2D_ERR_ARGUMENT);
    {
        const double r[4] = {1, 0, 1, 1};
        eg2d_curve *right;
        assert_int_equal(eg2d_curve_function(line_fn, (void *)r, &right), EG2D_OK);
        assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_IMAX, right, EG2D_DIST_UNIFORM, 0, 0, 0), EG2D_OK);
        eg2d_curve_destroy(right);
    }
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    assert_true(fabs(x[9 * 4] - 0) < 1e-15 && fabs(x[9 * 4 + 8] - 1) < 1e-15); /* JMAX reversed: (0,1)..(1,1) */
    assert_true(fabs(x[9 * 2 + 4] - 0.5) < 1e-11 && fabs(y[9 * 2 + 4] - 0.5) < 1e-11);
    eg2d_destroy(g);
    /* O-grid: a clockwise outer circle against a counter-clockwise inner one. */
    {
        eg2d_curve *inner, *outer;
        double cx[33], cy[33];
        int k;
        for (k = 0; k <= 32; ++k) {
            cx[k] = cos(2 * PI * k / 32);
            cy[k] = sin(2 * PI * k / 32);
        }
        cx[32] = cx[0];
        cy[32] = cy[0];
        assert_int_equal(eg2d_curve_polyline(33, cx, cy, &inner), EG2D_OK);
        for (k = 0; k <= 32; ++k) {
            cx[k] *= 3;
            cy[k] *= -3;
        }
        assert_int_equal(eg2d_curve_polyline(33, cx, cy, &outer), EG2D_OK);
        assert_int_equal(eg2d_create(33, 9, &g), EG2D_OK);
        assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_O), EG2D_OK);
        assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMIN, inner, EG2D_DIST_UNIFORM, 0, 0, 0), EG2D_OK);
        assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMAX, outer, EG2D_DIST_UNIFORM, 0, 0, 0), EG2D_ERR_BOUNDARY);
        assert_non_null(strstr(eg2d_last_error(g), "clockwise but side JMIN runs counter-clockwise"));
        assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMAX, outer, EG2D_DIST_UNIFORM, 0, 0, EG2D_CURVE_REVERSE),
                         EG2D_OK);
        assert_int_equal(eg2d_solve(g), EG2D_OK);
        eg2d_destroy(g);
        eg2d_curve_destroy(inner);
        eg2d_curve_destroy(outer);
    }
    eg2d_curve_destroy(bottom);
    eg2d_curve_destroy(top);
    eg2d_curve_destroy(left);
}

static void nan_fn(void *user, double t, double *x, double *y) {
    (void)user;
    *x = t;
    *y = t > 0.7 ? NAN : 0;
}

static void test_curve_errors(void **state) {
    eg2d_curve *c = (eg2d_curve *)1;
    const double x[2] = {1, 1}, y[2] = {2, 2};
    double v;
    (void)state;
    assert_int_equal(eg2d_curve_function(nan_fn, NULL, &c), EG2D_ERR_ARGUMENT);
    assert_null(c);
    assert_non_null(strstr(eg2d_last_error(NULL), "must be finite"));
    assert_int_equal(eg2d_curve_function(NULL, NULL, &c), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_curve_polyline(2, x, y, &c), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "all lie at (1, 2)"));
    assert_int_equal(eg2d_curve_polyline(1, x, y, &c), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_curve_length(NULL, &v), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "eg2d_curve_length: curve is NULL"));
    eg2d_curve_destroy(NULL);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_circle_arc_length_points),
        cmocka_unit_test(test_small_curve_far_from_origin),
        cmocka_unit_test(test_naca0012_arc_length_points),
        cmocka_unit_test(test_polyline_and_spline),
        cmocka_unit_test(test_distributions_end_spacings),
        cmocka_unit_test(test_vinokur_hits_both_spacings),
        cmocka_unit_test(test_distribution_errors),
        cmocka_unit_test(test_distribution_parameter),
        cmocka_unit_test(test_distribution_parameter_errors),
        cmocka_unit_test(test_airfoil_files),
        cmocka_unit_test(test_first_cell_height),
        cmocka_unit_test(test_opposite_sides_direction),
        cmocka_unit_test(test_curve_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
