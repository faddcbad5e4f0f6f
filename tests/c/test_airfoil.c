/* eg2d_set_airfoil: the boundary of an airfoil grid (eg2d.h). C- and O-grids
 * round NACA 0012 with a sharp trailing edge, the standard open one kept as a
 * blunt base or sharpened; the spacings, the cut, the far field as set; bad
 * settings refused with the handle unchanged; and the grids the default wall
 * layer then makes. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eg2d.h"

static double *alloc(int n) {
    double *p = malloc(sizeof(double) * (size_t)n);
    assert_non_null(p);
    return p;
}

static double dist(const double *x, const double *y, int a, int b) { return hypot(x[b] - x[a], y[b] - y[a]); }

/* A C-grid's trailing-edge index: the last i whose node is node ni-1-i. */
static int te_index(const double *x, const double *y, int ni) {
    int w = 0;
    while (w + 1 < ni / 2 && x[w + 1] == x[ni - 2 - w] && y[w + 1] == y[ni - 2 - w]) ++w;
    return w;
}

static eg2d_curve *naca0012(int flags) {
    eg2d_curve *c = NULL;
    assert_int_equal(eg2d_curve_naca4("0012", flags, &c), EG2D_OK);
    return c;
}

/* The C-grid's boundary: the cut along y = 0 from x = 1 + R to the trailing
 * edge at the wake index asked, its first cell the trailing-edge spacing;
 * the section's spacings at its edges as set; the far field R out. */
static void test_c_grid_boundary(void **state) {
    const int ni = 193, nj = 49, wake = 40;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), least = INFINITY;
    eg2d_grid *g;
    eg2d_curve *c = naca0012(EG2D_NACA_CLOSED_TE);
    int i, j, le = -1;
    (void)state;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_FARFIELD, 50), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_WAKE_NODES, wake), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_LE_SPACING, 1e-3), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_TE_SPACING, 4e-3), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_C), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    assert_true(fabs(x[0] - 51) < 1e-12 && fabs(x[ni - 1] - 51) < 1e-12);
    assert_int_equal(te_index(x, y, ni), wake);
    assert_true(fabs(x[wake] - 1) < 1e-12 && fabs(y[wake]) < 1e-9);
    for (i = 0; i < wake; ++i) { /* along the chord line (found to about 1e-8 radians) */
        assert_true(fabs(y[i]) < 1e-6);
        if (i > 0) assert_true(x[i] < x[i - 1]);
    }
    assert_true(fabs(dist(x, y, wake - 1, wake) / 4e-3 - 1) < 1e-9);  /* the cut's first cell */
    assert_true(fabs(dist(x, y, wake, wake + 1) / 4e-3 - 1) < 1e-6);  /* the section's at the trailing edge */
    for (i = wake; i <= ni - 1 - wake; ++i)
        if (le < 0 || x[i] < x[le]) le = i;
    assert_int_equal(le, ni / 2);
    assert_true(fabs(dist(x, y, le, le + 1) / 1e-3 - 1) < 1e-3 && fabs(dist(x, y, le - 1, le) / 1e-3 - 1) < 1e-3);
    for (j = 0; j < ni; ++j) /* the far field: no node of JMAX nearer the body than 50 chords */
        for (i = wake; i <= ni - 1 - wake; ++i) least = fmin(least, dist(x, y, i, j + ni * (nj - 1)));
    assert_true(least >= 50 - 1e-9);
    eg2d_destroy(g);
    eg2d_curve_destroy(c);
    free(x);
    free(y);
}

/* NACA 0012's standard trailing edge is open (0.00252 chords): kept as a
 * straight base of wall nodes on an O- or C-grid, or sharpened; a C-grid's
 * cut starts at the base's midpoint. */
