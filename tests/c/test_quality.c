/* Quality metrics: hand-computed cells (a unit square, a 30 degree rhombus,
 * a stretched row, a folded bow-tie), a converged test domain (the dome), the annulus
 * O-grid, and the fold check of eg2d_solve. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "eg2d.h"

#define PI 3.14159265358979323846
#define TIGHT 1e-12

static const int kCellMetrics[] = {EG2D_QUALITY_FOLDED_CELLS, EG2D_QUALITY_MIN_AREA, EG2D_QUALITY_MAX_AREA,
                                   EG2D_QUALITY_SKEWNESS, EG2D_QUALITY_ASPECT_RATIO, EG2D_QUALITY_SMOOTHNESS_I,
                                   EG2D_QUALITY_SMOOTHNESS_J};

static void assert_near(double got, double want, double tol, const char *what) {
    if (!(fabs(got - want) <= tol)) fail_msg("%s = %.17g, expected %.17g (tolerance %g)", what, got, want, tol);
}

static void assert_contains(const char *text, const char *part) {
    if (!strstr(text, part)) fail_msg("message \"%s\" does not contain \"%s\"", text, part);
}

/* A 3 x 3 node grid (2 x 2 cells) from node coordinates. */
static eg2d_grid *grid3(const double *x, const double *y) {
    eg2d_grid *g;
    assert_int_equal(eg2d_create(3, 3, &g), EG2D_OK);
    assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
    return g;
}

static double quality(eg2d_grid *g, int metric) {
    double v = -12345;
    assert_int_equal(eg2d_get_quality(g, metric, &v), EG2D_OK);
    return v;
}

/* Every cell of metric equals want. */
static void assert_cells(eg2d_grid *g, int metric, double want, const char *what) {
    double v[4];
    int c;
    assert_int_equal(eg2d_get_cell_quality(g, metric, v), EG2D_OK);
    for (c = 0; c < 4; ++c) assert_near(v[c], want, TIGHT, what);
}

static void test_unit_square(void **state) {
    double x[9], y[9];
    int k, s;
    eg2d_grid *g;
    (void)state;
    for (k = 0; k < 9; ++k) x[k] = k % 3, y[k] = k / 3;
    g = grid3(x, y);
    assert_cells(g, EG2D_QUALITY_FOLDED_CELLS, 0, "square folded");
    assert_cells(g, EG2D_QUALITY_MIN_AREA, 1, "square area");
    assert_cells(g, EG2D_QUALITY_SKEWNESS, 0, "square skewness");
    assert_cells(g, EG2D_QUALITY_ASPECT_RATIO, 1, "square aspect ratio");
    assert_cells(g, EG2D_QUALITY_SMOOTHNESS_I, 1, "square smoothness i");
    assert_cells(g, EG2D_QUALITY_SMOOTHNESS_J, 1, "square smoothness j");
    assert_near(quality(g, EG2D_QUALITY_MIN_AREA), 1, TIGHT, "min area");
    assert_near(quality(g, EG2D_QUALITY_MAX_AREA), 1, TIGHT, "max area");
    for (s = 0; s < 4; ++s) {
        assert_near(quality(g, EG2D_QUALITY_ORTHO_MAX_JMIN + s), 0, TIGHT, "square orthogonality max");
        assert_near(quality(g, EG2D_QUALITY_ORTHO_MEAN_JMIN + s), 0, TIGHT, "square orthogonality mean");
    }
    eg2d_destroy(g);
}

/* Cell (0, 0) with node (1, 1) moved to (2, 0): corner (1, 0) is a straight
 * 180-degree corner, degenerate but not folded, so its skewness is 90 - in
 * the grid and in its mirror image (left-handed), where the zero cross
 * product carries the other sign. */
