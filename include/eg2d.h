/*
 * eg2d.h -- elliptic generation of boundary-fitted quadrilateral grids.
 *
 * This header is the manual of libeg2d. It is plain C (C89 declarations)
 * and is the whole public API; the library is C++17 inside.
 *
 * Introduction
 * ------------
 * A grid is an opaque handle with ni x nj nodes. Node (i, j), i = 0..ni-1
 * along xi, j = 0..nj-1 along eta, lives at index k = i + ni*j of every
 * coordinate array ("Fortran order": a Fortran x(ni,nj) is the same memory).
 * The four sides are JMIN (j = 0), IMAX (i = ni-1), JMAX (j = nj-1) and
 * IMIN (i = 0); each side's points run in increasing index and adjacent sides
 * share their corner node.
 *
 * The usual sequence:
 *
 *     eg2d_grid *g;
 *     eg2d_create(65, 65, &g);
 *     eg2d_set_side(g, EG2D_SIDE_JMIN, xb, yb);   ... the four sides
 *     eg2d_initialize(g, EG2D_INIT_TFI);          (optional: solve does it)
 *     eg2d_set_tolerance(g, 1e-10);
 *     if (eg2d_solve(g) != EG2D_OK) puts(eg2d_last_error(g));
 *     eg2d_get_coordinates(g, x, y);
 *     eg2d_destroy(g);
 *
 * The equations, the notation and the one residual that every solver drives
 * to the tolerance are defined in NUMERICS.md (shipped with the sources):
 *   residual = max over unknown nodes of max(|R_x|, |R_y|) / (2(alpha+gamma)) / L
 * where L is the diagonal of the boundary's bounding box: about the largest
 * node move a Jacobi step would make, as a fraction of the domain size.
 *
 * Errors
 * ------
 * Every function that can fail returns an int status (EG2D_OK = 0). Every
 * call checks its arguments; nothing aborts the host program and no C++
 * exception crosses this interface. A call that fails because of its input
 * leaves the grid exactly as it was, and usable. eg2d_last_error() gives a
 * precise message for the last failed call on a grid.
 * Runs (eg2d_iterate, eg2d_solve) are the exception that keeps its work:
 * NOT_CONVERGED, INTERRUPTED and FOLDED keep the iterations done, and
 * DIVERGED restores the grid as it was before the failing iteration.
 *
 * Threads
 * -------
 * Different handles may be used from different threads at the same time:
 * the library has no global mutable state (tests/c/test_threads.c runs 8
 * threads x 50 grids against a serial run, under ThreadSanitizer).
 * Sharing one handle:
 *  - one call at a time: no call is internally locked, and that includes
 *    the query calls (eg2d_get_residual computes and caches; every failing
 *    call writes the handle's error text). Serialise with your own mutex.
 *  - a handle may move between threads (no thread affinity) when the hand
 *    over is synchronised (a mutex, a thread join, a queue).
 *  - eg2d_last_error(grid) is the handle's: read it before the next call on
 *    that handle. eg2d_last_error(NULL) is per thread.
 *  - the monitor runs on the thread of eg2d_iterate/eg2d_solve, inside the
 *    call; it may use the query calls (eg2d_get_*) on its own grid, and
 *    must not call anything that changes that grid, nor destroy it.
 *  - eg2d_version, eg2d_status_string, eg2d_solver_name and
 *    eg2d_parameter_bounds need no handle and are safe from any thread.
 *
 * ABI
 * ---
 * libeg2d.so.1 keeps its ABI through all 1.x releases: functions and
 * constants are only ever added; values never change; no struct is public.
 */
#ifndef EG2D_H
#define EG2D_H

