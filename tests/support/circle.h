/* Khattri's (2006) circle test domain: the unit circle split into four quarter
 * arcs, one per side (its XYcircle): JMIN from theta = 0 to pi/2, IMAX from
 * pi/2 to pi, JMAX from 3pi/2 back to pi, IMIN from 2pi back to 3pi/2, points
 * uniform in angle. */
#ifndef EG2D_TEST_CIRCLE_H
#define EG2D_TEST_CIRCLE_H

#include "eg2d.h"

#ifdef __cplusplus
extern "C" {
#endif

int domain_set_circle(eg2d_grid *grid);

#ifdef __cplusplus
}
#endif
#endif
