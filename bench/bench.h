/* The parts of the benchmark program eg2d_bench (bench/), shared between
 * its files: clocks, the cases, Ly & Norrison's (2007) table. */
#ifndef EG2D_BENCH_H
#define EG2D_BENCH_H

#include "eg2d.h"

/* Wall seconds (monotonic) and the CPU seconds of the calling thread: on a
 * shared machine the CPU time is the cost, the wall time what a user waits. */
double bench_wall(void);
double bench_cpu(void);

/* A case sets the boundary (and any static control) of an n x nj(n) grid. */
typedef struct {
    const char *name;
    int (*size_nj)(int n);
    int (*set)(eg2d_grid *g);
} bench_case;

const bench_case *bench_find_case(const char *name); /* NULL if none */

/* The median over i of the distance from a JMIN node to its neighbour on
 * j = 1: the wall spacing of the O- and C-grids (chord units for the
 * airfoils); the median, since the sharp trailing edge pinches a few cells. */
double bench_wall_spacing(const eg2d_grid *g);

/* One benchmark run (median times of `repeats`): TFI start, eg2d_solve. */
typedef struct {
    int iterations;
    double wall, cpu, r0, r1, residual;
    double residual_cpu;              /* CPU seconds of one eg2d_get_residual: 1 WU */
    double wall_spacing, aspect_ratio; /* of the final grid */
    const char *status;               /* "ok", "capped", "diverged", ... */
    char message[200];
    int levels, levels_built, events; /* what ran (eg2d_get_run_info) */
    char event[200];                  /* the first change of strategy, if any */
} bench_result;

bench_result bench_run(const bench_case *c, int ni, int nj, int solver, double omega, int system, double tol,
                       double cap, int repeats);

/* The any-size sweep (--sweep): cycles, seconds and microseconds per node
 * at sizes round 2^k, against the nearest 2^k+1 in the same run. */
void bench_sweep(int repeats, const char *svg_path);

/* Ly & Norrison (2007) Table 2 (--ogrid). */
void bench_ogrid(void);

/* The hyperbolic march on NACA 0012 (--march, march.c). */
void bench_march(void);

/* Wall-resolved O-grids: the wall control, the hybrid layer and the march
 * side by side (--wall, wall.c). */
void bench_walls(void);

/* Wall-resolved grids of internal flows: no control, the control alone and
 * the default graded layer side by side (--internal, internal.c). */
void bench_internal(void);

/* A set of blocks against one block of as many nodes (--blocks, blocks.c). */
void bench_blocks(void);

/* The variational system against Winslow on the course notes' domains
 * (--variational, variational.c): the domains, sizes and grids (rows) in
 * comma-separated lists (NULL: all), runs capped at `cap` CPU seconds. */
void bench_variational(const char *cases, const char *sizes, const char *grids, double cap);

#endif