#ifdef __cplusplus
extern "C" {
#endif

/* One export macro: everything else in the library is hidden. */
#if defined(_WIN32) && defined(EG2D_SHARED_BUILD)
#  define EG2D_API __declspec(dllexport)
#elif defined(__GNUC__) && __GNUC__ >= 4
#  define EG2D_API __attribute__((visibility("default")))
#else
#  define EG2D_API
#endif

#define EG2D_VERSION_MAJOR 1
#define EG2D_VERSION_MINOR 0
#define EG2D_VERSION_PATCH 0
#define EG2D_VERSION_NUMBER (EG2D_VERSION_MAJOR * 10000 + EG2D_VERSION_MINOR * 100 + EG2D_VERSION_PATCH)

/* The opaque grid handle. */
typedef struct eg2d_grid eg2d_grid;

/*=====================================================================
 * Status codes. Fixed values; new codes are only appended.
 *===================================================================*/
#define EG2D_OK                 0
#define EG2D_ERR_ARGUMENT       1  /* a NULL pointer, a size or a value out of range, NaN/Inf */
#define EG2D_ERR_MEMORY         2  /* an allocation could not be satisfied */
#define EG2D_ERR_BOUNDARY       3  /* corners of adjacent sides disagree, an open O-grid curve */
#define EG2D_ERR_STATE          4  /* a call out of order (iterate before the boundary is set) */
#define EG2D_ERR_NOT_CONVERGED  5  /* eg2d_solve reached the iteration limit */
#define EG2D_ERR_DIVERGED       6  /* NaN/Inf or a growing residual; the grid is restored */
#define EG2D_ERR_FOLDED         7  /* the converged grid has folded cells */
#define EG2D_ERR_IO             8  /* a file could not be read or written */
#define EG2D_ERR_UNSUPPORTED    9  /* a feature not built into this library */
#define EG2D_ERR_INTERRUPTED   10  /* the monitor callback asked the run to stop */

/* A static English name of a status ("EG2D_ERR_BOUNDARY: ..."); never NULL. */
EG2D_API const char *eg2d_status_string(int status);

/* The message of the last failed call on `grid`; "" if none has failed.
 * With grid == NULL: the calling thread's last failure of a call that had no
 * grid to record it in (eg2d_create, or any call given a NULL handle).
 * The text stays valid until the next failing call on the same grid/thread. */
EG2D_API const char *eg2d_last_error(const eg2d_grid *grid);

/* The library's version at run time (any pointer may be NULL). */
EG2D_API void eg2d_version(int *major, int *minor, int *patch);

/*=====================================================================
 * Creating a grid
 *===================================================================*/
/* A grid of ni x nj nodes, ni, nj >= 3 (and ni*nj must fit the address
 * space). *grid is set to NULL on failure. Defaults: single-block topology,
 * Winslow system, point SOR, tolerance 1e-8, automatic relaxation. */
EG2D_API int eg2d_create(int ni, int nj, eg2d_grid **grid);

/* Frees everything; NULL is a no-op. */
EG2D_API void eg2d_destroy(eg2d_grid *grid);

/* Topologies. SINGLE: four sides, all fixed. O: periodic in i; JMIN is the
 * inner and JMAX the outer closed curve (first point == last point), columns
 * i = 0 and i = ni-1 are the same physical points (the branch cut) and are
 * solved for with the interior. C: reserved for the C-grid with a wake cut.
 * Changing the topology forgets the boundary and the grid. */
#define EG2D_TOPO_SINGLE 0
#define EG2D_TOPO_O      1
#define EG2D_TOPO_C      2
EG2D_API int eg2d_set_topology(eg2d_grid *grid, int topology);
EG2D_API int eg2d_get_topology(const eg2d_grid *grid, int *topology);

/*=====================================================================
 * Boundary
 *===================================================================*/
#define EG2D_SIDE_JMIN 0  /* j = 0,    ni points */
#define EG2D_SIDE_IMAX 1  /* i = ni-1, nj points */
#define EG2D_SIDE_JMAX 2  /* j = nj-1, ni points */
#define EG2D_SIDE_IMIN 3  /* i = 0,    nj points */

/* Sets one side from its points in increasing index. Corners shared with a
 * side already set must agree to 1e-8 of the boundary's size, or the call
 * fails with EG2D_ERR_BOUNDARY and sets nothing. On an O-grid only JMIN and
 * JMAX exist and each must be a closed curve. A side set after the grid was
 * initialised moves only the boundary: the interior is kept as a warm start. */
EG2D_API int eg2d_set_side(eg2d_grid *grid, int side, const double *x, const double *y);

/* Sets the whole boundary ring from ni*nj arrays in Fortran order; only the
 * boundary nodes are read (for an O-grid: rows j = 0 and j = nj-1). */
EG2D_API int eg2d_set_boundary(eg2d_grid *grid, const double *x, const double *y);

/*=====================================================================
 * Initial grid
 *===================================================================*/
#define EG2D_INIT_TFI 0  /* linear transfinite interpolation, seed 001 eq 2.2 */

/* Fills the interior from the boundary. Needs the whole boundary. */
EG2D_API int eg2d_initialize(eg2d_grid *grid, int method);

/* A start grid of the user's own: whole ni*nj arrays, boundary included
 * (which then becomes the boundary). For an O-grid, columns 0 and ni-1 must
 * agree. */
EG2D_API int eg2d_set_coordinates(eg2d_grid *grid, const double *x, const double *y);

/*=====================================================================
 * System, solver and run settings
 *===================================================================*/
#define EG2D_SYSTEM_LAPLACE 0  /* Amsden-Hirt, x_xixi + x_etaeta = 0: linear */
#define EG2D_SYSTEM_WINSLOW 1  /* Winslow / Thompson-Thames-Mastin (default) */
EG2D_API int eg2d_set_system(eg2d_grid *grid, int system);

#define EG2D_SOLVER_PSOR      0  /* point SOR (Gauss-Seidel at omega = 1) */
#define EG2D_SOLVER_LSOR      1  /* line SOR, alternating directions */
#define EG2D_SOLVER_AF        2  /* approximate factorisation, false transients */
#define EG2D_SOLVER_NESTED    3  /* coarse-to-fine, seed 000 */
#define EG2D_SOLVER_MULTIGRID 4  /* FAS multigrid */
/* Selects a solver; EG2D_ERR_UNSUPPORTED for an id this library lacks. */
EG2D_API int eg2d_set_solver(eg2d_grid *grid, int solver);
EG2D_API int eg2d_get_solver(const eg2d_grid *grid, int *solver);
/* A solver's short name ("psor"), or NULL if this library has no such solver. */
EG2D_API const char *eg2d_solver_name(int solver);

/* Relaxation factor omega in (0, 2); 0 = automatic (for point SOR the
 * optimal factor of seed 003, computed for the grid's size). */
EG2D_API int eg2d_set_relaxation(eg2d_grid *grid, double omega);
/* Stop when residual <= tolerance (default 1e-8), tolerance in (0, 1). */
EG2D_API int eg2d_set_tolerance(eg2d_grid *grid, double tolerance);
/* Iteration limit of one eg2d_solve call (default 100000), >= 1. */
EG2D_API int eg2d_set_max_iterations(eg2d_grid *grid, int max_iterations);

/* Generic parameters, zstd-style: every setting has an id, bounds and a
 * default; the typed setters above are shorthands for these. Values are
 * doubles; an integer parameter takes only whole values. Ids are fixed and
 * grouped with gaps: 0-99 run, 100-199 solvers, 200-299 controls, 300-399 output. */
#define EG2D_PARAM_RELAXATION         0  /* (0, 2), 0 = automatic           */
#define EG2D_PARAM_TOLERANCE          1  /* (0, 1),  default 1e-8           */
#define EG2D_PARAM_MAX_ITERATIONS     2  /* [1, 1e9], default 100000        */
#define EG2D_PARAM_DIVERGENCE_FACTOR  3  /* [10, 1e12], default 1e4: a residual this many times
                                            the best of the run (and above 1e-2) is divergence */
#define EG2D_PARAM_FOLD_CHECK         4  /* 1 (default): eg2d_solve returns EG2D_ERR_FOLDED when
                                            the converged grid has folded cells; 0: it does not */
#define EG2D_PARAM_SVG_QUALITY      300  /* output 300-399. EG2D_FORMAT_SVG colours cells by this
                                            EG2D_QUALITY_* metric (one with per-cell values);
                                            -1 (default): no colouring */
EG2D_API int eg2d_set_parameter(eg2d_grid *grid, int param, double value);
EG2D_API int eg2d_get_parameter(const eg2d_grid *grid, int param, double *value);
/* Bounds and default of a parameter, without a grid. */
EG2D_API int eg2d_parameter_bounds(int param, double *lower, double *upper, double *default_value);

/*=====================================================================
 * Running
 *===================================================================*/
/* Called after every iteration with the iteration count of the grid (it
 * counts across calls) and the residual; a nonzero return stops the run
 * with EG2D_ERR_INTERRUPTED, keeping the iterations done. NULL removes it. */
typedef int (*eg2d_monitor_fn)(void *user, int iteration, double residual);
EG2D_API int eg2d_set_monitor(eg2d_grid *grid, eg2d_monitor_fn fn, void *user);

/* Does exactly `iterations` iterations (>= 0; one sweep, or one cycle of a
 * multilevel solver) and stores the residual after them in *residual
 * (residual may be NULL). Initialises by TFI first if the grid has only a
 * boundary. */
EG2D_API int eg2d_iterate(eg2d_grid *grid, int iterations, double *residual);

/* Iterates until residual <= tolerance: EG2D_OK, or EG2D_ERR_NOT_CONVERGED
 * after max_iterations, EG2D_ERR_DIVERGED, EG2D_ERR_INTERRUPTED. A converged
 * grid is checked for folded cells (EG2D_ERR_FOLDED, see PARAM_FOLD_CHECK). */
EG2D_API int eg2d_solve(eg2d_grid *grid);

/*=====================================================================
 * Queries
 *===================================================================*/
EG2D_API int eg2d_get_size(const eg2d_grid *grid, int *ni, int *nj);
/* Copies the ni*nj node coordinates (Fortran order). Needs an initialised grid. */
EG2D_API int eg2d_get_coordinates(const eg2d_grid *grid, double *x, double *y);
/* The residual (NUMERICS.md) of the current grid. Needs an initialised grid. */
EG2D_API int eg2d_get_residual(const eg2d_grid *grid, double *residual);
/* Iterations done since the grid was last initialised or given coordinates. */
EG2D_API int eg2d_get_iterations(const eg2d_grid *grid, int *iterations);

/*=====================================================================
 * Quality
 *===================================================================*/
/* Quality of the current grid (it must be initialised). Cell (i, j),
 * i < ni-1, j < nj-1, has the corners (i,j), (i+1,j), (i+1,j+1), (i,j+1);
 * per-cell arrays hold (ni-1)*(nj-1) values, cell (i, j) at i + (ni-1)*j.
 * A cell is folded when one of its corners turns against the grid's
 * orientation (left- and right-handed grids are both legal; the orientation
 * is the sign of the total area). eg2d_solve fails with EG2D_ERR_FOLDED when
 * the converged grid has a folded cell, naming the first one, unless
 * EG2D_PARAM_FOLD_CHECK is 0; the grid is kept, so these metrics can then
 * show where. Angles are in degrees. Ids are fixed, grouped with gaps. */
#define EG2D_QUALITY_FOLDED_CELLS 0  /* number of folded cells; per cell 1 (folded) or 0 */
#define EG2D_QUALITY_MIN_AREA     1  /* smallest cell area, signed by the grid's orientation:
                                        negative for an inverted cell; per cell: the area */
#define EG2D_QUALITY_MAX_AREA     2  /* largest cell area; per cell: the area (as MIN_AREA) */
#define EG2D_QUALITY_SKEWNESS    10  /* largest deviation of a corner angle from 90 degrees;
                                        angles are signed by the orientation, so a folded
                                        corner gives more than 90. Unit square 0, a rhombus
                                        with 30 degree corners 60 */
#define EG2D_QUALITY_ASPECT_RATIO 20 /* largest over cells of max(wi, wj) / min(wi, wj), where
                                        wi is the mean of the cell's two edges along i, wj
                                        along j (1 for a square or a rhombus) */
#define EG2D_QUALITY_SMOOTHNESS_I 30 /* largest ratio (>= 1) of the i-widths wi of two cells
                                        neighbouring in i (the stretching ratio); per cell: the
                                        largest ratio to its i-neighbours (O-grid: across the cut) */
#define EG2D_QUALITY_SMOOTHNESS_J 31 /* the same with wj, in j */
/* Orthogonality at a side: at each boundary node (corners excluded; on an
 * O-grid JMIN and JMAX are closed and every node counts once) the deviation
 * from 90 degrees of the angle between the boundary's tangent (central
 * difference) and the grid line leaving the node. The largest is
 * ORTHO_MAX_JMIN + side, the mean ORTHO_MEAN_JMIN + side (side an
 * EG2D_SIDE_*). Summaries only: no per-cell values. */
#define EG2D_QUALITY_ORTHO_MAX_JMIN  40
#define EG2D_QUALITY_ORTHO_MAX_IMAX  41
#define EG2D_QUALITY_ORTHO_MAX_JMAX  42
#define EG2D_QUALITY_ORTHO_MAX_IMIN  43
#define EG2D_QUALITY_ORTHO_MEAN_JMIN 50
#define EG2D_QUALITY_ORTHO_MEAN_IMAX 51
#define EG2D_QUALITY_ORTHO_MEAN_JMAX 52
#define EG2D_QUALITY_ORTHO_MEAN_IMIN 53
/* The scalar summary of a metric. An orthogonality metric of a side the
 * topology lacks (IMIN/IMAX of an O-grid) is EG2D_ERR_ARGUMENT. */
EG2D_API int eg2d_get_quality(const eg2d_grid *grid, int metric, double *value);
/* The per-cell values of a metric into values[(ni-1)*(nj-1)];
 * EG2D_ERR_ARGUMENT for a metric without per-cell values (orthogonality). */
EG2D_API int eg2d_get_cell_quality(const eg2d_grid *grid, int metric, double *values);

/*=====================================================================
 * Files
 *===================================================================*/
/* Writes the current grid (it must be initialised) to `path`. The file is
 * written to a temporary in the same directory and renamed over `path` only
 * when complete: a failed write never leaves a half-written file under
 * `path` (an existing file there is kept). A file that cannot be written is
 * EG2D_ERR_IO with the path and the system's reason.
 *
 * Plot3D (whole grid, "xyz" file). EG2D_FORMAT_PLOT3D writes the 2D form
 * as a Fortran-unformatted sequential file (4-byte record markers before and
 * after each record), little-endian, 8-byte reals:
 *     record 1: ni nj                      (int32)
 *     record 2: x(1..ni*nj) y(1..ni*nj)    (Fortran order)
 * EG2D_FORMAT_PLOT3D_ASCII writes the same numbers as text. Variants are
 * flags OR-ed into either id (they are not format ids of their own):
 *   EG2D_PLOT3D_3D     the 3D form with one k-plane: "ni nj 1", then x, y and
 *                      z = 0. Many tools (Pointwise's default, VTK without
 *                      TwoDimensionalGeometry) expect this one; 2D readers
 *                      (Construct2D's output, VTK with it) expect the 2D one.
 *   EG2D_PLOT3D_MULTI  the multi-grid header: a record "1" (the number of
 *                      grids) before the dimensions.
 *   EG2D_PLOT3D_SINGLE 4-byte reals (binary only).
 *   EG2D_PLOT3D_BIG_ENDIAN big-endian markers, integers and reals (binary only).
 *   EG2D_PLOT3D_NO_MARKERS a C stream ("binary" rather than "unformatted" in
 *                      Pointwise): the same numbers without record markers.
 * e.g. eg2d_write(g, "grid.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI).
 *
 * EG2D_FORMAT_VTS: VTK XML StructuredGrid (ASCII, 17 significant digits),
 * points with z = 0 and every per-cell quality metric as cell data (arrays
 * "folded", "area", "skewness", "aspect_ratio", "smoothness_i", "smoothness_j").
 * EG2D_FORMAT_CGNS: one base (cell dimension 2, physical dimension 2), one
 * structured zone "eg2d" with CoordinateX, CoordinateY. It is an optional
 * part: libeg2d loads the plugin libeg2d_cgns.so (built when libcgns is
 * found, installed next to libeg2d.so; EG2D_PLUGIN_DIR overrides where it is
 * looked for) when this format is asked for, so that libeg2d itself never
 * depends on libcgns; without the plugin the call is EG2D_ERR_UNSUPPORTED.
 * EG2D_FORMAT_GMV: GMV ASCII ("gmvinput ascii", nodes with z = 0, quad
 * cells, the per-cell metrics as cell variables), seed 002's format.
 * EG2D_FORMAT_MATLAB: a Matlab/Octave script that sets xl(i,j), yl(i,j)
 * (1-based, 17 digits) and plots the grid with the boundary in red, seed 002.
 * EG2D_FORMAT_SVG: a picture for a browser: grid lines, the boundary drawn
 * thicker, and cells coloured by the metric EG2D_PARAM_SVG_QUALITY when it
 * is set (blue = best to red = worst of the grid, with a legend). */
#define EG2D_FORMAT_PLOT3D       0
#define EG2D_FORMAT_PLOT3D_ASCII 1
#define EG2D_FORMAT_VTS          2
#define EG2D_FORMAT_CGNS         3
#define EG2D_FORMAT_GMV          4
#define EG2D_FORMAT_MATLAB       5
#define EG2D_FORMAT_SVG          6
#define EG2D_PLOT3D_3D         0x100
#define EG2D_PLOT3D_MULTI      0x200
#define EG2D_PLOT3D_SINGLE     0x400
#define EG2D_PLOT3D_BIG_ENDIAN 0x800
#define EG2D_PLOT3D_NO_MARKERS 0x1000
EG2D_API int eg2d_write(const eg2d_grid *grid, const char *path, int format);

/* Reads grid `block` (0-based) of a Plot3D whole-grid file of any variant
 * above, detecting which it holds: ASCII or Fortran-unformatted binary
 * (either byte order, 4- or 8-byte reals) or C stream binary, 2D or 3D with one k-plane (z is
 * ignored), single- or multi-grid. Gives the variant in *format (an
 * EG2D_FORMAT_PLOT3D* id with its EG2D_PLOT3D_* flags), the number of grids
 * in *nblocks and the block's size in *ni, *nj (each pointer may be NULL).
 * x and y (ni*nj each, Fortran order) may both be NULL to ask the size
 * first; the arrays can go to eg2d_set_coordinates as a start grid (from
 * Construct2D, Pointwise, or eg2d). A file that is none of these, a 3D
 * block with nk > 1 or a truncated file is EG2D_ERR_IO naming the path and
 * what was found. Errors are reported by eg2d_last_error(NULL). */
EG2D_API int eg2d_read_plot3d(const char *path, int block, int *format, int *nblocks, int *ni, int *nj,
                              double *x, double *y);

/* Point files: plain text, one point "x y" per line (spaces, tabs or a comma
 * between), '#' starts a comment, blank lines are skipped. A line that is not
 * two finite numbers is EG2D_ERR_IO naming the path, the line number and the
 * text. eg2d_read_points gives the number of points in *n and, when x and y
 * are not NULL, copies at most `capacity` of them (more is EG2D_ERR_ARGUMENT).
 * Errors are reported by eg2d_last_error(NULL). */
EG2D_API int eg2d_read_points(const char *path, int capacity, int *n, double *x, double *y);
/* Sets a side from a point file (as eg2d_set_side); the file must hold
 * exactly as many points as the side has (ni or nj), else EG2D_ERR_BOUNDARY. */
EG2D_API int eg2d_set_side_from_file(eg2d_grid *grid, int side, const char *path);

#ifdef __cplusplus
}
#endif
#endif /* EG2D_H */
