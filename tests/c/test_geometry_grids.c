/* O- and C-grids from curves: the annulus under every solver the library
 * has, a NACA0012 O-grid, C-grids with a wake cut, the elliptic-grid course notes' rose in a
 * circle, and the Hermite TFI initial grid. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "domains.h"
#include "solve_compare.h"
#include "eg2d.h"

#define PI 3.14159265358979323846

static double *alloc(int n) {
    double *p = malloc(sizeof(double) * (size_t)n);
    assert_non_null(p);
    return p;
}

/* Winslow's annulus solution for one solver; the cut stays one column. */
static double annulus_error(int solver, int ni, int nj) {
    double *x = alloc(ni * nj), *y = alloc(ni * nj), err;
    assert_true(solve_domain("annulus", ni, nj, solver, EG2D_SYSTEM_WINSLOW, 1e-13, x, y) >= 0);
    err = annulus_exact_error(ni, nj, x, y);
    assert_true(cut_columns_equal(ni, nj, x, y));
    free(x);
    free(y);
    return err;
}

/* r = r_i (r_o/r_i)^eta at second order (NUMERICS.md), for every solver id the
 * library has: the one driver over all solvers, NLopt-style. */
static void test_annulus_every_solver(void **state) {
    const int ni[] = {17, 33, 65}, nj[] = {9, 17, 33};
    int id, solvers = 0;
    (void)state;
    for (id = 0; id < 100; ++id) {
        double e[3];
        int m;
        if (!eg2d_solver_name(id)) continue;
        ++solvers;
        for (m = 0; m < 3; ++m) e[m] = annulus_error(id, ni[m], nj[m]);
        for (m = 1; m < 3; ++m) {
            const double order = log(e[m - 1] / e[m]) / log(2.0);
            print_message("annulus, %s: %dx%d error %.3e, order %.3f\n", eg2d_solver_name(id), ni[m], nj[m], e[m],
                          order);
            assert_true(order > 1.9 && order < 2.1);
        }
    }
    assert_true(solvers >= 1);
}

/* A circle of radius R about (cx, 0), clockwise from angle 0 (like the airfoil). */
struct circle { double cx, R, sense; };
static void circle_fn(void *user, double t, double *x, double *y) {
    const struct circle *c = (const struct circle *)user;
    *x = c->cx + c->R * cos(2 * PI * t);
    *y = c->sense * c->R * sin(2 * PI * t);
}

static void check_unfolded(eg2d_grid *g) {
    double folded, min_area;
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_MIN_AREA, &min_area), EG2D_OK);
    assert_true(folded == 0);
    assert_true(min_area > 0);
}

static void test_naca0012_o_grid(void **state) {
    const int ni = 129, nj = 33;
    eg2d_grid *g;
    int iters;
    double res;
    (void)state;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set_airfoil_o(g, "0012", 10.0), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-9), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_get_iterations(g, &iters), EG2D_OK);
    assert_int_equal(eg2d_get_residual(g, &res), EG2D_OK);
    print_message("NACA0012 O-grid %dx%d: %d iterations, residual %.2e\n", ni, nj, iters, res);
    assert_true(res <= 1e-9);
    check_unfolded(g);
    eg2d_destroy(g);
}

/* A C-grid around a NACA section: JMIN = lower wake (outflow -> TE), the
 * airfoil, the upper wake; JMAX = the C-shaped far field; IMIN, IMAX the
 * outflow lines. Returns the grid, solved. */