static void test_straight_corner(void **state) {
    double x[9], y[9], v[4];
    int k, mirror;
    (void)state;
    for (mirror = 0; mirror < 2; ++mirror) {
        eg2d_grid *g;
        for (k = 0; k < 9; ++k) x[k] = k % 3, y[k] = k / 3;
        x[4] = 2;
        y[4] = 0;
        for (k = 0; k < 9 && mirror; ++k) y[k] = -y[k]; /* left-handed */
        g = grid3(x, y);
        assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_FOLDED_CELLS, v), EG2D_OK);
        assert_near(v[0], 0, 0, "straight corner folded");
        assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, v), EG2D_OK);
        assert_near(v[0], 90, TIGHT, mirror ? "straight corner skewness (mirrored)" : "straight corner skewness");
        eg2d_destroy(g);
    }
}

/* A grid ni x nj from x, y (its creator's), and the largest per-cell
 * skewness in *most. */
static eg2d_grid *grid_and_largest_skewness(int ni, int nj, const double *x, const double *y, double *most) {
    eg2d_grid *g;
    double *v = malloc(sizeof(double) * (size_t)(ni - 1) * (size_t)(nj - 1));
    int k;
    assert_non_null(v);
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, v), EG2D_OK);
    *most = 0;
    for (k = 0; k < (ni - 1) * (nj - 1); ++k)
        if (v[k] > *most) *most = v[k];
    free(v);
    return g;
}

/* The skewness summary (found from cosines, without an atan2 per corner)
 * is the largest of the per-cell field, to the last bit: on a 17 x 13 grid whose nodes
 * are moved by up to 0.15 of the spacing (no fold) and by up to 0.7 (some
 * cells folded, corners past 90 either way), each also mirrored
 * (left-handed). */
static void test_skewness_summary_is_largest_cell(void **state) {
    enum { NI = 17, NJ = 13 };
    double x[NI * NJ], y[NI * NJ], most;
    unsigned seed = 12345u;
    int k, mirror, folded, m;
    (void)state;
    for (m = 0; m < 4; ++m) {
        const double amp = m < 2 ? 0.3 : 1.4;
        eg2d_grid *g;
        mirror = m % 2;
        seed = 12345u;
        for (k = 0; k < NI * NJ; ++k) {
            const int i = k % NI, j = k / NI, inner = i > 0 && j > 0 && i < NI - 1 && j < NJ - 1;
            double dx, dy;
            seed = seed * 1103515245u + 12345u;
            dx = ((seed >> 8) % 1000) / 1000.0 - 0.5;
            seed = seed * 1103515245u + 12345u;
            dy = ((seed >> 8) % 1000) / 1000.0 - 0.5;
            x[k] = i + (inner ? amp * dx : 0.0);
            y[k] = (mirror ? -1.0 : 1.0) * (j + (inner ? amp * dy : 0.0));
        }
        g = grid_and_largest_skewness(NI, NJ, x, y, &most);
        folded = (int)quality(g, EG2D_QUALITY_FOLDED_CELLS);
        if (amp > 1) {
            assert_true(folded > 0); /* the folded corners' branch */
            assert_true(most > 90);
        } else {
            assert_int_equal(folded, 0); /* the cosines' branch decides */
            assert_true(most > 5 && most < 90);
        }
        assert_true(quality(g, EG2D_QUALITY_SKEWNESS) == most); /* to the last bit */
        eg2d_destroy(g);
    }
}

/* The same on a Cartesian grid turned by 0.3 rad (every corner's cos^2 at
 * rounding level, so every corner is measured in the second pass) and on
 * one with a column of cells 1e-170 wide (the product of their edges'
 * squared lengths underflows to 0: read as a zero edge, cos^2 1 would hide
 * the 5.7-degree cells of a moved node): the summary is the largest
 * per-cell value to the last bit. */
