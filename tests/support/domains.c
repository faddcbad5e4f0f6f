#include "domains.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define EG2D_TEST_PI 3.14159265358979323846

const char *const domain_names[] = {"valley", "almost-convex", "swan", "dome", NULL};

typedef void (*curve_fn)(double s, double *x, double *y);

/* The elliptic-grid course notes, A1: valley. */
static void valley_b(double s, double *x, double *y) { *x = s; *y = 0; }
static void valley_t(double s, double *x, double *y) { *x = s; *y = 0.75 + 0.25 * sin(EG2D_TEST_PI * (0.5 + 2 * s)); }
static void valley_l(double s, double *x, double *y) { *x = 0; *y = s; }
static void valley_r(double s, double *x, double *y) { *x = 1; *y = s; }
/* A2: almost convex, right side x = 1/2 + cos(pi y)/6. */
static void convex_b(double s, double *x, double *y) { *x = 2.0 / 3.0 * s; *y = 0; }
static void convex_t(double s, double *x, double *y) { *x = 1.0 / 3.0 * s; *y = 1; }
static void convex_l(double s, double *x, double *y) { *x = 0; *y = s; }
static void convex_r(double s, double *x, double *y) { *x = 0.5 + cos(EG2D_TEST_PI * s) / 6.0; *y = s; }
/* A4: swan. */
static void swan_b(double s, double *x, double *y) { *x = s; *y = 0; }
static void swan_t(double s, double *x, double *y) { *x = s; *y = 1 - 2 * s + 2 * s * s; }
static void swan_l(double s, double *x, double *y) { *x = 0; *y = s; }
static void swan_r(double s, double *x, double *y) { *x = 1 + 2 * s - 2 * s * s; *y = s; }
/* A5: dome. */
static void dome_b(double s, double *x, double *y) { *x = s; *y = 0; }
static void dome_t(double s, double *x, double *y) { *x = s; *y = -4 * (s - 0.5) * (s - 0.5) + 2; }
static void dome_l(double s, double *x, double *y) { *x = 0; *y = s; }
static void dome_r(double s, double *x, double *y) { *x = 1; *y = s; }
/* A bilinear quadrilateral. */
/* The grid's size and two arrays for its longest side (the caller frees them). */
static int side_buffers(eg2d_grid *g, int *ni, int *nj, double **x, double **y) {
    int status = eg2d_get_size(g, ni, nj);
    if (status) return status;
    *x = malloc(sizeof(double) * (size_t)(*ni > *nj ? *ni : *nj));
    *y = malloc(sizeof(double) * (size_t)(*ni > *nj ? *ni : *nj));
    if (!*x || !*y) {
        free(*x);
        free(*y);
        return EG2D_ERR_MEMORY;
    }
    return EG2D_OK;
}

/* The elliptic-grid course notes, A3: the antenna, a stem [-3, 0] x [0, 1] joined to the half disc
 * x >= 0 of radius 3 about (0, 1/2) (examples/antenna.toml): bottom and top
 * run along the stem (70% of their intervals) and turn at the stem's mouth
 * along the wall x = 0; the right side is the half circle. Sets the sides. */
static int set_antenna(eg2d_grid *g) {
    int ni, nj, k, status, side;
    double *x, *y;
    if ((status = side_buffers(g, &ni, &nj, &x, &y))) return status;
    for (side = 0; side < 4 && !status; ++side) {
        const int n = (side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX) ? ni : nj;
        const int stem = (int)floor(0.7 * (n - 1) + 0.5); /* the stem's intervals: its mouth is a node */
        for (k = 0; k < n; ++k) {
            const double s = (double)k / (n - 1);
            if (side == EG2D_SIDE_IMIN) { x[k] = -3; y[k] = s; }
            else if (side == EG2D_SIDE_IMAX) {
                x[k] = 3 * cos(EG2D_TEST_PI * (s - 0.5));
                y[k] = 0.5 + 3 * sin(EG2D_TEST_PI * (s - 0.5));
            } else {
                const double y_stem = side == EG2D_SIDE_JMIN ? 0 : 1, y_wall = side == EG2D_SIDE_JMIN ? -2.5 : 3.5;
                if (k <= stem) { x[k] = -3 + 3.0 * k / stem; y[k] = y_stem; }
                else { x[k] = 0; y[k] = y_stem + (y_wall - y_stem) * (k - stem) / (n - 1 - stem); }
            }
        }
        status = eg2d_set_side(g, side, x, y);
    }
    free(x);
    free(y);
    return status;
}