static eg2d_grid *c_grid(const char *digits, int nw, int na, int nj, int init, double *x0, double *y0) {
    const double W = 5.0, R = 5.0;
    /* JMIN: nw lower-wake points, the na airfoil points (TE to TE), nw upper-wake points. */
    const int ni = 2 * nw + na;
    double *s = alloc(nw + 1), *x = alloc(ni), *y = alloc(ni), *ax = alloc(na), *ay = alloc(na);
    double *vx = alloc(nj), *vy = alloc(nj), *sj = alloc(nj);
    eg2d_grid *g;
    eg2d_curve *foil;
    int i, j, status;
    assert_int_equal(eg2d_curve_naca4(digits, EG2D_NACA_CLOSED_TE, &foil), EG2D_OK);
    assert_int_equal(eg2d_curve_points(foil, na, EG2D_DIST_UNIFORM, 0, 0, ax, ay), EG2D_OK);
    eg2d_curve_destroy(foil);
    /* Wake x from the TE (x = 1) to the outflow, clustered at the TE. */
    assert_int_equal(eg2d_distribution(EG2D_DIST_EXPONENTIAL, nw + 1, 4.0, 0, s), EG2D_OK);
    for (i = 0; i < nw; ++i) { /* lower wake: i = 0 at the outflow */
        x[i] = 1 + W * s[nw - i];
        y[i] = 0;
    }
    for (i = 0; i < na; ++i) {
        x[nw + i] = ax[i];
        y[nw + i] = ay[i];
    }
    for (i = 0; i < nw; ++i) { /* upper wake mirrors the lower one */
        x[nw + na + i] = x[nw - 1 - i];
        y[nw + na + i] = y[nw - 1 - i];
    }
    *x0 = x[nw / 2];
    *y0 = y[nw / 2];
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_C), EG2D_OK);
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_OK);
    /* Far field: the same x on the straight wake parts, the C in between. */
    {
        const int n = ni, nm = na; /* points on the C between the two wake lines, ends included */
        const double Lc = 2 * 1.0 + PI * R; /* lines x 1 -> 0 at y = -R, semicircle, 0 -> 1 at y = R */
        for (i = 0; i <= nw; ++i) {
            x[i] = 1 + W * s[nw - i];
            y[i] = -R;
            x[n - 1 - i] = x[i];
            y[n - 1 - i] = R;
        }
        for (i = 1; i < nm - 1; ++i) {
            const double d = Lc * i / (nm - 1);
            if (d < 1) { x[nw + i] = 1 - d; y[nw + i] = -R; }
            else if (d < 1 + PI * R) {
                const double a = -PI / 2 - (d - 1) / R;
                x[nw + i] = R * cos(a);
                y[nw + i] = R * sin(a);
            } else { x[nw + i] = d - 1 - PI * R; y[nw + i] = R; }
        }
    }
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMAX, x, y), EG2D_OK);
    assert_int_equal(eg2d_distribution(EG2D_DIST_EXPONENTIAL, nj, 2.0, 0, sj), EG2D_OK);
    for (j = 0; j < nj; ++j) {
        vx[j] = 1 + W;
        vy[j] = -R * sj[j];
    }
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_IMIN, vx, vy), EG2D_OK);
    for (j = 0; j < nj; ++j) vy[j] = R * sj[j];
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_IMAX, vx, vy), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-9), EG2D_OK);
    if (init >= 0) {
        double folded;
        assert_int_equal(eg2d_initialize(g, init), EG2D_OK);
        assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
        print_message("C-grid NACA%s, initial grid %d: %g folded cells\n", digits, init, folded);
    }
    status = eg2d_solve(g);
    if (status) print_message("%s\n", eg2d_last_error(g));
    assert_int_equal(status, EG2D_OK);
    free(s); free(x); free(y); free(ax); free(ay); free(vx); free(vy); free(sj);
    return g;
}