static void test_skewness_summary_degenerate(void **state) {
    enum { N = 5 };
    double x[N * N], y[N * N], most;
    int k, m;
    (void)state;
    for (m = 0; m < 2; ++m) {
        eg2d_grid *g;
        for (k = 0; k < N * N; ++k) {
            const double i = k % N, j = k / N;
            x[k] = cos(0.3) * i - sin(0.3) * j;
            y[k] = sin(0.3) * i + cos(0.3) * j;
            if (m == 1) x[k] = (k % N == 0) ? 0.0 : (k % N == 1 ? 1e-170 : k % N), y[k] = k / N;
            if (m == 1 && k == 3 + 2 * N) x[k] += 0.1; /* node (3, 2): four cells skewed by 5.7 degrees */
        }
        g = grid_and_largest_skewness(N, N, x, y, &most);
        if (m == 0) assert_true(most < 1e-12); /* right angles, to rounding */
        else assert_true(most > 5 && most < 6);
        assert_true(quality(g, EG2D_QUALITY_SKEWNESS) == most);
        eg2d_destroy(g);
    }
}

/* Node (i, j) at i (1, 0) + j (cos 30, sin 30): every cell a rhombus of unit
 * sides with corners of 30 and 150 degrees, area sin 30 = 1/2. */
static void test_rhombus_30(void **state) {
    double x[9], y[9];
    int k, s;
    eg2d_grid *g;
    (void)state;
    for (k = 0; k < 9; ++k) {
        x[k] = k % 3 + (k / 3) * cos(PI / 6);
        y[k] = (k / 3) * sin(PI / 6);
    }
    g = grid3(x, y);
    assert_cells(g, EG2D_QUALITY_FOLDED_CELLS, 0, "rhombus folded");
    assert_cells(g, EG2D_QUALITY_MAX_AREA, 0.5, "rhombus area");
    assert_cells(g, EG2D_QUALITY_SKEWNESS, 60, "rhombus skewness");
    assert_cells(g, EG2D_QUALITY_ASPECT_RATIO, 1, "rhombus aspect ratio");
    assert_near(quality(g, EG2D_QUALITY_SKEWNESS), 60, TIGHT, "rhombus skewness summary");
    /* Grid lines meet every side at 30 (or 150) degrees: 60 from orthogonal. */
    for (s = 0; s < 4; ++s) {
        assert_near(quality(g, EG2D_QUALITY_ORTHO_MAX_JMIN + s), 60, 1e-10, "rhombus orthogonality max");
        assert_near(quality(g, EG2D_QUALITY_ORTHO_MEAN_JMIN + s), 60, 1e-10, "rhombus orthogonality mean");
    }
    eg2d_destroy(g);
}

/* x = 0, 1, 3 and y = 0, 0.5, 1: cells 1 x 0.5 then 2 x 0.5. */
static void test_stretched_row(void **state) {
    const double xs[3] = {0, 1, 3};
    double x[9], y[9], v[4];
    int k;
    eg2d_grid *g;
    (void)state;
    for (k = 0; k < 9; ++k) x[k] = xs[k % 3], y[k] = 0.5 * (k / 3);
    g = grid3(x, y);
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_ASPECT_RATIO, v), EG2D_OK);
    assert_near(v[0], 2, TIGHT, "aspect ratio of the 1 x 0.5 cell");
    assert_near(v[1], 4, TIGHT, "aspect ratio of the 2 x 0.5 cell");
    assert_near(v[2], 2, TIGHT, "aspect ratio of the 1 x 0.5 cell, row 2");
    assert_near(quality(g, EG2D_QUALITY_ASPECT_RATIO), 4, TIGHT, "largest aspect ratio");
    assert_cells(g, EG2D_QUALITY_SMOOTHNESS_I, 2, "smoothness in i: widths 1 and 2");
    assert_cells(g, EG2D_QUALITY_SMOOTHNESS_J, 1, "smoothness in j: equal heights");
    assert_near(quality(g, EG2D_QUALITY_MIN_AREA), 0.5, TIGHT, "min area");
    assert_near(quality(g, EG2D_QUALITY_MAX_AREA), 1.0, TIGHT, "max area");
    eg2d_destroy(g);
}

