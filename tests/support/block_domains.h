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

/* The same step's blocks with every wall a wall of first cell h (h <= 0:
 * none asked; the Winslow system either way): the upstream floor and top
 * (block 0's JMIN, JMAX), the top downstream (block 1's JMAX), the floor
 * and the step's face (block 2's JMIN, IMIN). The blocks' sides are
 * spaced as a wall layer needs them (Vinokur 1983): x from h at the step's
 * face downstream, and towards x = 0 upstream; y from h at every wall and at the
 * step's height (its shear layer; 0.6/(nj_lower-1) there when h <= 0). */
int walled_step_blocks(double h, int ni_up, int ni_down, int nj_upper, int nj_lower, eg2d_grid *grids[3],
                       eg2d_blocks **set);

/* A rectangle ni x nj over [x0, x1] x [y0, y1] with those clusterings:
 * cluster_x 1 towards x1, -1 towards x0, 0 none; cluster_y towards both ends. */
int block_rectangle(int ni, int nj, double x0, double x1, double y0, double y1, int cluster_x, int cluster_y,
                    eg2d_grid **grid);

/* The bump domain: 0 <= x <= 2 over a bump (height 0.25 at x = 0.7) up to
 * y = 1, ni x nj nodes, rows clustered towards the bump. bump_point gives
 * its node (I, J) on the boundary and on any column (the start of a join
 * along a column). A block of it: node (i, j) of the block is node
 * map(i, j) of the domain (the block's sides from bump_point). */
typedef void (*block_map)(int i, int j, int *I, int *J, const int *p);
void bump_point(int ni, int nj, int I, int J, double *x, double *y);
int bump_block(int ni, int nj, int bni, int bnj, block_map map, const int *p, eg2d_grid **grid);
/* The bump domain ni x nj as two blocks split at column mid (the left
 * 0..mid, the right mid..ni-1), joined; grids[2] receive them. */
int bump_halves(int ni, int nj, int mid, eg2d_grid *grids[2], eg2d_blocks **set);

#endif