static void bil(double u, double v, double *x, double *y) {
    const double X[4] = {0, 2, 2.4, 0.3}, Y[4] = {0, 0.2, 1.6, 1};
    *x = (1 - u) * (1 - v) * X[0] + u * (1 - v) * X[1] + u * v * X[2] + (1 - u) * v * X[3];
    *y = (1 - u) * (1 - v) * Y[0] + u * (1 - v) * Y[1] + u * v * Y[2] + (1 - u) * v * Y[3];
}
static void quadr_b(double s, double *x, double *y) { bil(s, 0, x, y); }
static void quadr_t(double s, double *x, double *y) { bil(s, 1, x, y); }
static void quadr_l(double s, double *x, double *y) { bil(0, s, x, y); }
static void quadr_r(double s, double *x, double *y) { bil(1, s, x, y); }

static int set_curve(eg2d_grid *g, int side, int n, curve_fn f) {
    double *x = malloc(sizeof(double) * (size_t)n), *y = malloc(sizeof(double) * (size_t)n);
    int i, status;
    if (!x || !y) {
        free(x);
        free(y);
        return EG2D_ERR_MEMORY;
    }
    for (i = 0; i < n; ++i) f((double)i / (n - 1), &x[i], &y[i]);
    status = eg2d_set_side(g, side, x, y);
    free(x);
    free(y);
    return status;
}

int domain_set(eg2d_grid *g, const char *name) {
    curve_fn b, r, t, l;
    int ni, nj, status;
    if (!strcmp(name, "valley")) { b = valley_b; r = valley_r; t = valley_t; l = valley_l; }
    else if (!strcmp(name, "almost-convex")) { b = convex_b; r = convex_r; t = convex_t; l = convex_l; }
    else if (!strcmp(name, "swan")) { b = swan_b; r = swan_r; t = swan_t; l = swan_l; }
    else if (!strcmp(name, "dome")) { b = dome_b; r = dome_r; t = dome_t; l = dome_l; }
    else if (!strcmp(name, "quad")) { b = quadr_b; r = quadr_r; t = quadr_t; l = quadr_l; }
    else if (!strcmp(name, "antenna")) return set_antenna(g);
    else return EG2D_ERR_ARGUMENT;
    status = eg2d_get_size(g, &ni, &nj);
    if (status) return status;
    if ((status = set_curve(g, EG2D_SIDE_JMIN, ni, b))) return status;
    if ((status = set_curve(g, EG2D_SIDE_IMAX, nj, r))) return status;
    if ((status = set_curve(g, EG2D_SIDE_JMAX, ni, t))) return status;
    return set_curve(g, EG2D_SIDE_IMIN, nj, l);
}

int domain_set_annulus(eg2d_grid *g, double ri, double ro) {
    int ni, nj, i, status;
    double *x, *y;
    if ((status = eg2d_get_size(g, &ni, &nj))) return status;
    if ((status = eg2d_set_topology(g, EG2D_TOPO_O))) return status;
    x = malloc(sizeof(double) * (size_t)ni);
    y = malloc(sizeof(double) * (size_t)ni);
    if (!x || !y) {
        free(x);
        free(y);
        return EG2D_ERR_MEMORY;
    }
    for (i = 0; i < ni; ++i) {
        const double t = 2 * EG2D_TEST_PI * i / (ni - 1);
        x[i] = ri * cos(t);
        y[i] = ri * sin(t);
    }
    x[ni - 1] = x[0];
    y[ni - 1] = y[0];
    status = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    for (i = 0; i < ni && !status; ++i) {
        x[i] *= ro / ri;
        y[i] *= ro / ri;
    }
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_JMAX, x, y);
    free(x);
    free(y);
    return status;
}