/* The unit-square grid with nodes (0,1) and (1,1) swapped: cell (0, 0) has
 * corners (0,0), (1,0), (0,1), (1,1), a bow-tie whose corner angles are
 * +45, +45, -45, -45 degrees (the last two turn against the grid), area 0 by
 * its diagonals, edges 1 along i and sqrt 2 along j. Cell (0, 1) is the
 * mirrored bow-tie; cells (1, 0) and (1, 1) are convex with area 3/2, so the
 * grid is right-handed. */
static void test_bow_tie(void **state) {
    double x[9], y[9], v[4];
    int k;
    eg2d_grid *g;
    (void)state;
    for (k = 0; k < 9; ++k) x[k] = k % 3, y[k] = k / 3;
    x[3] = 1; /* node (0, 1) */
    x[4] = 0; /* node (1, 1) */
    g = grid3(x, y);
    assert_near(quality(g, EG2D_QUALITY_FOLDED_CELLS), 2, 0, "folded cells");
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_FOLDED_CELLS, v), EG2D_OK);
    assert_true(v[0] == 1 && v[1] == 0 && v[2] == 1 && v[3] == 0);
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_MIN_AREA, v), EG2D_OK);
    assert_near(v[0], 0, TIGHT, "bow-tie area");
    assert_near(v[1], 1.5, TIGHT, "convex cell (1, 0) area");
    assert_near(v[3], 1.5, TIGHT, "convex cell (1, 1) area");
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, v), EG2D_OK);
    assert_near(v[0], 135, TIGHT, "bow-tie skewness (a -45 degree corner)");
    assert_true(v[1] < 90 && v[3] < 90);
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_ASPECT_RATIO, v), EG2D_OK);
    assert_near(v[0], sqrt(2.0), TIGHT, "bow-tie aspect ratio");
    assert_near(quality(g, EG2D_QUALITY_SKEWNESS), 135, TIGHT, "largest skewness");
    eg2d_destroy(g);
}

/* A converged test domain (the dome of the elliptic-grid course notes):
 * the summaries are the extremes of the per-cell values, and the cell
 * areas add up to the area of the boundary polygon. */
