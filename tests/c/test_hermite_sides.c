/* Hermite TFI at chosen sides, in both directions (EG2D_PARAM_HERMITE_SIDES):
 * on every domain of the elliptic-grid course notes at 33 x 33 and 65 x 65,
 * no folded cell, grid lines leaving each chosen side within 1 degree of its
 * normal and first cells of the height set. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "measure.h"
#include "eg2d.h"

static double *alloc(int n) {
    double *p = malloc(sizeof(double) * (size_t)n);
    assert_non_null(p);
    return p;
}

/* A domain, the sides chosen on it and a length scale: the first-cell height
 * is half the uniform spacing, scale / (n - 1). */
struct hermite_case {
    const char *name;
    int sides; /* mask of (1 << EG2D_SIDE_*) */
    double scale;
};

static const struct hermite_case kCases[] = {
    {"valley", 15, 1.0},
    {"almost-convex", 15, 1.0},
    {"swan", 15, 1.0},
    {"dome", 15, 1.5},
    {"antenna", 15, 3.0},
    {"annulus", (1 << EG2D_SIDE_JMIN) | (1 << EG2D_SIDE_JMAX), 2.0},
    {"rose", (1 << EG2D_SIDE_JMIN) | (1 << EG2D_SIDE_JMAX), 8.4},
};

static void set_domain(eg2d_grid *g, const char *name) {
    if (!strcmp(name, "annulus")) assert_int_equal(domain_set_annulus(g, 1.0, 3.0), EG2D_OK);
    else if (!strcmp(name, "rose")) assert_int_equal(domain_set_rose(g), EG2D_OK);
    else assert_int_equal(domain_set(g, name), EG2D_OK);
}

/* Largest deviation from 90 degrees and largest relative error of the
 * first-cell height at one chosen side. On a single block the nodes next to
 * a corner where two chosen sides meet are left out: node (1, 1) is the first
 * node off both sides and cannot lie on both normals at both heights unless
 * the corner is a right angle (eg2d.h, EG2D_PARAM_HERMITE_SIDES). */
static void side_errors(const double *x, const double *y, int n, int side, int periodic, int sides, double h,
                        double *angle, double *height) {
    /* k runs along the side; its first node meets side IMIN or JMIN */
    const int at_start = (side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX) ? EG2D_SIDE_IMIN : EG2D_SIDE_JMIN;
    const int at_end = (side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX) ? EG2D_SIDE_IMAX : EG2D_SIDE_JMAX;
    int k0 = 1, k1 = n - 1;
    double lo, hi;
    if (periodic) k0 = 0;
    else {
        if (sides & (1 << at_start)) k0 = 2;
        if (sides & (1 << at_end)) k1 = n - 2;
    }
    measure_wall(x, y, n, n, side, periodic, k0, k1, angle, &lo, &hi);
    *height = fmax(fabs(lo - h), fabs(hi - h)) / h;
}

static void test_hermite_all_domains(void **state) {
    const int sizes[2] = {33, 65};
    size_t c;
    int s, side;
    (void)state;
    for (c = 0; c < sizeof kCases / sizeof kCases[0]; ++c)
        for (s = 0; s < 2; ++s) {
            const int n = sizes[s];
            const struct hermite_case *k = &kCases[c];
            const double h = 0.5 * k->scale / (n - 1);
            const int periodic = !strcmp(k->name, "annulus") || !strcmp(k->name, "rose");
            double *x = alloc(n * n), *y = alloc(n * n), folded, tfi_folded;
            eg2d_grid *g;
            assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
            set_domain(g, k->name);
            assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
            assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &tfi_folded), EG2D_OK);
            assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SIDES, k->sides), EG2D_OK);
            for (side = 0; side < 4; ++side)
                if (k->sides & (1 << side))
                    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_HEIGHT_JMIN + side, h), EG2D_OK);
            assert_int_equal(eg2d_initialize(g, EG2D_INIT_HERMITE), EG2D_OK);
            assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
            assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
            print_message("%-13s %2dx%-2d folded %g (linear TFI %g), h = %.4g:", k->name, n, n, folded, tfi_folded, h);
            for (side = 0; side < 4; ++side) {
                double angle, height;
                if (!(k->sides & (1 << side))) continue;
                side_errors(x, y, n, side, periodic, k->sides, h, &angle, &height);
                print_message(" side %d %.2e deg %.1e rel", side, angle, height);
                assert_true(angle < 1.0);
                /* The first node is put at r + h n exactly; what is left is
                 * the round-off of solving for the derivatives (1e-15 of the
                 * domain's size, here about 1e-13 of h) and of the distance. */
                assert_true(height < 1e-9);
            }
            print_message("\n");
            assert_true(folded == 0);
            eg2d_destroy(g);
            free(x);
            free(y);
        }
}

/* Height 0: alpha times the grid line's length over its cells, here
 * 0.5 x 2 / 32 on the annulus 1 <= r <= 3, and only at the chosen side. */
static void test_hermite_default_height(void **state) {
    const int n = 33;
    double *x = alloc(n * n), *y = alloc(n * n), worst = 0;
    eg2d_grid *g;
    int i;
    (void)state;
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    assert_int_equal(domain_set_annulus(g, 1.0, 3.0), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SIDES, 1 << EG2D_SIDE_JMIN), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SPACING, 0.5), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_HERMITE), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (i = 0; i < n; ++i) worst = fmax(worst, fabs(hypot(x[i + n], y[i + n]) - (1 + 0.5 * 2.0 / (n - 1))));
    assert_true(worst < 1e-12);
    eg2d_destroy(g);
    free(x);
    free(y);
}

/* The errors: a side the topology lacks; first cells too large for the
 * swan's acute corners (the grid is left as it was); bad parameter values. */
static void test_hermite_errors(void **state) {
    const int n = 33;
    double *x = alloc(n * n), *y = alloc(n * n), *x2 = alloc(n * n), *y2 = alloc(n * n);
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    assert_int_equal(domain_set_annulus(g, 1.0, 3.0), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SIDES, 1 << EG2D_SIDE_IMIN), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_HERMITE), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(g), "IMIN"));
    eg2d_destroy(g);
    assert_int_equal(eg2d_create(n, n, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "swan"), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SIDES, 15), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_HEIGHT_JMAX, 2.0 / (n - 1)), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_HEIGHT_IMIN, 2.0 / (n - 1)), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_HERMITE), EG2D_ERR_FOLDED);
    assert_non_null(strstr(eg2d_last_error(g), "folds"));
    assert_int_equal(eg2d_get_coordinates(g, x2, y2), EG2D_OK);
    assert_memory_equal(x, x2, sizeof(double) * (size_t)(n * n));
    assert_memory_equal(y, y2, sizeof(double) * (size_t)(n * n));
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SIDES, 16), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SIDES, 1.5), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_HEIGHT_IMAX, -1), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
    free(x);
    free(y);
    free(x2);
    free(y2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hermite_all_domains),
        cmocka_unit_test(test_hermite_default_height),
        cmocka_unit_test(test_hermite_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