static void rose_fn(void *user, double t, double *x, double *y) {
    const double th = 2 * EG2D_TEST_PI * t, r = 0.3 * (2 + cos(3 * th));
    (void)user;
    *x = r * cos(th);
    *y = r * sin(th);
}

static void circle9_fn(void *user, double t, double *x, double *y) {
    (void)user;
    *x = 9 * cos(2 * EG2D_TEST_PI * t);
    *y = 9 * sin(2 * EG2D_TEST_PI * t);
}

int domain_set_rose(eg2d_grid *g) {
    eg2d_curve *rose = NULL, *circ = NULL;
    int status = eg2d_set_topology(g, EG2D_TOPO_O);
    if (!status) status = eg2d_curve_function(rose_fn, NULL, &rose);
    if (!status) status = eg2d_curve_function(circle9_fn, NULL, &circ);
    if (!status) status = eg2d_set_side_curve(g, EG2D_SIDE_JMIN, rose, EG2D_DIST_UNIFORM, 0, 0, 0);
    if (!status) status = eg2d_set_side_curve(g, EG2D_SIDE_JMAX, circ, EG2D_DIST_UNIFORM, 0, 0, 0);
    eg2d_curve_destroy(rose);
    eg2d_curve_destroy(circ);
    return status;
}

typedef struct { double cx, radius; } far_circle;

static void far_circle_fn(void *user, double t, double *x, double *y) {
    const far_circle *c = (const far_circle *)user;
    *x = c->cx + c->radius * cos(2 * EG2D_TEST_PI * t);
    *y = -c->radius * sin(2 * EG2D_TEST_PI * t);
}

int domain_set_airfoil_o(eg2d_grid *g, const char *digits, double radius) {
    far_circle fc;
    eg2d_curve *foil = NULL, *far = NULL;
    int status;
    fc.cx = 0.5;
    fc.radius = radius;
    if ((status = eg2d_set_topology(g, EG2D_TOPO_O))) return status;
    if ((status = eg2d_curve_naca4(digits, EG2D_NACA_CLOSED_TE, &foil))) return status;
    status = eg2d_curve_function(far_circle_fn, &fc, &far);
    if (!status) status = eg2d_set_side_curve(g, EG2D_SIDE_JMIN, foil, EG2D_DIST_UNIFORM, 0, 0, 0);
    if (!status) status = eg2d_set_side_curve(g, EG2D_SIDE_JMAX, far, EG2D_DIST_UNIFORM, 0, 0, 0);
    eg2d_curve_destroy(foil);
    eg2d_curve_destroy(far);
    return status;
}

/* A C-grid's far field and outflow sides (x holds JMIN's x on entry, ni +
 * nj values of room): JMAX the lines y = -radius, radius above the cut at its
 * nodes' x and the half circle of that radius about the trailing edge (1, 0)
 * between, at the fractions f of its arc (NULL: uniform); IMIN and IMAX the
 * outflow lines x = 1 + radius, uniform. */
static int c_grid_far_sides(eg2d_grid *g, int ni, int nj, int wake, double radius, const double *f, double *x,
                            double *y) {
    const int na = ni - 2 * wake;
    int i, j, status;
    for (i = 0; i < ni; ++i) {
        if (i <= wake || i >= ni - 1 - wake) {
            y[i] = i <= wake ? -radius : radius;
        } else {
            const double a = -EG2D_TEST_PI / 2 - EG2D_TEST_PI * (f ? f[i - wake] : (double)(i - wake) / (na - 1));
            x[i] = 1 + radius * cos(a);
            y[i] = radius * sin(a);
        }
    }
    if ((status = eg2d_set_side(g, EG2D_SIDE_JMAX, x, y))) return status;
    for (j = 0; j < nj; ++j) {
        x[j] = 1 + radius;
        y[j] = -radius * (double)j / (nj - 1);
    }
    if ((status = eg2d_set_side(g, EG2D_SIDE_IMIN, x, y))) return status;
    for (j = 0; j < nj; ++j) y[j] = -y[j];
    return eg2d_set_side(g, EG2D_SIDE_IMAX, x, y);
}