static void test_converged_dome(void **state) {
    enum { NI = 33, NJ = 25, NC = (NI - 1) * (NJ - 1) };
    static double x[NI * NJ], y[NI * NJ], v[NC];
    double polygon = 0, sum = 0, lo, hi;
    int m, c, k, ring[2 * (NI + NJ) - 4], n = 0, i, j;
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "dome"), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    /* Shoelace area of the boundary ring, counter-clockwise from node (0, 0). */
    for (i = 0; i < NI - 1; ++i) ring[n++] = i;
    for (j = 0; j < NJ - 1; ++j) ring[n++] = NI - 1 + NI * j;
    for (i = NI - 1; i > 0; --i) ring[n++] = i + NI * (NJ - 1);
    for (j = NJ - 1; j > 0; --j) ring[n++] = NI * j;
    for (k = 0; k < n; ++k) {
        const int a = ring[k], b = ring[(k + 1) % n];
        polygon += 0.5 * (x[a] * y[b] - x[b] * y[a]);
    }
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_MIN_AREA, v), EG2D_OK);
    for (c = 0; c < NC; ++c) sum += v[c];
    print_message("dome %dx%d: cell areas sum to %.15f, boundary polygon %.15f (exact dome 5/3)\n", NI, NJ, sum,
                  polygon);
    assert_near(sum, polygon, 1e-13 * polygon, "sum of cell areas");
    for (m = 0; m < (int)(sizeof kCellMetrics / sizeof kCellMetrics[0]); ++m) {
        const int id = kCellMetrics[m];
        assert_int_equal(eg2d_get_cell_quality(g, id, v), EG2D_OK);
        lo = hi = v[0];
        for (c = 1; c < NC; ++c) lo = v[c] < lo ? v[c] : lo, hi = v[c] > hi ? v[c] : hi;
        assert_true(quality(g, id) == (id == EG2D_QUALITY_MIN_AREA ? lo : hi));
    }
    print_message("dome: area %.4g..%.4g, skewness %.2f deg, aspect ratio %.3f, smoothness i %.3f j %.3f\n",
                  quality(g, EG2D_QUALITY_MIN_AREA), quality(g, EG2D_QUALITY_MAX_AREA),
                  quality(g, EG2D_QUALITY_SKEWNESS), quality(g, EG2D_QUALITY_ASPECT_RATIO),
                  quality(g, EG2D_QUALITY_SMOOTHNESS_I), quality(g, EG2D_QUALITY_SMOOTHNESS_J));
    assert_true(quality(g, EG2D_QUALITY_FOLDED_CELLS) == 0);
    assert_true(quality(g, EG2D_QUALITY_MIN_AREA) > 0);
    assert_true(quality(g, EG2D_QUALITY_SKEWNESS) < 90); /* no corner turns against the grid */
    for (m = 0; m < 4; ++m) {
        const double mx = quality(g, EG2D_QUALITY_ORTHO_MAX_JMIN + m), mean = quality(g, EG2D_QUALITY_ORTHO_MEAN_JMIN + m);
        print_message("dome: orthogonality at side %d: max %.4g, mean %.4g deg\n", m, mx, mean);
        assert_true(mean >= 0 && mean <= mx && mx < 90);
    }
    /* The dome is symmetric about x = 1/2: IMIN and IMAX are mirror images
       (to the tolerance: a Gauss-Seidel sweep runs one way). */
    assert_near(quality(g, EG2D_QUALITY_ORTHO_MAX_IMIN), quality(g, EG2D_QUALITY_ORTHO_MAX_IMAX), 1e-4,
                "orthogonality IMIN vs IMAX");
    assert_near(quality(g, EG2D_QUALITY_ORTHO_MEAN_IMIN), quality(g, EG2D_QUALITY_ORTHO_MEAN_IMAX), 1e-4,
                "mean orthogonality IMIN vs IMAX");
    /* Every side's x is linear in xi (x = s), so x = xi solves Winslow's
       x-equation exactly (all second derivatives vanish): the i-lines are
       vertical and meet the flat bottom at exactly 90 degrees. */
    assert_true(quality(g, EG2D_QUALITY_ORTHO_MAX_JMIN) < 1e-10);
    eg2d_destroy(g);
}

/* The annulus O-grid: by symmetry the lines of constant i are radial, so
 * they meet both circles orthogonally, and the cells are equal along i
 * (across the branch cut too). */
static void test_annulus_orthogonal(void **state) {
    enum { NI = 49, NJ = 17 };
    double v;
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_create(NI, NJ, &g), EG2D_OK);
    assert_int_equal(domain_set_annulus(g, 3, 9), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-12), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    print_message("annulus %dx%d: orthogonality max JMIN %.2e JMAX %.2e deg, smoothness i %.15f, j %.6f "
                  "(ratio of the exact radii (9/3)^(1/%d) = %.6f)\n",
                  NI, NJ, quality(g, EG2D_QUALITY_ORTHO_MAX_JMIN), quality(g, EG2D_QUALITY_ORTHO_MAX_JMAX),
                  quality(g, EG2D_QUALITY_SMOOTHNESS_I), quality(g, EG2D_QUALITY_SMOOTHNESS_J), NJ - 1,
                  pow(3.0, 1.0 / (NJ - 1)));
    assert_true(quality(g, EG2D_QUALITY_ORTHO_MAX_JMIN) < 1e-8);
    assert_true(quality(g, EG2D_QUALITY_ORTHO_MAX_JMAX) < 1e-8);
    assert_near(quality(g, EG2D_QUALITY_SMOOTHNESS_I), 1, 1e-10, "smoothness in i on the annulus");
    assert_near(quality(g, EG2D_QUALITY_SMOOTHNESS_J), pow(3.0, 1.0 / (NJ - 1)), 2e-3,
                "smoothness in j: the ratio of successive radii");
    /* An O-grid has no IMIN/IMAX sides. */
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_ORTHO_MAX_IMIN, &v), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "no side IMIN");
    eg2d_destroy(g);
}

