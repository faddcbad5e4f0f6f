/* Petrilli's (1989) three test channels (`boundary(1..3)` of the Pascal listing)
 * and its source arrays p1/p2, for grids of (ni+1) x (nj+1) nodes where ni,
 * nj are the listing's interval counts (it runs ni = 8, nj = 32). */
#ifndef EG2D_TEST_CHANNELS_H
#define EG2D_TEST_CHANNELS_H

#include "eg2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Sets the four sides of channel `geom` (1, 2, 3) as the listing does. */
int channel_set(eg2d_grid *grid, int geom);

/* Fills P, Q (node counts ni x nj, Fortran order) with the listing's p1/p2
 * for `geom`, zero elsewhere. Geometry 2's last loop runs over i but sets
 * row j (a typo): we use the rows j = nj7-2 .. nj7+1 it means. */
void channel_sources(int geom, int ni_nodes, int nj_nodes, double *P, double *Q);

#ifdef __cplusplus
}
#endif
#endif