static void test_c_grid_wake_cut(void **state) {
    const int nw = 16, na = 65, nj = 25, ni = 2 * nw + na;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), x0, y0, res, worst_cos = -1, te_cos = -1, worst_ratio = 1, moved;
    eg2d_grid *g;
    int i, iters, topo;
    (void)state;
    g = c_grid("2412", nw, na, nj, -1, &x0, &y0);
    assert_int_equal(eg2d_get_topology(g, &topo), EG2D_OK);
    assert_int_equal(topo, EG2D_TOPO_C);
    assert_int_equal(eg2d_get_iterations(g, &iters), EG2D_OK);
    assert_int_equal(eg2d_get_residual(g, &res), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    check_unfolded(g);
    for (i = 0; i <= nw; ++i) { /* the two wake halves are the same points */
        assert_true(x[i] == x[ni - 1 - i]);
        assert_true(y[i] == y[ni - 1 - i]);
    }
    /* The cut nodes were solved for: the cambered section's wake left y = 0. */
    moved = fabs(y[nw / 2] - y0) + fabs(x[nw / 2] - x0);
    /* Smooth across the cut: at each cut node the eta-line goes straight on
     * (the edges to either side are nearly opposite) with nearly equal cells;
     * the node next to the trailing edge (a singular point of the map) bends more. */
    for (i = 1; i < nw; ++i) {
        const double ax = x[i + ni] - x[i], ay = y[i + ni] - y[i];
        const double bx = x[ni - 1 - i + ni] - x[i], by = y[ni - 1 - i + ni] - y[i];
        const double la = hypot(ax, ay), lb = hypot(bx, by);
        if (i < nw - 1) worst_cos = fmax(worst_cos, (ax * bx + ay * by) / (la * lb));
        else te_cos = (ax * bx + ay * by) / (la * lb);
        worst_ratio = fmax(worst_ratio, fmax(la / lb, lb / la));
    }
    print_message("C-grid NACA2412 %dx%d: %d iterations, residual %.2e, wake node moved %.3e; across the cut: "
                  "angle of the eta-line >= %.2f deg (%.2f deg next to the TE), cell ratio <= %.3f\n",
                  ni, nj, iters, res, moved, acos(worst_cos) * 180 / PI, acos(te_cos) * 180 / PI, worst_ratio);
    assert_true(res <= 1e-9);
    assert_true(moved > 1e-4);
    assert_true(worst_cos < cos(170 * PI / 180));
    assert_true(te_cos < cos(150 * PI / 180));
    assert_true(worst_ratio < 1.2);
    /* A kink put into the cut is an error the residual sees, and the solver removes. */
    x[nw / 2] += 0.05;
    x[ni - 1 - nw / 2] += 0.05;
    {
        double x_before = x[nw / 2] - 0.05;
        assert_int_equal(eg2d_set_coordinates(g, x, y), EG2D_OK);
        assert_int_equal(eg2d_get_residual(g, &res), EG2D_OK);
        assert_true(res > 1e-4);
        assert_int_equal(eg2d_solve(g), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        assert_true(fabs(x[nw / 2] - x_before) < 1e-6);
        assert_true(x[nw / 2] == x[ni - 1 - nw / 2]);
    }
    eg2d_destroy(g);
    free(x);
    free(y);
}

static void test_c_grid_naca0012(void **state) {
    double x0, y0;
    eg2d_grid *g;
    int iters;
    (void)state;
    g = c_grid("0012", 24, 81, 33, EG2D_INIT_TFI, &x0, &y0);
    check_unfolded(g);
    assert_int_equal(eg2d_get_iterations(g, &iters), EG2D_OK);
    print_message("C-grid NACA0012 129x33: %d iterations from linear TFI\n", iters);
    eg2d_destroy(g);
    g = c_grid("0012", 24, 81, 33, EG2D_INIT_HERMITE, &x0, &y0);
    check_unfolded(g);
    assert_int_equal(eg2d_get_iterations(g, &iters), EG2D_OK);
    print_message("C-grid NACA0012 129x33: %d iterations from Hermite TFI\n", iters);
    eg2d_destroy(g);
}

static void test_c_grid_boundary_errors(void **state) {
    eg2d_grid *g;
    double x[9], y[9];
    int i;
    (void)state;
    assert_int_equal(eg2d_create(9, 5, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_C), EG2D_OK);
    for (i = 0; i < 9; ++i) {
        x[i] = cos(2 * PI * i / 9.0);
        y[i] = sin(2 * PI * i / 9.0);
    }
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_ERR_BOUNDARY);
    assert_non_null(strstr(eg2d_last_error(g), "must coincide"));
    x[8] = x[0];
    y[8] = y[0];
    assert_int_equal(eg2d_set_side(g, EG2D_SIDE_JMIN, x, y), EG2D_ERR_BOUNDARY);
    assert_non_null(strstr(eg2d_last_error(g), "the wake cut needs"));
    eg2d_destroy(g);
    assert_int_equal(eg2d_create(5, 5, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_C), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
}

/* The elliptic-grid course notes, B2: the three-leaved rose inside the circle r = 9. */
static void test_rose_in_circle(void **state) {
    eg2d_grid *g;
    int iters;
    (void)state;
    assert_int_equal(eg2d_create(61, 25, &g), EG2D_OK);
    assert_int_equal(domain_set_rose(g), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    assert_int_equal(eg2d_solve(g), EG2D_OK);
    check_unfolded(g);
    assert_int_equal(eg2d_get_iterations(g, &iters), EG2D_OK);
    print_message("rose in circle 61x25: %d iterations\n", iters);
    eg2d_destroy(g);
}

/* Hermite TFI on the annulus: radial lines and, along each, the cubic of
 * the grid-generation lecture notes eq 2.4 with r_eta = alpha (r_o - r_i) at both circles. */
static void test_hermite_annulus(void **state) {
    const int ni = 33, nj = 11;
    const double alpha = 0.25;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), worst = 0;
    eg2d_grid *g;
    int i, j;
    (void)state;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(domain_set_annulus(g, 3.0, 9.0), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SPACING, alpha), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_HERMITE), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (j = 0; j < nj; ++j)
        for (i = 0; i < ni; ++i) {
            const double s = (double)j / (nj - 1), t = 2 * PI * i / (ni - 1);
            const double r = 3 * (2 * s + 1) * (1 - s) * (1 - s) + 9 * (3 - 2 * s) * s * s +
                             6 * alpha * ((1 - s) * (1 - s) * s + (s - 1) * s * s);
            worst = fmax(worst, hypot(x[i + ni * j] - r * cos(t), y[i + ni * j] - r * sin(t)));
        }
    print_message("Hermite TFI on the annulus: largest deviation from eq 2.4 %.2e\n", worst);
    assert_true(worst < 1e-12);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_HERMITE_SPACING, 0), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_initialize(g, 7), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
    free(x);
    free(y);
}

