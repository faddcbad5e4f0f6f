/* --sweep: multigrid at every kind of size, side by side with the nearest
 * 2^k+1 size in the same run (any-size coarsening; the targets: at most 2x
 * the cycles and 2x the cost per node of that size). Cases: the swan
 * (n x n), the annulus O-grid (n x (n/2+1)) and the NACA 0012 C-grid
 * (n x (n/4+1)), at 2^k, 2^k+1, 2^k+2 and round sizes from 65 to 1025, and
 * the rectangular 385x97, 897x257 and 250x100. Prints a markdown table;
 * with --svg FILE also a picture of cycles and microseconds per node
 * against n. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

static const int kSizes[] = {65,  66,  100, 127, 128, 129, 130, 200, 250, 255,  256,  257,
                             258, 300, 500, 511, 512, 513, 514, 1000, 1023, 1024, 1025};
#define N_SIZES ((int)(sizeof kSizes / sizeof kSizes[0]))

typedef struct {
    const char *name;
    int ni, nj;
} shape;

/* The 2^k+1 count nearest to n (on a log scale). */
static int nearest_pow2_plus1(int n) {
    const int k = (int)floor(log2((double)(n - 1)) + 0.5);
    return (1 << k) + 1;
}

typedef struct {
    int ni, nj, cycles;
    double seconds, us_per_node, factor;
    const char *status;
} point;

static point measure(const bench_case *c, int ni, int nj, int repeats) {
    const bench_result r = bench_run(c, ni, nj, EG2D_SOLVER_MULTIGRID, 0.0, EG2D_SYSTEM_WINSLOW, 1e-10, 60, repeats);
    point p;
    p.ni = ni;
    p.nj = nj;
    p.cycles = r.iterations;
    p.seconds = r.cpu;
    p.us_per_node = 1e6 * r.cpu / ((double)ni * nj);
    p.factor = r.iterations > 1 && r.r1 > 0 ? pow(r.residual / r.r1, 1.0 / (r.iterations - 1)) : NAN;
    p.status = r.status;
    return p;
}

/* One polyline per case into an SVG panel of width w at (x0, y0). */
static void svg_panel(FILE *f, double x0, double y0, double w, double h, const char *title, const point pts[][N_SIZES],
                      int ncases, const char *const names[], int cycles) {
    static const char *const colour[] = {"#1f77b4", "#d62728", "#2ca02c"};
    double vmax = 0;
    int c, s;
    for (c = 0; c < ncases; ++c)
        for (s = 0; s < N_SIZES; ++s) vmax = fmax(vmax, cycles ? pts[c][s].cycles : pts[c][s].us_per_node);
    vmax = cycles ? ceil(vmax + 1) : ceil(vmax * 1.1 * 10) / 10;
    fprintf(f, "<rect x='%g' y='%g' width='%g' height='%g' fill='none' stroke='#888'/>\n", x0, y0, w, h);
    fprintf(f, "<text x='%g' y='%g' font-size='13'>%s</text>\n", x0, y0 - 6, title);
    for (s = 0; s <= 4; ++s) {
        const double v = vmax * s / 4, y = y0 + h - h * s / 4;
        fprintf(f, "<text x='%g' y='%g' font-size='10' text-anchor='end'>%.*f</text>\n", x0 - 4, y + 3,
                cycles ? 0 : 2, v);
    }
    for (s = 65; s <= 1025; s = 2 * s - 1) {
        const double x = x0 + w * log2((s - 1) / 64.0) / 4.0;
        fprintf(f, "<line x1='%g' y1='%g' x2='%g' y2='%g' stroke='#ddd'/>\n", x, y0, x, y0 + h);
        fprintf(f, "<text x='%g' y='%g' font-size='10' text-anchor='middle'>%d</text>\n", x, y0 + h + 12, s);
    }
    for (c = 0; c < ncases; ++c) {
        fprintf(f, "<polyline fill='none' stroke='%s' stroke-width='1.5' points='", colour[c]);
        for (s = 0; s < N_SIZES; ++s) {
            const point *p = &pts[c][s];
            const double v = cycles ? p->cycles : p->us_per_node;
            fprintf(f, "%.1f,%.1f ", x0 + w * log2((p->ni - 1) / 64.0) / 4.0, y0 + h - h * v / vmax);
        }
        fprintf(f, "'/>\n<text x='%g' y='%g' font-size='11' fill='%s'>%s</text>\n", x0 + w + 6,
                y0 + 14 + 14 * c, colour[c], names[c]);
    }
}