int domain_set_airfoil_c(eg2d_grid *g, const char *digits, int wake, double radius) {
    int ni, nj, na, i, status;
    double *x, *y;
    eg2d_curve *foil = NULL;
    if ((status = eg2d_get_size(g, &ni, &nj))) return status;
    na = ni - 2 * wake;
    if (wake < 2 || na < 5) return EG2D_ERR_ARGUMENT;
    if ((status = eg2d_set_topology(g, EG2D_TOPO_C))) return status;
    x = malloc(sizeof(double) * (size_t)(ni + nj));
    y = malloc(sizeof(double) * (size_t)(ni + nj));
    if (!x || !y) {
        free(x);
        free(y);
        return EG2D_ERR_MEMORY;
    }
    status = eg2d_curve_naca4(digits, EG2D_NACA_CLOSED_TE, &foil);
    if (!status) status = eg2d_curve_points(foil, na, EG2D_DIST_UNIFORM, 0, 0, x + wake, y + wake);
    eg2d_curve_destroy(foil);
    for (i = 0; i < wake; ++i) { /* the wake, uniform from the outflow x = 1 + radius to the TE */
        x[i] = x[ni - 1 - i] = 1 + radius * (double)(wake - i) / wake;
        y[i] = y[ni - 1 - i] = 0;
    }
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    if (!status) status = c_grid_far_sides(g, ni, nj, wake, radius, NULL, x, y);
    free(x);
    free(y);
    return status;
}

/* The ratio r of n geometric cells from `first` that add up to `length`. */
static double geometric_ratio(double first, double length, int n) {
    double lo = 1.0, hi = 2.0;
    for (int it = 0; it < 200; ++it) {
        const double r = 0.5 * (lo + hi);
        if (first * (pow(r, n) - 1) / (r - 1) < length) lo = r;
        else hi = r;
    }
    return 0.5 * (lo + hi);
}