static void test_open_trailing_edge(void **state) {
    const int ni = 129, nj = 33;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), value;
    eg2d_grid *g;
    eg2d_curve *c = naca0012(0);
    int i, corner, on_base = 0;
    (void)state;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(eg2d_get_parameter(g, EG2D_PARAM_AIRFOIL_TRAILING_EDGE, &value), EG2D_OK);
    assert_true(value == EG2D_AIRFOIL_TE_BLUNT);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_TE_SPACING, 5e-4), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_O), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    for (i = 0; i < ni - 1; ++i)
        if (fabs(x[i] - x[0]) < 1e-12) ++on_base; /* the base: straight, at the corners' x */
    assert_true(on_base >= 4);
    assert_true(fabs(y[0] - y[ni - 1]) < 1e-15 && y[0] < -1e-3); /* the loop starts at the lower corner */
    /* Kept on a C-grid: the cut starts at the base's midpoint; the cut's
     * first cell and the section's at the corners are the base's spacing. */
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_C), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    i = te_index(x, y, ni);
    assert_true(fabs(x[i] - 1) < 1e-12 && fabs(y[i]) < 1e-12);
    for (corner = i; fabs(x[corner + 1] - 1) < 1e-12; ++corner) {}
    assert_int_equal(corner - i, 3); /* 0.00126 chords at about 5e-4: 3 cells of 4.2e-4 */
    assert_true(fabs(dist(x, y, i - 1, i) / dist(x, y, i, i + 1) - 1) < 1e-9);
    assert_true(fabs(dist(x, y, corner, corner + 1) / dist(x, y, i, i + 1) - 1) < 1e-6);
    assert_true(fabs(y[i - 1]) < 1e-12 && x[i - 1] > 1); /* along the base's normal: the chord */
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_TRAILING_EDGE, EG2D_AIRFOIL_TE_SHARPEN), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_C), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    i = te_index(x, y, ni); /* sharpened: the section ends at the base's midpoint */
    assert_true(fabs(x[i] - 1) < 1e-12 && fabs(y[i]) < 1e-9);
    assert_true(fabs(x[i + 1] - x[i]) > 1e-5); /* no base: the next node is on the lower surface */
    eg2d_destroy(g);
    eg2d_curve_destroy(c);
    free(x);
    free(y);
}

/* An O-grid's sharp trailing edge: cut back to a straight base
 * EG2D_PARAM_AIRFOIL_O_TE_BASE thick (default 5e-5 chords), across the
 * edge's bisector (the chord on a symmetric section), a few ten-thousandths
 * of the chord back, its two cells the surfaces' first; 0 keeps the edge a
 * single node at (1, 0); C-grids keep it on their cut. */
static void test_o_grid_sharp_edge_base(void **state) {
    const int ni = 257, nj = 33;
    double *x = alloc(ni * nj), *y = alloc(ni * nj), value;
    eg2d_grid *g;
    eg2d_curve *c = naca0012(EG2D_NACA_CLOSED_TE);
    int i;
    (void)state;
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(eg2d_get_parameter(g, EG2D_PARAM_AIRFOIL_O_TE_BASE, &value), EG2D_OK);
    assert_true(value == 5e-5);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_O), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    /* the loop starts at the lower corner; the base: nodes ni-3 (upper corner), ni-2 (its midpoint), ni-1 */
    assert_true(y[0] < 0 && fabs(y[ni - 3] + y[0]) < 1e-9 && fabs(y[ni - 2]) < 1e-12);
    assert_true(fabs(dist(x, y, 0, ni - 3) - 5e-5) < 1e-9);
    assert_true(fabs(x[0] - x[ni - 3]) < 1e-12 && x[0] < 1 - 1e-4 && x[0] > 1 - 5e-4);
    assert_true(fabs(dist(x, y, 0, 1) / dist(x, y, ni - 3, ni - 2) - 1) < 1e-6);
    /* kept sharp */
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_O_TE_BASE, 0), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_O_TE_BASE, -1), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_O), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    assert_true(fabs(x[0] - 1) < 1e-12 && fabs(y[0]) < 1e-12 && dist(x, y, 0, ni - 2) > 1e-4);
    /* a C-grid's sharp edge stays on its cut, whatever the setting */
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_O_TE_BASE, 5e-5), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_C), EG2D_OK);
    assert_int_equal(eg2d_initialize(g, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    i = te_index(x, y, ni);
    assert_true(fabs(x[i] - 1) < 1e-12 && fabs(y[i]) < 1e-12);
    eg2d_destroy(g);
    eg2d_curve_destroy(c);
    free(x);
    free(y);
}

/* What cannot be made is refused, and the handle keeps what it had. */
/* The airfoil's settings act whatever their order: set after
 * eg2d_set_airfoil they make its boundary again (a far field of 500 set
 * afterwards was 100, with EG2D_OK), identical to the grid they make set
 * before; once the user has replaced a side, no longer. */
/* eg2d_set_airfoil makes the run an airfoil grid's (tolerance 1e-10, on a
 * C-grid the V(1,2) cycle) for each parameter the caller has not set, before
 * or after it; a caller's setting stays. */
static double param(const eg2d_grid *g, int id) {
    double v = -1;
    assert_int_equal(eg2d_get_parameter(g, id, &v), EG2D_OK);
    return v;
}

static void test_airfoil_run_defaults(void **state) {
    eg2d_curve *naca;
    eg2d_grid *g;
    double def;
    (void)state;
    assert_int_equal(eg2d_curve_naca4("0012", 0, &naca), EG2D_OK);
    /* nothing set: the C-grid's run */
    assert_int_equal(eg2d_create(129, 33, &g), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, naca, EG2D_TOPO_C), EG2D_OK);
    assert_true(param(g, EG2D_PARAM_TOLERANCE) == 1e-10);
    assert_true(param(g, EG2D_PARAM_MG_CYCLE) == 1 && param(g, EG2D_PARAM_MG_PRE_SMOOTH) == 1 &&
                param(g, EG2D_PARAM_MG_POST_SMOOTH) == 2);
    /* set afterwards: the caller's value */
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_MG_CYCLE, 2), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, naca, EG2D_TOPO_C), EG2D_OK);
    assert_true(param(g, EG2D_PARAM_MG_CYCLE) == 2);
    eg2d_destroy(g);
    /* set before, even to the library's own default: kept */
    assert_int_equal(eg2d_parameter_bounds(EG2D_PARAM_TOLERANCE, NULL, NULL, &def), EG2D_OK);
    assert_int_equal(eg2d_create(129, 33, &g), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, def), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, naca, EG2D_TOPO_O), EG2D_OK);
    assert_true(param(g, EG2D_PARAM_TOLERANCE) == def);
    /* an O-grid keeps the default cycle */
    assert_int_equal(eg2d_parameter_bounds(EG2D_PARAM_MG_CYCLE, NULL, NULL, &def), EG2D_OK);
    assert_true(param(g, EG2D_PARAM_MG_CYCLE) == def);
    /* a failed eg2d_set_airfoil changes nothing */
    eg2d_destroy(g);
    assert_int_equal(eg2d_create(9, 5, &g), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, naca, EG2D_TOPO_C), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_parameter_bounds(EG2D_PARAM_TOLERANCE, NULL, NULL, &def), EG2D_OK);
    assert_true(param(g, EG2D_PARAM_TOLERANCE) == def);
    eg2d_destroy(g);
    eg2d_curve_destroy(naca);
}

