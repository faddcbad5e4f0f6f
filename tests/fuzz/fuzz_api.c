/* libFuzzer harness of the C API: the bytes are a program of up to 48 calls
 * (sizes, topology, sides and whole grids built from a square or a circle
 * and then broken: NaN, Inf, huge and tiny values, duplicate points,
 * zero-length, reversed, shifted and self-intersecting sides; systems,
 * solvers, every parameter, sources, orthogonality, weights, parameter
 * grids, AF settings, sides on curves, iterate/solve, queries). A monitor caps the
 * iterations of one input at 300 so each input is fast.
 *
 * Besides the sanitizers, the harness asserts the API's promises and aborts
 * (a crash for libFuzzer) when one is broken: a documented status; a message
 * naming the function on failure; a failed call other than a run changes
 * nothing observable; coordinates are always finite; a successful solve is
 * within the tolerance. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eg2d.h"
#include "fuzz_input.h"

#define MAXN 24
#define MAX_CALLS 48
#define ITERATION_BUDGET 300

typedef struct {
    int used, stop_at;
} budget;

static int budget_monitor(void *user, int iteration, double residual) {
    budget *b = (budget *)user;
    (void)residual;
    ++b->used;
    return b->used >= ITERATION_BUDGET || iteration == b->stop_at;
}

static void promise(int ok, const char *what) {
    if (!ok) {
        fprintf(stderr, "fuzz_api: broken promise: %s\n", what);
        abort();
    }
}

/* Every parameter id the library has (found once; new ones join by themselves). */
#define MAX_PARAMS 64
static int param_ids[MAX_PARAMS], nparams = -1;

static void find_parameters(void) {
    int id;
    double lo, hi, def;
    nparams = 0;
    for (id = 0; id < 1000 && nparams < MAX_PARAMS; ++id)
        if (eg2d_parameter_bounds(id, &lo, &hi, &def) == EG2D_OK) param_ids[nparams++] = id;
}

/* What a caller can observe without running anything. */
typedef struct {
    int ni, nj, topology, solver, iterations, rc_coords;
    double params[MAX_PARAMS];
    double x[MAXN * MAXN], y[MAXN * MAXN];
} observed;

static void observe(const eg2d_grid *g, observed *o) {
    int k;
    memset(o, 0, sizeof *o);
    eg2d_get_size(g, &o->ni, &o->nj);
    eg2d_get_topology(g, &o->topology);
    eg2d_get_solver(g, &o->solver);
    eg2d_get_iterations(g, &o->iterations);
    for (k = 0; k < nparams; ++k) eg2d_get_parameter(g, param_ids[k], &o->params[k]);
    o->rc_coords = eg2d_get_coordinates(g, o->x, o->y);
    if (o->rc_coords == EG2D_OK)
        for (k = 0; k < o->ni * o->nj; ++k) promise(isfinite(o->x[k]) && isfinite(o->y[k]), "finite coordinates");
}

/* n points of side `side` of the square [0, s]^2 (or, on an O-grid, a
 * closed circle of radius s, or 2s for JMAX), then broken by the input. */
static void make_side(fuzz_input *in, int side, int n, int ogrid, double *x, double *y) {
    const double s = fuzz_u8(in) < 200 ? 1.0 : fuzz_double(in);
    int p, m, mutations = fuzz_below(in, 4);
    for (p = 0; p < n; ++p) {
        const double t = (double)p / (n - 1);
        if (ogrid) {
            const double r = side == 2 ? 2 * s : s, a = 6.283185307179586 * t;
            x[p] = p == n - 1 ? r : r * cos(a);
            y[p] = p == n - 1 ? 0 : r * sin(a);
        } else {
            x[p] = s * (side == 1 ? 1 : side == 3 ? 0 : t);
            y[p] = s * (side == 2 ? 1 : side == 0 ? 0 : t);
        }
    }
    for (m = 0; m < mutations; ++m) {
        const int k = fuzz_below(in, n), what = fuzz_below(in, 7);
        switch (what) {
        case 0: x[k] = fuzz_double(in); break;                 /* one value: NaN, Inf, huge, ... */
        case 1: y[k] = fuzz_double(in); break;
        case 2:                                                 /* reversed */
            for (p = 0; p < n / 2; ++p) {
                double t = x[p];
                x[p] = x[n - 1 - p];
                x[n - 1 - p] = t;
                t = y[p];
                y[p] = y[n - 1 - p];
                y[n - 1 - p] = t;
            }
            break;
        case 3:                                                 /* zero length: all one point */
            for (p = 1; p < n; ++p) {
                x[p] = x[0];
                y[p] = y[0];
            }
            break;
        case 4:                                                 /* a duplicate point */
            if (k + 1 < n) {
                x[k + 1] = x[k];
                y[k + 1] = y[k];
            }
            break;
        case 5: {                                               /* across the domain: self-intersecting */
            const double d = fuzz_double(in);
            for (p = 1; p < n - 1; ++p) y[p] += (p % 2 ? d : -d);
            break;
        }
        default: {                                              /* shifted: corners disagree */
            const double d = fuzz_double(in);
            for (p = 0; p < n; ++p) x[p] += d;
        }
        }
    }
}