/* Hermite TFI on a single block: grid lines leave JMIN at right angles to first order. */
static void test_hermite_orthogonal_single_block(void **state) {
    const int ni = 33, nj = 33;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), worst_h = 0, worst_l = 0;
    eg2d_grid *g;
    int i, pass;
    (void)state;
    for (pass = 0; pass < 2; ++pass) {
        double worst = 0;
        assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
        assert_int_equal(domain_set(g, "dome"), EG2D_OK);
        assert_int_equal(eg2d_initialize(g, pass == 0 ? EG2D_INIT_HERMITE : EG2D_INIT_TFI), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        for (i = ni / 4; i <= 3 * ni / 4; ++i) { /* |cos| of the angle at the top (JMAX, curved), away
                                                    from the corners, which are not right angles */
            const int k = i + ni * (nj - 1);
            const double tx = x[k + 1] - x[k - 1], ty = y[k + 1] - y[k - 1];
            const double ex = x[k] - x[k - ni], ey = y[k] - y[k - ni];
            worst = fmax(worst, fabs(tx * ex + ty * ey) / (hypot(tx, ty) * hypot(ex, ey)));
        }
        if (pass == 0) worst_h = worst; else worst_l = worst;
        eg2d_destroy(g);
    }
    print_message("dome, largest |cos| at JMAX: Hermite %.3f, linear TFI %.3f\n", worst_h, worst_l);
    assert_true(worst_h < 0.1 && worst_h < 0.5 * worst_l);
    free(x);
    free(y);
}

static void valley_top(void *user, double t, double *x, double *y) {
    (void)user;
    *x = t;
    *y = 0.75 + 0.25 * sin(PI * (0.5 + 2 * t));
}

/* The elliptic-grid course notes' valley with its curved top sliding: grid lines meet it at right
 * angles, its nodes stay on the curve and in order, the corners stay. */
