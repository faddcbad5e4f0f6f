/* Measurements of a grid's coordinates shared by the control tests. */
#ifndef EG2D_TEST_MEASURE_H
#define EG2D_TEST_MEASURE_H

#ifdef __cplusplus
extern "C" {
#endif

/* Distance between nodes (i0, j0) and (i1, j1) of an ni-wide grid. */
double measure_distance(const double *x, const double *y, int ni, int i0, int j0, int i1, int j1);

/* At the wall side JMIN (j = 0) of an ni x nj grid, over wall nodes i in
 * [i_begin, i_end): the largest deviation (degrees) from 90 of the angle
 * between the wall's central tangent r(i+1,0) - r(i-1,0) (periodic = 1 wraps
 * round an O-grid) and the first grid segment r(i,1) - r(i,0), and the
 * smallest and largest first-cell height |r(i,1) - r(i,0)|. */
void measure_wall_jmin(const double *x, const double *y, int ni, int periodic, int i_begin, int i_end,
                       double *max_angle_deviation, double *min_height, double *max_height);

#ifdef __cplusplus
}
#endif
#endif
