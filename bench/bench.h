/* The parts of the benchmark program eg2d_bench (bench/), shared between
 * its files: clocks, the cases, seed 004's table. */
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

/* Seed 004 Table 2 (--seed004). */
void bench_seed004(void);

/* The hyperbolic march on NACA 0012 (--march, march.c). */
void bench_march(void);

#endif
