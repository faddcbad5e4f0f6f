/* The test domains of the source documents as boundary points, shared by the tests, the examples and
 * the benchmark. Points are uniform in each side's parameter s in [0, 1]. */
#ifndef EG2D_TEST_DOMAINS_H
#define EG2D_TEST_DOMAINS_H

#include "eg2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Simply connected domains of the elliptic-grid course notes: "valley", "almost-convex", "swan",
 * "dome", "antenna" (as examples/antenna.toml: the stem gets 70% of the
 * intervals of bottom and top; not in domain_names); and the bilinear quadrilateral "quad" with corners (0,0), (2,0.2),
 * (2.4,1.6), (0.3,1). Sets the four sides; returns the eg2d status. */
int domain_set(eg2d_grid *grid, const char *name);

/* The annulus r_inner <= r <= r_outer as an O-grid (JMIN inner, JMAX outer,
 * counter-clockwise from theta = 0). Sets the topology and both sides. */
int domain_set_annulus(eg2d_grid *grid, double r_inner, double r_outer);

/* The elliptic-grid course notes, B2: the three-leaved rose r = 0.3 (2 + cos 3t) inside the circle
 * r = 9, as an O-grid (JMIN the rose, JMAX the circle, both counter-clockwise
 * from t = 0, points uniform in arc length). Sets the topology and both sides. */
int domain_set_rose(eg2d_grid *grid);

/* A NACA 4-digit section ("0012") with a sharp trailing edge as an O-grid:
 * JMIN the section by arc length (from the trailing edge along the lower
 * surface), JMAX the circle of the given radius about (0.5, 0), both
 * clockwise from the trailing-edge side. Sets the topology and both sides. */
int domain_set_airfoil_o(eg2d_grid *grid, const char *digits, double radius);

/* The same section as a C-grid: JMIN the lower wake (`wake` points from the
 * outflow x = 1 + radius to the trailing edge, uniform), the section, the
 * upper wake; JMAX the lines y = -radius and y = radius over the wake and the
 * half circle of that radius about the trailing edge between; IMIN and IMAX
 * the outflow lines. ni - 2 wake points lie on the section. */
int domain_set_airfoil_c(eg2d_grid *grid, const char *digits, int wake, double radius);

/* A C-grid as flow solvers use it: the section with `wake` points on each
 * side of the cut, the cut from the trailing edge to the outflow x = 1 +
 * radius growing geometrically from the section's trailing-edge spacing
 * `te`; the section by Vinokur's distribution on each surface, `te` at the
 * trailing edge and `le` at the leading edge (the least x of the section);
 * JMAX the lines y = -radius and y = radius above the cut (at the cut's x)
 * and the half circle of that radius about the trailing edge between, its
 * nodes by Vinokur's distribution with `te` at both ends; IMIN and IMAX
 * the outflow lines, uniform. ni - 2 wake points, an odd count, lie on the
 * section. */
int domain_set_airfoil_c_graded(eg2d_grid *grid, const char *digits, int wake, double radius, double le, double te);

/* The body r = 1 + 0.25 cos 2t + 0.15 sin 3t + 0.08 cos 5t (an irregular
 * blob) inside the circle r = 8, as an O-grid: the setup of Tai, Chiang &
 * Su's comparison of point, line and AF schemes (87 x 31 there). */
int domain_set_blob(eg2d_grid *grid);

/* The rectangle [0,1] x [0,height] whose bottom and top nodes sit at x = X[i]
 * (ni values from 0 to 1) and whose left and right sides are uniform in y.
 * Sets the four sides; returns the eg2d status. */
int domain_set_rectangle_columns(eg2d_grid *grid, const double *X, double height);

/* Names of the simply connected domains, NULL-terminated. */
extern const char *const domain_names[];

#ifdef __cplusplus
}
#endif
#endif
