/* Wall-resolved grids of internal flows side by side (eg2d_bench --internal):
 * NASA TMR's flat plate and bump-in-channel (their boundary points and wall
 * stretches as published), a straight channel with one wall, a bend, an
 * S-shaped diffuser, a body in a pipe, two walls meeting at a corner and a
 * cavity (tests/support/internal.h), at
 * the sizes users pick, each solved three ways from the
 * same boundary with the default solver, residual 1e-10:
 *   none     no wall control (the time the layer is measured against);
 *   before   EG2D_ORTHO_WALL with EG2D_PARAM_WALL_LAYER 0: the Sorenson-type
 *            control alone, what these walls got before the graded layer;
 *   default  EG2D_ORTHO_WALL and the heights, nothing else set (the graded
 *            layer, src/grid/graded_layer.hpp).
 * Columns: status, multigrid cycles, CPU seconds (median of 3; see kShortest) and their
 * ratio to "none" in the same run, then eg2d_get_wall_layer's figures at
 * each wall side (first cell median and range, growth over 30 cells, the
 * angle from the wall normal), the largest skewness and the folded cells. */
#include <malloc.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "internal.h"

typedef enum { PLATE, BUMP, CHANNEL, BEND, DIFFUSER, PIPE, CAVITY, CORNER } domain;

typedef struct {
    const char *name;
    domain d;
    int ni, nj, topology;
    int walls;  /* a mask of 1 << side */
    double h;
} internal_case;

typedef enum { NONE, BEFORE, DEFAULT } method;
static const char *const method_name[] = {"none", "before", "default"};

static int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int set_domain(eg2d_grid *g, const internal_case *c) {
    if (c->topology != EG2D_TOPO_SINGLE) eg2d_set_topology(g, c->topology);
    switch (c->d) {
    case PLATE: return domain_set_tmr(g, EG2D_TEST_DATA, "flatplate_137x97", 1);
    case BUMP: return domain_set_tmr(g, EG2D_TEST_DATA, "bump_177x81", 1);
    case CHANNEL: return domain_set_channel(g);
    case BEND: return domain_set_bend(g);
    case DIFFUSER: return domain_set_diffuser(g, c->h);
    case PIPE: return domain_set_pipe(g);
    default: return domain_set_cavity(g, c->h);  /* CAVITY, CORNER: sides clustered at both ends */
    }
}

/* With EG2D_BENCH_WRITE=DIR the default method's grid of each case is also
 * written as an OpenFOAM case DIR/CASE-NIxNJ (bench/internal_checkmesh.sh
 * runs checkMesh on them). */
static void write_case(const eg2d_grid *g, const internal_case *c) {
    const char *dir = getenv("EG2D_BENCH_WRITE");
    if (!dir) return;
    static const char *const tag[] = {"plate", "bump", "channel", "bend", "diffuser", "pipe", "cavity", "corner"};
    char path[512];
    snprintf(path, sizeof path, "%s/%s-%dx%d", dir, tag[c->d], c->ni, c->nj);
    if (eg2d_write(g, path, EG2D_FORMAT_OPENFOAM) != EG2D_OK) fprintf(stderr, "%s: %s\n", path, eg2d_last_error(g));
}

/* A run shorter than kShortest is timed over as many runs as reach it, and
 * their mean taken: a straight channel's solve is a millisecond or less,
 * where one timing of CPU time is as much the heap's first touch as the
 * solve (at 385x129, 3.2x the uncontrolled solve timed once against 2.5x
 * over 200 runs). */
static const double kShortest = 0.05;

static void run(const internal_case *c, method m, double *baseline) {
    double cpu[3];
    int status = EG2D_OK, it = 0;
    char figures[400] = "", tail[80] = "";
    for (int r = 0; r < 3; ++r) {
        double total = 0;
        int runs = 0;
        eg2d_grid *g = NULL;
        for (;;) {
            eg2d_create(c->ni, c->nj, &g);
            set_domain(g, c);
            if (m != NONE) {
                for (int s = 0; s < 4; ++s)
                    if (c->walls >> s & 1) eg2d_set_wall_spacing(g, s, c->h);
                eg2d_set_orthogonality(g, EG2D_ORTHO_WALL);
                if (m == BEFORE) eg2d_set_parameter(g, EG2D_PARAM_WALL_LAYER, 0);
            }
            eg2d_set_tolerance(g, 1e-10);
            eg2d_set_max_iterations(g, 5000);
            const double t0 = bench_cpu();
            status = eg2d_solve(g);
            total += bench_cpu() - t0;
            ++runs;
            if (total >= kShortest) break;  /* the last grid's figures below */
            eg2d_destroy(g);  /* before the next, as each run of the single timing did */
        }
        cpu[r] = total / runs;
        eg2d_get_iterations(g, &it);
        if (r == 2) {
            int n = 0;
            for (int s = 0; s < 4 && m != NONE; ++s) {
                if (!(c->walls >> s & 1)) continue;
                double v[5];
                for (int w = 0; w < 5; ++w) eg2d_get_wall_layer(g, s, w, &v[w]);
                n += snprintf(figures + n, sizeof figures - (size_t)n, "%s%s %.4g (%.4g-%.4g), %.3f, %.2f",
                              n ? "; " : "", s == 0 ? "JMIN" : s == 1 ? "IMAX" : s == 2 ? "JMAX" : "IMIN", v[1], v[0],
                              v[2], v[3], v[4]);
            }
            double skew = NAN, folds = NAN;
            eg2d_get_quality(g, EG2D_QUALITY_SKEWNESS, &skew);
            eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folds);
            snprintf(tail, sizeof tail, "%.1f | %g", skew, folds);
            if (m == DEFAULT) write_case(g, c);
        }
        eg2d_destroy(g);
    }
    qsort(cpu, 3, sizeof *cpu, by_value);
    if (m == NONE) *baseline = cpu[1];
    printf("| %s %dx%d, %g | %s | %s | %d | %.4f | %.2f | %s | %s |\n", c->name, c->ni, c->nj, c->h, method_name[m],
           status == EG2D_OK ? "ok" : eg2d_status_string(status), it, cpu[1], cpu[1] / *baseline,
           m == NONE ? "" : figures, tail);
}

