/* Measurements of a grid's coordinates shared by the control tests. */
#ifndef EG2D_TEST_MEASURE_H
#define EG2D_TEST_MEASURE_H

#ifdef __cplusplus
extern "C" {
#endif

/* Distance between nodes (i0, j0) and (i1, j1) of an ni-wide grid. */
double measure_distance(const double *x, const double *y, int ni, int i0, int j0, int i1, int j1);

/* At the wall `side` (EG2D_SIDE_*) of an ni x nj grid, over the wall nodes
 * k in [k_begin, k_end) (k = i on JMIN/JMAX, j on IMIN/IMAX): the largest
 * deviation (degrees) from 90 of the angle between the wall's central
 * tangent r(k+1) - r(k-1) (periodic = 1 wraps round an O-grid) and the first
 * grid segment from the wall node to its inward neighbour, and the smallest
 * and largest length of that segment (the first-cell height). */
void measure_wall(const double *x, const double *y, int ni, int nj, int side, int periodic, int k_begin, int k_end,
                  double *max_angle_deviation, double *min_height, double *max_height);

/* Over the cell corners of an ni x nj grid (cell (i, j): (i,j), (i+1,j),
 * (i+1,j+1), (i,j+1)), without the four block corners when single_block
 * (their angle is the boundary's): the mean and the largest deviation
 * (degrees) of the angle from 90, signed by the grid's orientation (a folded
 * corner counts more than 90); and the ratio of the largest to the smallest
 * cell area (HUGE_VAL when a cell is folded or flat). */
void measure_angles(const double *x, const double *y, int ni, int nj, int single_block, double *mean,
                    double *largest, double *area_ratio);

#ifdef __cplusplus
}
#endif
#endif