static void test_settings_after_set_airfoil(void **state) {
    const int ni = 129, nj = 33, n = ni * nj;
    double *x1 = alloc(n), *y1 = alloc(n), *x2 = alloc(n), *y2 = alloc(n);
    eg2d_curve *c = naca0012(EG2D_NACA_CLOSED_TE);
    eg2d_grid *before, *after;
    (void)state;
    assert_int_equal(eg2d_create(ni, nj, &before), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(before, EG2D_PARAM_AIRFOIL_FARFIELD, 500), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(before, EG2D_PARAM_AIRFOIL_WAKE_NODES, 24), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(before, c, EG2D_TOPO_C), EG2D_OK);
    assert_int_equal(eg2d_create(ni, nj, &after), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(after, c, EG2D_TOPO_C), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(after, EG2D_PARAM_AIRFOIL_FARFIELD, 500), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(after, EG2D_PARAM_AIRFOIL_WAKE_NODES, 24), EG2D_OK);
    assert_int_equal(eg2d_initialize(before, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_initialize(after, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(before, x1, y1), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(after, x2, y2), EG2D_OK);
    assert_true(fabs(x1[0] - 501) < 1e-9);
    assert_memory_equal(x1, x2, sizeof(double) * (size_t)n);
    assert_memory_equal(y1, y2, sizeof(double) * (size_t)n);
    /* A bad value is refused with the boundary unchanged. */
    assert_int_equal(eg2d_set_parameter(after, EG2D_PARAM_AIRFOIL_WAKE_NODES, 70), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_initialize(after, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(after, x2, y2), EG2D_OK);
    assert_memory_equal(x1, x2, sizeof(double) * (size_t)n);
    double wake = 0;
    assert_int_equal(eg2d_get_parameter(after, EG2D_PARAM_AIRFOIL_WAKE_NODES, &wake), EG2D_OK);
    assert_true(wake == 24);
    /* The user's own JMAX replaces the airfoil's: the far field no longer moves it. */
    double *sx = alloc(ni), *sy = alloc(ni);
    for (int i = 0; i < ni; ++i) sx[i] = x1[(nj - 1) * ni + i], sy[i] = y1[(nj - 1) * ni + i];
    sy[ni / 2] += 1.0;
    assert_int_equal(eg2d_set_side(after, EG2D_SIDE_JMAX, sx, sy), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(after, EG2D_PARAM_AIRFOIL_FARFIELD, 100), EG2D_OK);
    assert_int_equal(eg2d_initialize(after, EG2D_INIT_TFI), EG2D_OK);
    assert_int_equal(eg2d_get_coordinates(after, x2, y2), EG2D_OK);
    assert_true(fabs(x2[0] - 501) < 1e-9 && y2[(nj - 1) * ni + ni / 2] == sy[ni / 2]);
    free(sx), free(sy);
    eg2d_destroy(before), eg2d_destroy(after);
    eg2d_curve_destroy(c);
    free(x1), free(y1), free(x2), free(y2);
}

static void test_refused(void **state) {
    eg2d_grid *g;
    eg2d_curve *c = naca0012(EG2D_NACA_CLOSED_TE);
    int topology = -1;
    (void)state;
    assert_int_equal(eg2d_create(25, 9, &g), EG2D_OK);
    assert_int_equal(eg2d_set_topology(g, EG2D_TOPO_O), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_WAKE_NODES, 10), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_C), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(g), "leaves 5 nodes on the section with 10 cut nodes a side"));
    assert_int_equal(eg2d_get_topology(g, &topology), EG2D_OK);
    assert_int_equal(topology, EG2D_TOPO_O);
    assert_int_equal(eg2d_set_airfoil(g, c, EG2D_TOPO_SINGLE), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_airfoil(g, NULL, EG2D_TOPO_O), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_FARFIELD, 1), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_TRAILING_EDGE, 2), EG2D_ERR_ARGUMENT);
    eg2d_destroy(g);
    eg2d_curve_destroy(c);
}