/* Whole-grid arrays: the square's bilinear grid, a few values broken. */
static void make_grid(fuzz_input *in, int ni, int nj, double *x, double *y) {
    int k, m, mutations = fuzz_below(in, 4);
    for (k = 0; k < ni * nj; ++k) {
        x[k] = (double)(k % ni) / (ni - 1);
        y[k] = (double)(k / ni) / (nj - 1);
    }
    for (m = 0; m < mutations; ++m) {
        k = (int)((fuzz_u8(in) << 8 | fuzz_u8(in)) % (ni * nj));
        if (fuzz_u8(in) & 1) x[k] = fuzz_double(in);
        else y[k] = fuzz_double(in);
    }
}

/* A size: small and valid mostly, sometimes any int (invalid ones are
 * refused by eg2d_create; valid big ones are not tried: a fuzzer must not
 * allocate gigabytes). */
static int make_size(fuzz_input *in) {
    const uint8_t sel = fuzz_u8(in);
    if (sel < 224) return 3 + sel % (MAXN - 2);
    {
        const int v = fuzz_int(in);
        return v >= 3 && v <= MAXN ? v : (v > MAXN ? -v : v);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fuzz_input in = {data, size, 0};
    budget b = {0, -1};
    static double x[MAXN * MAXN], y[MAXN * MAXN];
    static observed before, after;
    eg2d_grid *g = NULL;
    int ni = make_size(&in), nj = make_size(&in), calls, rc;
    const int trace = getenv("EG2D_FUZZ_TRACE") != NULL; /* prints each call: for reading a crash */
    static double p[MAXN * MAXN], q[MAXN * MAXN];

    if (nparams < 0) find_parameters();

    rc = eg2d_create(ni, nj, &g);
    promise(rc == EG2D_OK || rc == EG2D_ERR_ARGUMENT, "eg2d_create status");
    if (rc != EG2D_OK) {
        promise(g == NULL, "*grid is NULL after a failed create");
        promise(strncmp(eg2d_last_error(NULL), "eg2d_create: ", 13) == 0, "eg2d_create message");
        return 0;
    }
    eg2d_set_monitor(g, budget_monitor, &b);

    for (calls = 0; calls < MAX_CALLS && !fuzz_done(&in); ++calls) {
        int topology = 0, is_run = 0, v, k;
        double d, t;
        const char *name = "";
        eg2d_get_topology(g, &topology);
        observe(g, &before);
        switch (fuzz_below(&in, 30)) {
        case 0: name = "eg2d_set_topology"; rc = eg2d_set_topology(g, fuzz_int(&in)); break;
        case 1:
        case 2:
        case 3: {
            const int side = fuzz_u8(&in) < 240 ? fuzz_below(&in, 4) : fuzz_int(&in);
            const int n = (side == 0 || side == 2) ? ni : nj;
            make_side(&in, side, n, topology == EG2D_TOPO_O, x, y);
            name = "eg2d_set_side";
            rc = eg2d_set_side(g, side, fuzz_u8(&in) == 255 ? NULL : x, y);
            break;
        }
        case 4: {
            /* A whole square's ring at once (other sides are then consistent). */
            int side, p;
            double sx[MAXN], sy[MAXN];
            for (side = 0; side < 4; ++side) {
                const int n = (side == 0 || side == 2) ? ni : nj;
                make_side(&in, side, n, topology == EG2D_TOPO_O, sx, sy);
                for (p = 0; p < n; ++p) {
                    const int idx = side == 0 ? p : side == 1 ? ni - 1 + ni * p : side == 2 ? p + ni * (nj - 1) : ni * p;
                    x[idx] = sx[p];
                    y[idx] = sy[p];
                }
            }
            name = "eg2d_set_boundary";
            rc = eg2d_set_boundary(g, x, y);
            break;
        }
        case 5:
            make_grid(&in, ni, nj, x, y);
            name = "eg2d_set_coordinates";
            rc = eg2d_set_coordinates(g, x, y);
            break;
        case 6: name = "eg2d_initialize"; rc = eg2d_initialize(g, fuzz_u8(&in) < 200 ? EG2D_INIT_TFI : fuzz_int(&in)); break;
        case 7: name = "eg2d_set_system"; rc = eg2d_set_system(g, fuzz_int(&in)); break;
        case 8: name = "eg2d_set_solver"; rc = eg2d_set_solver(g, fuzz_int(&in)); break;
        case 9: name = "eg2d_set_relaxation"; rc = eg2d_set_relaxation(g, fuzz_double(&in)); break;
        case 10: name = "eg2d_set_tolerance"; rc = eg2d_set_tolerance(g, fuzz_double(&in)); break;
        case 11: name = "eg2d_set_max_iterations"; rc = eg2d_set_max_iterations(g, fuzz_int(&in)); break;
        case 12:
            v = fuzz_u8(&in) < 220 ? param_ids[fuzz_below(&in, nparams)] : fuzz_int(&in);
            name = "eg2d_set_parameter";
            rc = eg2d_set_parameter(g, v, fuzz_double(&in));
            break;
        case 13:
            name = "eg2d_set_monitor";
            b.stop_at = fuzz_int(&in);
            rc = eg2d_set_monitor(g, budget_monitor, &b);
            break;
        case 14:
        case 15:
            is_run = 1;
            name = "eg2d_iterate";
            v = fuzz_int(&in);
            rc = eg2d_iterate(g, v, fuzz_u8(&in) & 1 ? &d : NULL);
            break;
        case 16:
            is_run = 1;
            name = "eg2d_solve";
            rc = eg2d_solve(g);
            if (rc == EG2D_OK) {
                promise(eg2d_get_residual(g, &d) == EG2D_OK, "residual after a solve");
                eg2d_get_parameter(g, EG2D_PARAM_TOLERANCE, &t);
                promise(d <= t, "a successful solve is within the tolerance");
            }
            break;
        /* Control functions (sources, orthogonality, adaptivity) and AF settings. */
        case 18:
            name = "eg2d_add_line_source";
            v = fuzz_int(&in);
            d = fuzz_double(&in);
            t = fuzz_double(&in);
            rc = eg2d_add_line_source(g, v, d, t, fuzz_double(&in));
            break;
        case 19:
            name = "eg2d_add_point_source";
            d = fuzz_double(&in);
            t = fuzz_double(&in);
            rc = eg2d_add_point_source(g, d, t, fuzz_double(&in), fuzz_double(&in));
            break;
        case 20: name = "eg2d_clear_sources"; rc = eg2d_clear_sources(g); break;
        case 21:
            make_grid(&in, ni, nj, p, q);
            name = "eg2d_set_source_arrays";
            v = fuzz_u8(&in);
            rc = eg2d_set_source_arrays(g, v & 1 ? p : NULL, v & 2 ? q : NULL);
            break;
        case 22: name = "eg2d_set_orthogonality"; rc = eg2d_set_orthogonality(g, fuzz_int(&in)); break;
        case 23:
            name = "eg2d_set_wall_spacing";
            v = fuzz_u8(&in) < 200 ? fuzz_below(&in, 4) : fuzz_int(&in);
            rc = eg2d_set_wall_spacing(g, v, fuzz_double(&in));
            break;
        case 24:
            make_grid(&in, ni, nj, p, q);
            for (k = 0; k < ni * nj; ++k) p[k] = 1 + fabs(p[k] - q[k]); /* positive mostly */
            name = "eg2d_set_weight";
            rc = eg2d_set_weight(g, fuzz_u8(&in) == 255 ? NULL : p);
            break;
        case 25:
            make_grid(&in, ni, nj, p, q);
            name = "eg2d_set_parameter_grid";
            rc = eg2d_set_parameter_grid(g, fuzz_u8(&in) == 255 ? NULL : p, q);
            break;
        case 26:
            name = "eg2d_set_af_cycle";
            d = fuzz_double(&in);
            t = fuzz_double(&in);
            rc = eg2d_set_af_cycle(g, d, t, fuzz_int(&in));
            break;
        case 27:
            name = "eg2d_set_af_time_rule";
            d = fuzz_double(&in);
            rc = eg2d_set_af_time_rule(g, d, fuzz_double(&in));
            break;
        case 28: {
            /* A side on a curve through broken side points, any distribution and flags. */
            const int side = fuzz_below(&in, 4), n = (side == 0 || side == 2) ? ni : nj;
            eg2d_curve *c = NULL;
            make_side(&in, side, n, topology == EG2D_TOPO_O, x, y);
            if (trace)
                for (k = 0; k < n; ++k) fprintf(stderr, "  curve point %d: (%.17g, %.17g)\n", k, x[k], y[k]);
            k = fuzz_u8(&in) & 1 ? eg2d_curve_spline(n, x, y, &c) : eg2d_curve_polyline(n, x, y, &c);
            promise(k == EG2D_OK ? c != NULL : c == NULL, "a curve or NULL");
            name = "eg2d_set_side_curve";
            v = fuzz_u8(&in) < 200 ? fuzz_below(&in, 5) : fuzz_int(&in);
            d = fuzz_double(&in);
            t = fuzz_double(&in);
            rc = c ? eg2d_set_side_curve(g, side, c, v, d, t, fuzz_below(&in, 8)) : EG2D_OK;
            eg2d_curve_destroy(c);
            break;
        }
        default:
            /* Queries with any ids; they change nothing. */
            v = fuzz_int(&in);
            k = eg2d_get_residual(g, &d);
            /* STATE before an interior exists, ARGUMENT when controls make the equations non-finite. */
            if (!(k == EG2D_OK ? isfinite(d) : k == EG2D_ERR_STATE || k == EG2D_ERR_ARGUMENT))
                fprintf(stderr, "eg2d_get_residual: %d, %g, %s\n", k, d, eg2d_last_error(g));
            promise(k == EG2D_OK ? isfinite(d) : k == EG2D_ERR_STATE || k == EG2D_ERR_ARGUMENT, "eg2d_get_residual");
            promise(eg2d_status_string(v) != NULL, "eg2d_status_string is never NULL");
            (void)eg2d_solver_name(v);
            {
                double lo, hi, def;
                k = eg2d_parameter_bounds(v, &lo, &hi, &def);
                promise(k == EG2D_OK || k == EG2D_ERR_ARGUMENT, "eg2d_parameter_bounds status");
                if (k == EG2D_OK) promise(eg2d_get_parameter(g, v, &d) == EG2D_OK, "a known parameter reads");
            }
            name = "eg2d_get_quality";
            rc = eg2d_get_quality(g, v, &d);
            promise(rc == EG2D_OK || rc == EG2D_ERR_ARGUMENT || rc == EG2D_ERR_STATE, "eg2d_get_quality status");
            break;
        }
        if (trace) fprintf(stderr, "%-24s -> %d %s\n", name, rc, rc ? eg2d_last_error(g) : "");
        promise(rc >= EG2D_OK && rc <= EG2D_ERR_INTERRUPTED, "a documented status");
        if (rc != EG2D_OK) {
            const char *m = eg2d_last_error(g);
            promise(strncmp(m, name, strlen(name)) == 0 && m[strlen(name)] == ':', "the message names the call");
        }
        observe(g, &after);
        if (rc != EG2D_OK && !is_run) promise(memcmp(&before, &after, sizeof before) == 0, "a failed call changes nothing");
    }
    eg2d_destroy(g);
    return 0;
}