/* Laplace (Amsden-Hirt) folds the valley of the elliptic-grid course notes: eg2d_solve converges,
 * then fails with EG2D_ERR_FOLDED naming the first folded cell, keeps the
 * grid, and the per-cell metrics show the same cells. */
static void test_solve_reports_folds(void **state) {
    enum { N = 17, NC = (N - 1) * (N - 1) };
    double v[NC], skew[NC], count = 0, r;
    int c, first = -1;
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_create(N, N, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "valley"), EG2D_OK);
    assert_int_equal(eg2d_set_system(g, EG2D_SYSTEM_LAPLACE), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_ERR_FOLDED);
    assert_contains(eg2d_last_error(g), "folded cells; the first is cell (");
    assert_int_equal(eg2d_get_residual(g, &r), EG2D_OK);
    assert_true(r <= 1e-8); /* converged and kept */
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_FOLDED_CELLS, v), EG2D_OK);
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, skew), EG2D_OK);
    for (c = 0; c < NC; ++c) {
        count += v[c];
        if (v[c] == 1 && first < 0) first = c;
        if (v[c] == 1) assert_true(skew[c] > 90); /* a folded corner's angle is negative */
    }
    assert_true(count > 0 && count == quality(g, EG2D_QUALITY_FOLDED_CELLS));
    {
        char where[64];
        snprintf(where, sizeof where, "cell (%d, %d)", first % (N - 1), first / (N - 1));
        assert_contains(eg2d_last_error(g), where);
        print_message("valley %dx%d, Laplace: %.0f folded cells, first %s\n", N, N, count, where);
    }
    /* With the check off the same run is a success. */
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_FOLD_CHECK, 0), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    eg2d_destroy(g);
}

static void test_cell_quality_errors(void **state) {
    double v[64];
    eg2d_grid *g;
    (void)state;
    assert_int_equal(eg2d_get_cell_quality(NULL, EG2D_QUALITY_SKEWNESS, v), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(NULL), "eg2d_get_cell_quality: grid is NULL");
    assert_int_equal(eg2d_create(5, 5, &g), EG2D_OK);
    assert_int_equal(domain_set(g, "quad"), EG2D_OK);
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, v), EG2D_ERR_STATE);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_SKEWNESS, NULL), EG2D_ERR_ARGUMENT);
    assert_string_equal(eg2d_last_error(g), "eg2d_get_cell_quality: values is NULL");
    assert_int_equal(eg2d_get_cell_quality(g, 3, v), EG2D_ERR_ARGUMENT); /* a gap in the ids */
    assert_string_equal(eg2d_last_error(g), "eg2d_get_cell_quality: metric = 3: no such quality metric");
    assert_int_equal(eg2d_get_cell_quality(g, EG2D_QUALITY_ORTHO_MEAN_JMAX, v), EG2D_ERR_ARGUMENT);
    assert_contains(eg2d_last_error(g), "no per-cell values");
    assert_int_equal(eg2d_get_quality(g, 11, v), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_unit_square),        cmocka_unit_test(test_rhombus_30),
        cmocka_unit_test(test_straight_corner),    cmocka_unit_test(test_skewness_summary_is_largest_cell),
        cmocka_unit_test(test_skewness_summary_degenerate),
        cmocka_unit_test(test_stretched_row),      cmocka_unit_test(test_bow_tie),
        cmocka_unit_test(test_converged_dome),     cmocka_unit_test(test_annulus_orthogonal),
        cmocka_unit_test(test_solve_reports_folds), cmocka_unit_test(test_cell_quality_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