void bench_sweep(int repeats, const char *svg_path) {
    const char *const names[] = {"swan", "annulus", "naca0012-c"};
    static point pts[3][N_SIZES];
    const shape extra[] = {{"naca0012-c", 385, 97}, {"naca0012-c", 897, 257}, {"annulus", 250, 100},
                           {"swan", 250, 100}};
    int c, s, worst_ok = 1;
    printf("Multigrid (default settings), Winslow, TFI start, residual 1e-10; CPU s of this thread, median of %d.\n"
           "ratio: against the nearest 2^k+1 size of the same case in this run (cycles, microseconds per node).\n\n",
           repeats);
    printf("| case | size | cycles | CPU s | us/node | factor/cycle | nearest 2^k+1 | cycle ratio | cost ratio | status |\n");
    printf("|---|---|---:|---:|---:|---:|---|---:|---:|---|\n");
    for (c = 0; c < 3; ++c) {
        const bench_case *bc = bench_find_case(names[c]);
        for (s = 0; s < N_SIZES; ++s) pts[c][s] = measure(bc, kSizes[s], bc->size_nj(kSizes[s]), repeats);
        for (s = 0; s < N_SIZES; ++s) {
            const point *p = &pts[c][s], *ref = NULL;
            const int m = nearest_pow2_plus1(p->ni);
            int k;
            double rc, ru;
            for (k = 0; k < N_SIZES; ++k)
                if (pts[c][k].ni == m) ref = &pts[c][k];
            rc = ref ? (double)p->cycles / ref->cycles : NAN;
            ru = ref ? p->us_per_node / ref->us_per_node : NAN;
            if (!(rc <= 2 && ru <= 2) || strcmp(p->status, "ok")) worst_ok = 0;
            printf("| %s | %dx%d | %d | %.3f | %.3f | %.4f | %dx%d | %.2f | %.2f | %s |\n", names[c], p->ni, p->nj,
                   p->cycles, p->seconds, p->us_per_node, p->factor, m, bc->size_nj(m), rc, ru, p->status);
        }
    }
    for (s = 0; s < (int)(sizeof extra / sizeof extra[0]); ++s) {
        const bench_case *bc = bench_find_case(extra[s].name);
        const point p = measure(bc, extra[s].ni, extra[s].nj, repeats);
        printf("| %s | %dx%d | %d | %.3f | %.3f | %.4f | | | | %s |\n", extra[s].name, p.ni, p.nj, p.cycles, p.seconds,
               p.us_per_node, p.factor, p.status);
    }
    printf("\nevery sweep size within 2x the cycles and 2x the cost per node of its nearest 2^k+1 size: %s\n",
           worst_ok ? "yes" : "NO");
    if (svg_path) {
        FILE *f = fopen(svg_path, "w");
        if (!f) {
            perror(svg_path);
            return;
        }
        fprintf(f, "<svg xmlns='http://www.w3.org/2000/svg' width='900' height='300' font-family='sans-serif'>\n"
                   "<rect width='900' height='300' fill='white'/>\n");
        svg_panel(f, 50, 30, 300, 220, "multigrid cycles to 1e-10 against n (log scale)", pts, 3, names, 1);
        svg_panel(f, 500, 30, 300, 220, "CPU microseconds per node against n", pts, 3, names, 0);
        fprintf(f, "</svg>\n");
        fclose(f);
        printf("picture: %s\n", svg_path);
    }
}