void bench_internal(void) {
    /* Freed memory kept for the next run (glibc returned it between runs, and
     * which of them paid the page faults of taking it back depended on the
     * cases run before: the straight channel 257x129 at 2.4-3.1x the
     * uncontrolled solve from one run of this table to the next). A first
     * solve in a fresh process, the cold case, is in bench/RESULTS.md. */
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    /* First cells: TMR's where the case is TMR's; else 1e-5 where the rows
     * allow growth 1.2 and a larger one where they do not (80 rows between
     * two walls 1 apart need about 1.27 from 1e-5), as a user picks them. */
    static const internal_case cases[] = {
        {"flat plate (TMR)", PLATE, 137, 97, EG2D_TOPO_SINGLE, 1, 2e-6},
        {"bump (TMR)", BUMP, 177, 81, EG2D_TOPO_SINGLE, 1, 4e-6},
        {"channel, one wall (uniform sides)", CHANNEL, 177, 81, EG2D_TOPO_SINGLE, 1, 1e-5},
        {"channel, one wall (uniform sides)", CHANNEL, 137, 97, EG2D_TOPO_SINGLE, 1, 1e-5},
        {"channel, one wall (uniform sides)", CHANNEL, 257, 129, EG2D_TOPO_SINGLE, 1, 1e-5},
        {"channel, one wall (uniform sides)", CHANNEL, 385, 129, EG2D_TOPO_SINGLE, 1, 1e-5},
        {"bend", BEND, 177, 81, EG2D_TOPO_SINGLE, 5, 1e-4},
        {"bend", BEND, 137, 97, EG2D_TOPO_SINGLE, 5, 5e-5},
        {"bend", BEND, 257, 129, EG2D_TOPO_SINGLE, 5, 1e-5},
        {"bend", BEND, 385, 129, EG2D_TOPO_SINGLE, 5, 1e-5},
        {"diffuser (clustered inlet)", DIFFUSER, 177, 81, EG2D_TOPO_SINGLE, 5, 2e-4},
        {"diffuser (clustered inlet)", DIFFUSER, 137, 97, EG2D_TOPO_SINGLE, 5, 5e-5},
        {"diffuser (clustered inlet)", DIFFUSER, 257, 129, EG2D_TOPO_SINGLE, 5, 1e-5},
        {"diffuser (clustered inlet)", DIFFUSER, 385, 129, EG2D_TOPO_SINGLE, 5, 1e-5},
        {"pipe with a body (O)", PIPE, 177, 81, EG2D_TOPO_O, 5, 2e-4},
        {"pipe with a body (O)", PIPE, 137, 97, EG2D_TOPO_O, 5, 5e-5},
        {"pipe with a body (O)", PIPE, 257, 129, EG2D_TOPO_O, 5, 1e-5},
        {"pipe with a body (O)", PIPE, 385, 129, EG2D_TOPO_O, 5, 1e-5},
        {"corner, walls JMIN and IMIN (sides clustered)", CORNER, 177, 81, EG2D_TOPO_SINGLE, 9, 2e-4},
        {"corner, walls JMIN and IMIN (sides clustered)", CORNER, 137, 97, EG2D_TOPO_SINGLE, 9, 1e-4},
        {"corner, walls JMIN and IMIN (sides clustered)", CORNER, 257, 129, EG2D_TOPO_SINGLE, 9, 1e-4},
        {"corner, walls JMIN and IMIN (sides clustered)", CORNER, 385, 129, EG2D_TOPO_SINGLE, 9, 1e-4},
        {"cavity (clustered corners)", CAVITY, 177, 81, EG2D_TOPO_SINGLE, 15, 2e-4},
        {"cavity (clustered corners)", CAVITY, 137, 97, EG2D_TOPO_SINGLE, 15, 1e-4},
        {"cavity (clustered corners)", CAVITY, 257, 129, EG2D_TOPO_SINGLE, 15, 1e-4},
        {"cavity (clustered corners)", CAVITY, 385, 129, EG2D_TOPO_SINGLE, 15, 1e-4},
    };
    printf("Residual 1e-10, the default solver (multigrid); CPU seconds are medians of 3, the ratio is to \"none\" in\n"
           "the same run. Per wall: first cell median (range), growth over 30 cells, angle from the normal (deg).\n\n");
    printf("| case (size, first cell) | method | status | cycles | CPU s | ratio | wall layer | skewness deg | folds |\n"
           "|---|---|---|---:|---:|---:|---|---:|---:|\n");
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        double baseline = 1;
        for (int m = NONE; m <= DEFAULT; ++m) {
            run(&cases[k], (method)m, &baseline);
            fflush(stdout);
        }
    }
}
