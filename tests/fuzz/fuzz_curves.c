/* libFuzzer harness of the curve and distribution calls (no grid): curves
 * through broken point sets (polyline, spline), NACA digits from the bytes,
 * then lengths, points at any s, point distributions and clustering maps with
 * edge-case parameters. Every status must be documented with a message naming
 * the call; every point given out must be finite. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eg2d.h"
#include "fuzz_input.h"

#define MAXP 40

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check(const char *function, int status) {
    const char *m;
    if (status == EG2D_OK) return;
    m = eg2d_last_error(NULL);
    if (status < 1 || status > 10 || strncmp(m, function, strlen(function)) != 0 || m[strlen(function)] != ':') {
        fprintf(stderr, "%s: status %d, message \"%s\"\n", function, status, m);
        abort();
    }
}

static void all_finite(const double *v, int n, const char *what) {
    int k;
    for (k = 0; k < n; ++k)
        if (!isfinite(v[k])) {
            fprintf(stderr, "fuzz_curves: %s[%d] = %g\n", what, k, v[k]);
            abort();
        }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fuzz_input in = {data, size, 0};
    double x[MAXP], y[MAXP], s[MAXP], u[MAXP], v[MAXP], gs[MAXP * MAXP], gt[MAXP * MAXP], d, e;
    eg2d_curve *c = NULL;
    int n = fuzz_below(&in, MAXP + 1), k, rc, kind = fuzz_below(&in, 3);
    /* A curve: points on a circle arc or a line, broken like fuzz_api's sides. */
    for (k = 0; k < n; ++k) {
        const double t = n > 1 ? (double)k / (n - 1) : 0;
        x[k] = kind == 1 ? cos(6.283185307179586 * t) : t;
        y[k] = kind == 1 ? sin(6.283185307179586 * t) : 0.25 * t * t;
    }
    for (k = fuzz_below(&in, 4); k > 0 && n > 0; --k) {
        const int p = fuzz_below(&in, n);
        if (fuzz_u8(&in) & 1) x[p] = fuzz_double(&in);
        else y[p] = fuzz_double(&in);
        if (fuzz_u8(&in) == 7 && p + 1 < n) { x[p + 1] = x[p]; y[p + 1] = y[p]; } /* duplicate */
    }
    if (kind == 2) {
        char digits[8];
        int flags = fuzz_u8(&in) < 128 ? EG2D_NACA_CLOSED_TE : fuzz_int(&in);
        for (k = 0; k < 7; ++k) digits[k] = (char)(fuzz_u8(&in) < 200 ? '0' + fuzz_below(&in, 10) : fuzz_u8(&in));
        digits[fuzz_below(&in, 8)] = '\0';
        digits[7] = '\0';
        rc = eg2d_curve_naca4(fuzz_u8(&in) == 255 ? NULL : digits, flags, &c);
        check("eg2d_curve_naca4", rc);
    } else {
        const int count = fuzz_u8(&in) < 240 ? n : fuzz_int(&in), spline = fuzz_u8(&in) & 1;
        rc = spline ? eg2d_curve_spline(count < 0 || count > n ? n : count, x, y, &c)
                    : eg2d_curve_polyline(count < 0 || count > n ? n : count, x, y, &c);
        check(spline ? "eg2d_curve_spline" : "eg2d_curve_polyline", rc);
    }
    if ((rc == EG2D_OK) != (c != NULL)) abort();
    if (c) {
        rc = eg2d_curve_length(c, &d);
        check("eg2d_curve_length", rc);
        if (rc == EG2D_OK && !(d >= 0 && isfinite(d))) abort();
        for (k = 0; k < 4; ++k) {
            rc = eg2d_curve_evaluate(c, fuzz_double(&in), &d, &e);
            check("eg2d_curve_evaluate", rc);
            if (rc == EG2D_OK && !(isfinite(d) && isfinite(e))) abort();
        }
        n = fuzz_below(&in, MAXP + 1);
        d = fuzz_double(&in);
        e = fuzz_double(&in);
        rc = eg2d_curve_points(c, n, fuzz_u8(&in) < 200 ? fuzz_below(&in, 5) : fuzz_int(&in), d, e, x, y);
        check("eg2d_curve_points", rc);
        if (rc == EG2D_OK) {
            all_finite(x, n, "curve x");
            all_finite(y, n, "curve y");
        }
        eg2d_curve_destroy(c);
    }
    /* Distributions and the parameter-grid helpers. */
    n = fuzz_u8(&in) < 240 ? fuzz_below(&in, MAXP + 1) : fuzz_int(&in);
    if (n > MAXP) n = MAXP;
    d = fuzz_double(&in);
    e = fuzz_double(&in);
    rc = eg2d_distribution(fuzz_u8(&in) < 200 ? fuzz_below(&in, 5) : fuzz_int(&in), n, d, e, s);
    check("eg2d_distribution", rc);
    if (rc == EG2D_OK) all_finite(s, n, "s");
    d = fuzz_double(&in);
    e = fuzz_double(&in);
    rc = eg2d_clustering_map(fuzz_below(&in, 4), d, e, fuzz_double(&in), n, u);
    check("eg2d_clustering_map", rc);
    if (rc == EG2D_OK) {
        all_finite(u, n, "u");
        for (k = 0; k < n; ++k) v[k] = n > 1 ? (double)k / (n - 1) : 0;
        rc = eg2d_tensor_parameter_grid(n, fuzz_u8(&in) & 1 ? n : 2, u, v, gs, gt);
        check("eg2d_tensor_parameter_grid", rc);
    }
    d = fuzz_double(&in);
    e = fuzz_double(&in);
    rc = eg2d_first_cell_height(d, e, fuzz_double(&in), &d);
    check("eg2d_first_cell_height", rc);
    if (rc == EG2D_OK && !(d > 0 && isfinite(d))) abort();
    return 0;
}
