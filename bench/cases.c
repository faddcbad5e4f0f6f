/* The benchmark cases: the elliptic-grid course notes domains, the annulus O-grid
 * with and without an attraction source, the NACA0012 O- and C-grids, and
 * the NACA0012 O-grid with the wall control at a first cell of 1e-5 chord. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "domains.h"

static int square(int n) { return n; }
static int half(int n) { return n / 2 + 1; }
static int quarter(int n) { return n / 4 + 1; }
static int set_swan(eg2d_grid *g) { return domain_set(g, "swan"); }
static int set_valley(eg2d_grid *g) { return domain_set(g, "valley"); }
static int set_dome(eg2d_grid *g) { return domain_set(g, "dome"); }
static int set_annulus(eg2d_grid *g) { return domain_set_annulus(g, 1.0, 3.0); }
static int set_annulus_source(eg2d_grid *g) {
    const int status = domain_set_annulus(g, 1.0, 3.0);
    return status != EG2D_OK ? status : eg2d_add_line_source(g, EG2D_ETA, 0.0, 100.0, 0.2);
}
static int set_naca0012(eg2d_grid *g) { return domain_set_airfoil_o(g, "0012", 10.0); }
static int set_naca0012_c(eg2d_grid *g) {
    int ni, nj, status = eg2d_get_size(g, &ni, &nj);
    return status ? status : domain_set_airfoil_c(g, "0012", ni / 4, 5.0);
}

/* The wall spacing 1e-5 chord the way a user asks for it: the wall
 * control (EG2D_ORTHO_WALL, eg2d_set_wall_spacing), which is updated between
 * iterations. (A static alternative, Khattri's (2006) parameter grid with t
 * Vinokur-clustered to the wall, is unsound on an airfoil: it makes t
 * harmonic, and a harmonic t vanishing on a wedge of exterior angle
 * 345 degrees grows like rho^0.52 from the trailing edge, so the first
 * eta-line sits about (1e-5)^1.9 from it; every solver folded that case.) */
#define WALL_SPACING 1e-5
static int set_naca0012_wall(eg2d_grid *g) {
    int status = set_naca0012(g);
    if (!status) status = eg2d_set_orthogonality(g, EG2D_ORTHO_WALL);
    if (!status) status = eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, WALL_SPACING);
    return status;
}

static const bench_case cases[] = {
    {"swan", square, set_swan},          /* the elliptic-grid course notes A4 */
    {"valley", square, set_valley},      /* the elliptic-grid course notes A1 */
    {"dome", square, set_dome},          /* the elliptic-grid course notes A5: strongly curved top */
    {"annulus", half, set_annulus},      /* O-grid, 1 <= r <= 3, n x (n/2+1) */
    {"naca0012", quarter, set_naca0012}, /* O-grid, sharp-TE NACA0012 in r = 10, n x (n/4+1) */
    {"naca0012-c", quarter, set_naca0012_c}, /* C-grid, n/4 wake points a side to x = 6, r = 5 */
    /* The annulus with Ly & Norrison (2007) eq 14's line attraction toward the inner wall
     * (mu = 100, kappa = 0.2): iterations against "annulus" are the cost of sources. */
    {"annulus-source", half, set_annulus_source},
    /* naca0012 with a first cell of 1e-5 chord at the wall (aspect ratios
     * 8e2-3e3): the stretched-cell speed target, against "naca0012". */
    {"naca0012-wall", quarter, set_naca0012_wall},
};

const bench_case *bench_find_case(const char *name) {
    size_t k;
    for (k = 0; k < sizeof cases / sizeof cases[0]; ++k)
        if (!strcmp(cases[k].name, name)) return &cases[k];
    return NULL;
}

static int cmp_double(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double bench_wall_spacing(const eg2d_grid *g) {
    int ni, nj, i;
    double *x, *y, h = NAN;
    if (eg2d_get_size(g, &ni, &nj) || !(x = malloc(sizeof(double) * 2 * (size_t)ni * nj))) return NAN;
    y = x + (size_t)ni * nj;
    if (!eg2d_get_coordinates(g, x, y)) {
        for (i = 0; i < ni; ++i) x[i] = hypot(x[i + ni] - x[i], y[i + ni] - y[i]);
        qsort(x, (size_t)ni, sizeof x[0], cmp_double);
        h = x[ni / 2];
    }
    free(x);
    return h;
}