int domain_set_airfoil_c_graded(eg2d_grid *g, const char *digits, int wake, double radius, double le, double te) {
    int ni, nj, na, half, i, status;
    double *x, *y, *s, *s2, length, s_le = 0.5, lo = 0.0, hi = 1.0;
    eg2d_curve *foil = NULL;
    if ((status = eg2d_get_size(g, &ni, &nj))) return status;
    na = ni - 2 * wake;
    if (wake < 2 || na < 5 || na % 2 == 0) return EG2D_ERR_ARGUMENT;
    half = na / 2;
    if ((status = eg2d_set_topology(g, EG2D_TOPO_C))) return status;
    if ((status = eg2d_curve_naca4(digits, EG2D_NACA_CLOSED_TE, &foil))) return status;
    x = malloc(sizeof(double) * (size_t)(ni + nj));
    y = malloc(sizeof(double) * (size_t)(ni + nj));
    s = malloc(sizeof(double) * (size_t)(half + 1));
    s2 = malloc(sizeof(double) * (size_t)na);
    if (!x || !y || !s || !s2) {
        free(x); free(y); free(s); free(s2);
        eg2d_curve_destroy(foil);
        return EG2D_ERR_MEMORY;
    }
    eg2d_curve_length(foil, &length);
    for (i = 0; i < 200; ++i) { /* the leading edge: ternary search for the least x */
        double xa, xb, ya;
        const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
        eg2d_curve_evaluate(foil, a, &xa, &ya);
        eg2d_curve_evaluate(foil, b, &xb, &ya);
        if (xa < xb) hi = b;
        else lo = a;
    }
    s_le = 0.5 * (lo + hi);
    status = eg2d_distribution(EG2D_DIST_VINOKUR, half + 1, te / (s_le * length), le / (s_le * length), s);
    for (i = 0; !status && i <= half; ++i) status = eg2d_curve_evaluate(foil, s_le * s[i], x + wake + i, y + wake + i);
    if (!status)
        status = eg2d_distribution(EG2D_DIST_VINOKUR, half + 1, le / ((1 - s_le) * length), te / ((1 - s_le) * length), s);
    for (i = 0; !status && i <= half; ++i)
        status = eg2d_curve_evaluate(foil, s_le + (1 - s_le) * s[i], x + wake + half + i, y + wake + half + i);
    eg2d_curve_destroy(foil);
    if (!status) {
        const double ds = hypot(x[wake + 1] - x[wake], y[wake + 1] - y[wake]), r = geometric_ratio(ds, radius, wake);
        double cell = ds, at = 1.0;
        x[wake] = x[ni - 1 - wake] = 1.0;
        y[wake] = y[ni - 1 - wake] = 0.0;
        for (i = wake - 1; i >= 0; --i, cell *= r) {
            at += cell;
            x[i] = x[ni - 1 - i] = i == 0 ? 1 + radius : at;
            y[i] = y[ni - 1 - i] = 0;
        }
        status = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    }
    /* The far field: the same x above the wake, a half circle about the TE
     * between, its nodes by Vinokur's distribution from the wake's spacing
     * at the TE on to both ends (no jump in spacing where the two meet). */
    if (!status)
        status = eg2d_distribution(EG2D_DIST_VINOKUR, na, te / (EG2D_TEST_PI * radius), te / (EG2D_TEST_PI * radius), s2);
    if (!status) status = c_grid_far_sides(g, ni, nj, wake, radius, s2, x, y);
    free(x); free(y); free(s); free(s2);
    return status;
}

int domain_set_rectangle_columns(eg2d_grid *g, const double *X, double height) {
    int ni, nj, i, status;
    double *x, *y;
    if ((status = side_buffers(g, &ni, &nj, &x, &y))) return status;
    for (i = 0; i < ni; ++i) { x[i] = X[i]; y[i] = 0.0; }
    status = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    for (i = 0; i < ni; ++i) y[i] = height;
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_JMAX, x, y);
    for (i = 0; i < nj; ++i) { x[i] = 0.0; y[i] = height * i / (nj - 1); }
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_IMIN, x, y);
    for (i = 0; i < nj; ++i) x[i] = 1.0;
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_IMAX, x, y);
    free(x);
    free(y);
    return status;
}

int domain_set_blob(eg2d_grid *g) {
    int ni, nj, i, status;
    double *x, *y;
    if ((status = eg2d_get_size(g, &ni, &nj))) return status;
    x = malloc(sizeof(double) * (size_t)ni * 2);
    if (!x) return EG2D_ERR_MEMORY;
    y = x + ni;
    for (i = 0; i < ni; ++i) {
        const double t = 2 * EG2D_TEST_PI * i / (ni - 1);
        const double r = 1 + 0.25 * cos(2 * t) + 0.15 * sin(3 * t) + 0.08 * cos(5 * t);
        x[i] = r * cos(t);
        y[i] = r * sin(t);
    }
    x[ni - 1] = x[0];
    y[ni - 1] = y[0];
    status = eg2d_set_topology(g, EG2D_TOPO_O);
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_JMIN, x, y);
    for (i = 0; i < ni; ++i) {
        const double t = 2 * EG2D_TEST_PI * i / (ni - 1);
        x[i] = 8 * cos(t);
        y[i] = 8 * sin(t);
    }
    x[ni - 1] = x[0];
    y[ni - 1] = y[0];
    if (!status) status = eg2d_set_side(g, EG2D_SIDE_JMAX, x, y);
    free(x);
    return status;
}
