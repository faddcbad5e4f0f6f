/* Internal-flow domains with walls, shared by tests/c/test_graded_layer.c and
 * the benchmark's --internal mode (bench/internal.c). Each sets the boundary
 * of a created grid (and the patches the case needs) and returns EG2D_OK or
 * the failing call's status; wall spacings are the caller's. */
#ifndef EG2D_TEST_INTERNAL_H
#define EG2D_TEST_INTERNAL_H

#include "eg2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* NASA TMR's boundary points as published (tests/data/tmr/NAME_SIDE.dat):
 * "flatplate_137x97" (the plate from JMIN node 24, symmetry ahead) or
 * "bump_177x81" (the bump from node 48 to 128, symmetry either side). With
 * patches = 1 the symmetry and wall stretches of JMIN are set as TMR's. */
int domain_set_tmr(eg2d_grid *grid, const char *data_dir, const char *name, int patches);
/* A 90-degree bend of a channel 1 wide: inner wall radius 1 (JMIN), outer 2
 * (JMAX), straight legs of 2; inlet (IMIN) and outlet (IMAX) with uniform points. */
int domain_set_bend(eg2d_grid *grid);
/* An S-shaped diffuser: the centre line rises by 1.5 and the width grows
 * from 1 to 2 (smoothstep) over x in [0, 6], straight 2 before and after;
 * walls JMIN and JMAX; inlet and outlet uniform (cluster 0) or with that
 * spacing at both walls (Vinokur), as a user clusters them. */
int domain_set_diffuser(eg2d_grid *grid, double cluster);
/* An O-grid between an ellipse (semi-axes 0.5, 0.3; JMIN) and a pipe of
 * radius 2 (JMAX). */
int domain_set_pipe(eg2d_grid *grid);
/* The unit square with its points clustered at the corners by Vinokur's
 * two-sided function, first and last spacing h: a cavity walled all round. */
int domain_set_cavity(eg2d_grid *grid, double h);
/* A straight channel 4 long and 1 high with uniform points. */
int domain_set_channel(eg2d_grid *grid);

#ifdef __cplusplus
}
#endif
#endif