/* The boundary and a first cell are all a wall-resolved grid needs: the
 * default wall layer makes the hybrid one on both topologies, blunt bases
 * included, without folds and with the height on the body. */
static void solve(eg2d_curve *c, int topology, int ni, int nj, int trailing_edge) {
    double h, folded, *x = alloc(ni * nj), *y = alloc(ni * nj), least = INFINITY, most = 0;
    eg2d_grid *g;
    char note[512];
    int i, wake = 0, it;
    assert_int_equal(eg2d_first_cell_height(1.0, 6e6, 1.0, &h), EG2D_OK);
    assert_int_equal(eg2d_create(ni, nj, &g), EG2D_OK);
    assert_int_equal(eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_TRAILING_EDGE, trailing_edge), EG2D_OK);
    assert_int_equal(eg2d_set_airfoil(g, c, topology), EG2D_OK);
    assert_int_equal(eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), EG2D_OK);
    assert_int_equal(eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), EG2D_OK);
    assert_int_equal(eg2d_set_tolerance(g, 1e-10), EG2D_OK);
    if (eg2d_solve(g) != EG2D_OK) fail_msg("%s", eg2d_last_error(g));
    assert_int_equal(eg2d_get_iterations(g, &it), EG2D_OK);
    assert_int_equal(eg2d_get_run_event(g, 0, NULL, note, (int)sizeof note), EG2D_OK);
    assert_non_null(strstr(note, "wall layer (hybrid)"));
    assert_int_equal(eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded), EG2D_OK);
    assert_true(folded == 0);
    assert_int_equal(eg2d_get_coordinates(g, x, y), EG2D_OK);
    if (topology == EG2D_TOPO_C) wake = te_index(x, y, ni);
    for (i = wake; i <= (topology == EG2D_TOPO_C ? ni - 1 - wake : ni - 2); ++i) {
        least = fmin(least, dist(x, y, i, i + ni));
        most = fmax(most, dist(x, y, i, i + ni));
    }
    print_message("%s %dx%d, %s: %d cycles, first cell %.6g..%.6g (asked %.6g)\n",
                  topology == EG2D_TOPO_C ? "C" : "O", ni, nj, trailing_edge ? "sharpened" : "as given", it, least,
                  most, h);
    assert_true(it <= 10);
    assert_true(fabs(least / h - 1) < 1e-3 && fabs(most / h - 1) < 1e-3);
    eg2d_destroy(g);
    free(x);
    free(y);
}

static void test_wall_resolved(void **state) {
    eg2d_curve *sharp = naca0012(EG2D_NACA_CLOSED_TE), *open = naca0012(0);
    (void)state;
    solve(sharp, EG2D_TOPO_C, 385, 97, EG2D_AIRFOIL_TE_BLUNT);
    solve(sharp, EG2D_TOPO_O, 257, 129, EG2D_AIRFOIL_TE_BLUNT);
    solve(open, EG2D_TOPO_O, 257, 129, EG2D_AIRFOIL_TE_BLUNT);
    solve(open, EG2D_TOPO_C, 385, 97, EG2D_AIRFOIL_TE_SHARPEN);
    solve(open, EG2D_TOPO_C, 385, 97, EG2D_AIRFOIL_TE_BLUNT); /* folded at the base's corners before */
    eg2d_curve_destroy(sharp);
    eg2d_curve_destroy(open);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_c_grid_boundary),
        cmocka_unit_test(test_open_trailing_edge),
        cmocka_unit_test(test_o_grid_sharp_edge_base),
        cmocka_unit_test(test_refused),
        cmocka_unit_test(test_settings_after_set_airfoil),
        cmocka_unit_test(test_airfoil_run_defaults),
        cmocka_unit_test(test_wall_resolved),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
