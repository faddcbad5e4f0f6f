/* A NACA 4-digit airfoil O-grid boundary for the tests (the library's own
 * NACA API is another issue's). */
#ifndef EG2D_TEST_AIRFOIL_H
#define EG2D_TEST_AIRFOIL_H

#include "eg2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The NACA 4-digit section `digits` (e.g. "0012", "2412") of unit chord with
 * the closed trailing edge (last thickness coefficient -0.1036) as the inner
 * curve JMIN of an O-grid, and the circle of radius r_outer about (0.5, 0) as
 * JMAX. Node i is at theta = 2 pi i/(ni-1), x = (1 + cos theta)/2 (cosine
 * spacing, dense at both edges), counter-clockwise from the trailing edge over
 * the upper surface. Sets the topology and both sides; returns the status. */
int airfoil_set_naca4_ogrid(eg2d_grid *grid, const char *digits, double r_outer);

/* The point of the section at theta (as above). */
void airfoil_naca4_point(const char *digits, double theta, double *x, double *y);

#ifdef __cplusplus
}
#endif
#endif