static void test_sliding_side(void **state) {
    const int ni = 33, nj = 33;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), cos_slide = 0, cos_fixed = 0;
    eg2d_grid *g;
    eg2d_curve *top;
    int pass, i;
    (void)state;
    assert_int_equal(eg2d_curve_function(valley_top, NULL, &top), EG2D_OK);
    for (pass = 0; pass < 2; ++pass) {
        double worst = 0;
        assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
        assert_int_equal(domain_set(g, "valley"), EG2D_OK);
        assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMAX, top, EG2D_DIST_UNIFORM, 0, 0,
                                             pass == 0 ? EG2D_CURVE_SLIDING : 0),
                         EG2D_OK);
        assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
        assert_int_equal(eg2d_solve(g), EG2D_OK);
        assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
        for (i = 1; i < ni - 1; ++i) {
            const int k = i + ni * (nj - 1);
            /* the curve's own tangent at the node */
            const double tx = 1, ty = 0.5 * PI * cos(PI * (0.5 + 2 * x[k]));
            const double ex = x[k] - x[k - ni], ey = y[k] - y[k - ni];
            worst = fmax(worst, fabs(tx * ex + ty * ey) / (hypot(tx, ty) * hypot(ex, ey)));
            assert_true(fabs(y[k] - (0.75 + 0.25 * sin(PI * (0.5 + 2 * x[k])))) < 1e-9); /* on the curve */
            assert_true(x[k] > x[k - 1]);                                               /* in order */
        }
        assert_true(x[ni * (nj - 1)] == 0 && x[ni * nj - 1] == 1); /* corners fixed */
        if (pass == 0) cos_slide = worst; else cos_fixed = worst;
        eg2d_destroy(g);
    }
    print_message("valley top: largest |cos| of the angle between grid line and curve: sliding %.2e, fixed %.4f\n",
                  cos_slide, cos_fixed);
    assert_true(cos_slide < 1e-6 && cos_fixed > 0.5);
    /* Sliding is single-block only. */
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_O), EG2D_OK);
    {
        eg2d_curve *c;
        struct circle cc = {0.0, 1.0, 1.0};
        assert_int_equal(eg2d_curve_function(circle_fn, &cc, &c), EG2D_OK);
        assert_int_equal(eg2d_set_side_curve(g, EG2D_SIDE_JMIN, c, EG2D_DIST_UNIFORM, 0, 0, EG2D_CURVE_SLIDING),
                         EG2D_ERR_UNSUPPORTED);
        assert_non_null(strstr(eg2d_last_error(g), "only single-block grids have sliding sides"));
        eg2d_curve_destroy(c);
    }
    eg2d_destroy(g);
    eg2d_curve_destroy(top);
    free(x);
    free(y);
}

/* Runs `its` iterations from a new TFI start into x, y; with solve_first, on
 * a handle that was solved to convergence before. */
static void reinit_run(int (*set_domain)(eg2d_grid *), int ni, int nj, int solve_first, int its, double *x, double *y) {
    eg2d_grid *g;
    double r;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(set_domain(g), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    if (solve_first) assert_int_equal(eg2d_solve(g), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_iterate(g, its, &r), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    eg2d_destroy(g);
}

static int naca0012_c_65(eg2d_grid *g) { return domain_set_airfoil_c(g, "0012", 16, 5.0); }
static int valley_sliding_top(eg2d_grid *g) {
    eg2d_curve *top;
    int status = domain_set(g, "valley");
    if (status) return status;
    if ((status = eg2d_curve_function(valley_top, NULL, &top))) return status;
    status = eg2d_set_side_curve(g, EG2D_SIDE_JMAX, top, EG2D_DIST_UNIFORM, 0, 0, EG2D_CURVE_SLIDING);
    eg2d_curve_destroy(top);
    return status;
}

/* eg2d_initialize starts from the boundary as set, not as a solve left it: a
 * C-grid's wake cut and a sliding side move while solving, and a handle
 * re-initialised after a solve must then run bit for bit as a new one (it
 * did not: the cut's moved nodes were the new TFI's boundary). */
static void test_reinitialize_runs_as_new(void **state) {
    struct {
        int (*set)(eg2d_grid *);
        int ni, nj;
    } cases[] = {{naca0012_c_65, 65, 17}, {valley_sliding_top, 33, 33}};
    size_t c;
    (void)state;
    for (c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        const int n = cases[c].ni * cases[c].nj;
        double *x0 = alloc(n), *y0 = alloc(n), *x1 = alloc(n), *y1 = alloc(n);
        reinit_run(cases[c].set, cases[c].ni, cases[c].nj, 0, 3, x0, y0);
        reinit_run(cases[c].set, cases[c].ni, cases[c].nj, 1, 3, x1, y1);
        assert_memory_equal(x0, x1, sizeof(double) * (size_t)n);
        assert_memory_equal(y0, y1, sizeof(double) * (size_t)n);
        free(x0);
        free(y0);
        free(x1);
        free(y1);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_annulus_every_solver),
        cmocka_unit_test(test_naca0012_o_grid),
        cmocka_unit_test(test_c_grid_wake_cut),
        cmocka_unit_test(test_c_grid_naca0012),
        cmocka_unit_test(test_c_grid_boundary_errors),
        cmocka_unit_test(test_rose_in_circle),
        cmocka_unit_test(test_hermite_annulus),
        cmocka_unit_test(test_hermite_orthogonal_single_block),
        cmocka_unit_test(test_sliding_side),
        cmocka_unit_test(test_reinitialize_runs_as_new),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
