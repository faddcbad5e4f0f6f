/* Sets of blocks the tests and the benchmark share. */
#ifndef BLOCK_DOMAINS_H
#define BLOCK_DOMAINS_H
#include "eg2d.h"

/* A backward-facing step with Driver & Seegmiller's expansion (step height
 * 1, channel 8 upstream and 9 downstream) over x in [-4, 20] (the lengths
 * shortened): block 0 the upstream channel (ni_up x nj_upper), block 1 the
 * channel above the step's height downstream (ni_down x nj_upper), block 2
 * the step's own channel below it (ni_down x nj_lower); x clustered towards
 * the step, y towards every wall; block 0's IMAX joined to block 1's IMIN,
 * block 1's JMIN to block 2's JMAX. grids[3] receive the blocks. Returns
 * the first failing status. */
int step_blocks(int ni_up, int ni_down, int nj_upper, int nj_lower, eg2d_grid *grids[3], eg2d_blocks **set);

/* A rectangle ni x nj over [x0, x1] x [y0, y1] with those clusterings:
 * cluster_x 1 towards x1, -1 towards x0, 0 none; cluster_y towards both ends. */
int block_rectangle(int ni, int nj, double x0, double x1, double y0, double y1, int cluster_x, int cluster_y,
                    eg2d_grid **grid);

#endif
