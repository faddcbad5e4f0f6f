/*
 * eg2d.h -- elliptic generation of boundary-fitted quadrilateral grids.
 *
 * This header is the manual of libeg2d. It is plain C (C89 declarations)
 * and is the whole public API; the library is C++17 inside. Each call below
 * states its contract: what it does, the units, its errors and what a
 * failure leaves unchanged. How the methods work, why, and what was
 * measured on them is in docs/methods.md, in the order of the groups here;
 * the equations and the residual in docs/NUMERICS.md; papers are cited by
 * author and year (docs/references.md).
 *
 * Contents
 * --------
 *  0) Preamble: introduction, errors, threads, host environment, ABI.
 *  1) Status codes, errors and version: EG2D_OK, EG2D_ERR_*;
 *     eg2d_status_string, eg2d_last_error, eg2d_version.
 *  2) Lists: what this library has, by name (EG2D_LIST_*, EG2D_VALUE_*,
 *     EG2D_WRITES_*): eg2d_list_count, eg2d_list_entry, eg2d_list_name,
 *     eg2d_list_find, eg2d_parameter_info, eg2d_format_info,
 *     eg2d_quality_cell_field.
 *  3) Ids, one ordered table per kind: sides and directions (EG2D_SIDE_*,
 *     EG2D_XI, EG2D_ETA), EG2D_TOPO_*, EG2D_INIT_*, EG2D_SYSTEM_*,
 *     EG2D_SOLVER_*, EG2D_ORTHO_*, EG2D_PARAM_* (bounds, default, unit)
 *     and the values some of them take (EG2D_MARCH_END_*, EG2D_AIRFOIL_TE_*),
 *     EG2D_RUN_*, EG2D_QUALITY_*, EG2D_WALL_*, EG2D_FORMAT_* and the
 *     EG2D_PLOT3D_* flags, EG2D_DIST_*, EG2D_CURVE_*, EG2D_NACA_*,
 *     EG2D_CLUSTER_*, EG2D_PATCH_*.
 *  4) Create and boundary:
 *     eg2d_create, eg2d_destroy, eg2d_set_topology, eg2d_get_topology,
 *     eg2d_get_cut, eg2d_set_side, eg2d_set_boundary,
 *     eg2d_set_patch, eg2d_clear_patches, eg2d_get_patch_count,
 *     eg2d_get_patch.
 *  5) Initial grid:
 *     eg2d_initialize (TFI, Hermite, hyperbolic march), eg2d_set_coordinates,
 *     eg2d_set_interior_line, eg2d_clear_interior_lines.
 *  6) System, controls and walls:
 *     eg2d_set_system, eg2d_add_line_source, eg2d_add_point_source,
 *     eg2d_clear_sources, eg2d_set_source_arrays, eg2d_set_orthogonality,
 *     eg2d_set_wall_spacing, eg2d_set_wall_spacing_nodes,
 *     eg2d_set_parameter_grid, eg2d_clustering_map,
 *     eg2d_tensor_parameter_grid, eg2d_set_weight, eg2d_get_controls.
 *  7) Solvers and the run:
 *     eg2d_set_solver, eg2d_get_solver, eg2d_solver_name,
 *     eg2d_set_relaxation, eg2d_set_tolerance, eg2d_set_max_iterations,
 *     eg2d_set_parameter, eg2d_get_parameter, eg2d_parameter_bounds,
 *     eg2d_set_af_cycle, eg2d_set_af_time_rule, eg2d_set_monitor,
 *     eg2d_iterate, eg2d_solve.
 *  8) Results and quality:
 *     eg2d_get_size, eg2d_get_coordinates, eg2d_get_residual,
 *     eg2d_get_iterations, eg2d_get_run_info, eg2d_get_run_event,
 *     eg2d_get_quality, eg2d_get_cell_quality, eg2d_get_wall_layer.
 *  9) Files:
 *     eg2d_write, eg2d_read_plot3d, eg2d_read_plot3d_into,
 *     eg2d_read_points, eg2d_set_side_from_file.
 * 10) Curves and airfoils:
 *     eg2d_curve_polyline, eg2d_curve_spline, eg2d_curve_function,
 *     eg2d_curve_naca4, eg2d_curve_read_airfoil, eg2d_curve_destroy,
 *     eg2d_curve_length, eg2d_curve_evaluate, eg2d_distribution,
 *     eg2d_distribution_parameter, eg2d_curve_points, eg2d_set_side_curve,
 *     eg2d_first_cell_height, eg2d_set_airfoil.
 * 11) Sets of blocks (multi-block): eg2d_blocks_create,
 *     eg2d_blocks_destroy, eg2d_blocks_last_error, eg2d_blocks_add,
 *     eg2d_blocks_set_name, eg2d_blocks_name, eg2d_blocks_join,
 *     eg2d_blocks_hold_join, eg2d_blocks_check, eg2d_blocks_solve,
 *     eg2d_blocks_get_run, eg2d_blocks_get_kinks, eg2d_blocks_write.
 *
 * Introduction
 * ------------
 * A grid is an opaque handle with ni x nj nodes. Node (i, j), i = 0..ni-1
 * along xi, j = 0..nj-1 along eta, lives at index k = i + ni*j of every
 * coordinate array ("Fortran order": a Fortran x(ni,nj) is the same memory).
 * The four sides are JMIN (j = 0), IMAX (i = ni-1), JMAX (j = nj-1) and
 * IMIN (i = 0); each side's points run in increasing index and adjacent sides
 * share their corner node. Lengths are in the unit of the coordinates given
 * ("the boundary's length unit"), angles in degrees.
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
 * to the tolerance are defined in docs/NUMERICS.md:
 *   residual = max over unknown nodes of max(|R_x|, |R_y|) / (2(alpha+gamma)) / L
 * where L is the diagonal of the boundary's bounding box: about the largest
 * node move a Jacobi step would make, as a fraction of the domain size
 * (EG2D_SYSTEM_VARIATIONAL: the gradient of its functional, scaled alike).
 *
 * Errors
 * ------
 * Every function that can fail returns an int status (EG2D_OK = 0). Every
 * call checks its arguments; nothing aborts the host program and no C++
 * exception crosses this interface. A call that fails because of its input
 * leaves the grid exactly as it was, and usable. eg2d_last_error() gives a
 * precise message for the last failed call on a grid. Calls without a grid
 * (curves, distributions, file readers) report through eg2d_last_error(NULL).
 * Runs (eg2d_iterate, eg2d_solve) are the exception that keeps its work:
 * NOT_CONVERGED at the iteration limit, INTERRUPTED and FOLDED keep the
 * iterations done, and DIVERGED and a stall (EG2D_PARAM_STALL_ITERATIONS)
 * restore the run's last good grid: the latest iterate whose
 * residual was below the previous good one's (the start is the first),
 * had halved since or came 10 iterations after it, and that folds no more
 * cells than the start. The message names its iteration, and
 * eg2d_get_iterations counts up to it.
 *
 * Threads
 * -------
 * Different handles may be used from different threads at the same time:
 * the library has no global mutable state (tests/c/test_threads.c runs
 * many threads against a serial run, under ThreadSanitizer).
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
 *  - eg2d_version, eg2d_status_string, eg2d_solver_name,
 *    eg2d_parameter_bounds and the calls of section 2 (eg2d_list_*,
 *    eg2d_parameter_info, eg2d_format_info, eg2d_quality_cell_field) need
 *    no handle and are safe from any thread.
 *    A curve (eg2d_curve) is immutable once made and may be shared.
 *
 * Host environment
 * ----------------
 * Locale: files, reports and messages write numbers with a '.' and readers
 * (Plot3D, point and airfoil files) expect one, whatever setlocale the host
 * made: the bytes written are those of the "C" locale. The library never
 * changes the process's locale (it switches only the calling thread's, with
 * uselocale, for the duration of a conversion).
 * Floating point: no call raises the invalid, divide-by-zero or overflow
 * flag on valid input, so a host may run with these traps on
 * (feenableexcept, gfortran -ffpe-trap=invalid,zero,overflow); the library
 * never changes the floating-point environment. The exception: a run that
 * diverges (EG2D_ERR_DIVERGED) may overflow before the divergence is caught.
 *
 * ABI
 * ---
 * libeg2d.so.1 keeps its ABI through all 1.x releases: functions and
 * constants are only ever added; values never change; no struct is public.
 * Ids are fixed; a table below may have gaps, never a renumbering.
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

/* The opaque handles: a grid, and a plane curve (group 10). */
typedef struct eg2d_grid eg2d_grid;
typedef struct eg2d_curve eg2d_curve;

/*=====================================================================
 * 1) Status codes, errors and version
 *
 * Fixed values; new codes are only appended.
 *===================================================================*/
#define EG2D_OK                 0
#define EG2D_ERR_ARGUMENT       1  /* a NULL pointer, a size or a value out of range, NaN/Inf */
#define EG2D_ERR_MEMORY         2  /* an allocation could not be satisfied */
#define EG2D_ERR_BOUNDARY       3  /* corners of adjacent sides disagree, an open O-grid curve */
#define EG2D_ERR_STATE          4  /* a call out of order (iterate before the boundary is set) */
#define EG2D_ERR_NOT_CONVERGED  5  /* eg2d_solve reached the iteration limit, or made no progress (EG2D_PARAM_STALL_ITERATIONS) */
#define EG2D_ERR_DIVERGED       6  /* NaN/Inf or a growing residual; the last good grid is restored */
#define EG2D_ERR_FOLDED         7  /* the converged grid has folded cells */
#define EG2D_ERR_IO             8  /* a file could not be read or written */
#define EG2D_ERR_UNSUPPORTED    9  /* a feature not built into this library */
#define EG2D_ERR_INTERRUPTED   10  /* the monitor callback asked the run to stop */
#define EG2D_ERR_INTERNAL      11  /* a defect inside eg2d (an unexpected exception): please
                                      report it with the message; the handle is unchanged */

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
 * 2) Lists: what this library has, by name
 *
 * Every kind of id of section 3 (solvers, parameters, formats, quality
 * metrics, systems, initial grids, orthogonality methods, topologies, point
 * distributions) is one table inside the library. These calls read it, so a
 * program (the eg2d command, a case-file reader, a GUI) needs no copy of its
 * own. Every id this library knows is listed. Names are short lower-case
 * words ("multigrid", "wall_growth", "vts"), valid for the life of the
 * process; no handle, safe from any thread. docs/tables.md prints them all.
 *===================================================================*/
/* The lists. */
#define EG2D_LIST_SOLVERS        0
#define EG2D_LIST_PARAMETERS     1
#define EG2D_LIST_FORMATS        2
#define EG2D_LIST_QUALITY        3
#define EG2D_LIST_SYSTEMS        4
#define EG2D_LIST_INITIALIZERS   5
#define EG2D_LIST_ORTHOGONALITY  6
#define EG2D_LIST_TOPOLOGIES     7
#define EG2D_LIST_DISTRIBUTIONS  8
#define EG2D_LIST_SET_FORMATS    9  /* the formats that hold a set of blocks (eg2d_blocks_write) */

/* The number of entries of `list`. EG2D_ERR_ARGUMENT: an unknown list, NULL. */
EG2D_API int eg2d_list_count(int list, int *count);
/* Entry `index` (0 <= index < count, in increasing id order): its id and
 * name (either pointer may be NULL). EG2D_ERR_ARGUMENT: an unknown list, an
 * index out of range; nothing is written then. */
EG2D_API int eg2d_list_entry(int list, int index, int *id, const char **name);
/* The name of `id` in `list`, or NULL when this library has no such id. */
EG2D_API const char *eg2d_list_name(int list, int id);
/* The id named `name` in `list` (exact, case-sensitive). EG2D_ERR_ARGUMENT:
 * no such name; the message (eg2d_last_error(NULL)) lists the valid ones. */
EG2D_API int eg2d_list_find(int list, const char *name, int *id);

/* What a parameter's value may be, as bits of eg2d_parameter_info's *kind. */
#define EG2D_VALUE_REAL        0  /* any number within the bounds */
#define EG2D_VALUE_INTEGER     1  /* whole numbers only */
#define EG2D_VALUE_FLAG        2  /* 0 (off) or 1 (on); INTEGER is set too */
#define EG2D_VALUE_AUTOMATIC   4  /* 0 means "chosen by the library", even outside the bounds */
#define EG2D_VALUE_OPEN_LOWER  8  /* the lower bound itself is excluded */
#define EG2D_VALUE_OPEN_UPPER 16  /* the upper bound itself is excluded */
/* A parameter's kind (EG2D_VALUE_* bits), its unit ("1" for a pure number,
 * "length" for the grid's coordinate unit, "chords", "nodes", "iterations",
 * "sweeps") and a one-line summary; any pointer may be NULL. Bounds and
 * default: eg2d_parameter_bounds. EG2D_ERR_ARGUMENT: no such parameter. */
EG2D_API int eg2d_parameter_info(int param, int *kind, const char **unit, const char **summary);

/* What a format writes, eg2d_format_info's *kind. */
#define EG2D_WRITES_FILE      0  /* one file */
#define EG2D_WRITES_DIRECTORY 1  /* a directory of files (an OpenFOAM case) */
/* A format's kind and the usual suffix of its file or directory (".vts",
 * ".report.json", "_foam"); either pointer may be NULL. EG2D_ERR_ARGUMENT:
 * no such format. (Whether a plugin format can be written here, CGNS
 * without its plugin, eg2d_write says: EG2D_ERR_UNSUPPORTED.) */
EG2D_API int eg2d_format_info(int format, int *kind, const char **suffix);

/* The name of a quality metric's per-cell field (as in .vts and .gmv files;
 * "area" for both EG2D_QUALITY_MIN_AREA and _MAX_AREA), or NULL when the
 * metric is a summary only (the EG2D_QUALITY_ORTHO_* metrics) or unknown. */
EG2D_API const char *eg2d_quality_cell_field(int metric);

/*=====================================================================
 * 3) Ids, one ordered table per kind
 *
 * Every id the calls below take, defined here before any call uses it.
 * What an id does is said at the call that takes it (named on each table).
 *===================================================================*/

/* Sides (eg2d_set_side, eg2d_set_wall_spacing, eg2d_set_patch, ...). */
#define EG2D_SIDE_JMIN 0  /* j = 0,    ni points */
#define EG2D_SIDE_IMAX 1  /* i = ni-1, nj points */
#define EG2D_SIDE_JMAX 2  /* j = nj-1, ni points */
#define EG2D_SIDE_IMIN 3  /* i = 0,    nj points */

/* Directions (eg2d_set_interior_line, eg2d_add_line_source). */
#define EG2D_XI  0  /* a xi = const line (i index), acts on P */
#define EG2D_ETA 1  /* an eta = const line (j index), acts on Q */

/* Topologies (eg2d_set_topology, eg2d_set_airfoil). */
#define EG2D_TOPO_SINGLE 0  /* four sides, all fixed (the default) */
#define EG2D_TOPO_O      1  /* periodic in i round a closed JMIN inside a closed JMAX */
#define EG2D_TOPO_C      2  /* a C-grid round a body, with a wake cut on JMIN */

/* Initial grids (eg2d_initialize). */
#define EG2D_INIT_TFI        0  /* linear transfinite interpolation */
#define EG2D_INIT_HERMITE    1  /* TFI with Hermite blending: lines leave sides at 90 degrees */
#define EG2D_INIT_HYPERBOLIC 2  /* the hyperbolic march out from JMIN */

/* Systems (eg2d_set_system). */
#define EG2D_SYSTEM_LAPLACE     0  /* Amsden-Hirt, x_xixi + x_etaeta = 0: linear */
#define EG2D_SYSTEM_WINSLOW     1  /* Winslow / Thompson-Thames-Mastin (default) */
#define EG2D_SYSTEM_VARIATIONAL 2  /* minimise V = aA + bS + cO + dW */

/* Solvers (eg2d_set_solver); one iteration of each is said there. */
#define EG2D_SOLVER_PSOR      0  /* point SOR (Gauss-Seidel at omega = 1) */
#define EG2D_SOLVER_LSOR      1  /* line SOR, alternating directions; the periodic
                                    direction of an O-grid is solved as a cyclic system */
#define EG2D_SOLVER_AF        2  /* approximate factorisation, false transients */
#define EG2D_SOLVER_NESTED    3  /* coarse-to-fine, Petrilli (1989) */
#define EG2D_SOLVER_MULTIGRID 4  /* FAS multigrid (the default); see EG2D_PARAM_MG_* */

/* Orthogonality controls (eg2d_set_orthogonality). */
#define EG2D_ORTHO_NONE              0  /* none (the default) */
#define EG2D_ORTHO_MIDDLECOFF_THOMAS 1  /* Phi, Psi from the boundary point distribution */
#define EG2D_ORTHO_WALL              2  /* first-cell height and 90 degrees at wall sides */

/* Parameters (eg2d_set_parameter, eg2d_get_parameter, eg2d_parameter_bounds).
 * Values are doubles; an integer parameter takes only whole values; a
 * value out of its bounds is EG2D_ERR_ARGUMENT with nothing changed. Ids
 * are grouped with gaps: 0-99 run, 10-19 the variational system,
 * 100-199 solvers, 200-299 controls, 300-399 output, 400-499 geometry and
 * initial grid. Each line: bounds, default, unit: meaning. Lengths are in
 * the boundary's length unit unless "chords" is said; "auto" = a value of
 * 0 asks for the automatic one. */
#define EG2D_PARAM_RELAXATION         0  /* (0, 2), auto (default): SOR factor omega */
#define EG2D_PARAM_TOLERANCE          1  /* (0, 1), default 1e-8: stop at residual <= it */
#define EG2D_PARAM_MAX_ITERATIONS     2  /* [1, 1e9] integer, default 100000: limit of one eg2d_solve */
#define EG2D_PARAM_DIVERGENCE_FACTOR  3  /* [10, 1e12], default 1e4: a residual this many times
                                            the best of the run (and above 1e-2) is divergence */
#define EG2D_PARAM_FOLD_CHECK         4  /* 0 or 1 (default): eg2d_solve returns EG2D_ERR_FOLDED
                                            for a converged grid with folded cells; variational
                                            system: 1 also guards every step against folding */
#define EG2D_PARAM_STALL_ITERATIONS   5  /* [0, 1e9] integer, auto (default), iterations: this many
                                            in a row without progress end eg2d_solve with
                                            EG2D_ERR_NOT_CONVERGED (eg2d_solve) */
#define EG2D_PARAM_MONITOR_SET_UP     6  /* 0 (default) or 1: the monitor is also called during a
                                            run's set-up (eg2d_set_monitor) */
#define EG2D_PARAM_VARIATIONAL_AREA          10  /* [0, 1e6], default 0, dimensionless: weight a */
#define EG2D_PARAM_VARIATIONAL_SPACING       11  /* [0, 1e6], default 1, dimensionless: weight b */
#define EG2D_PARAM_VARIATIONAL_ORTHOGONALITY 12  /* [0, 1e6], default 0, dimensionless: weight c */
#define EG2D_PARAM_VARIATIONAL_SMOOTHNESS    13  /* [0, 1e6], default 0, dimensionless: weight d */
#define EG2D_PARAM_VARIATIONAL_ORTHOGONALITY_FORM 14  /* 0 (default): O as dot products;
                                                     1: as squared cotangents (eg2d_set_system) */
#define EG2D_PARAM_AF_DTAU_MIN      100  /* (0, 1e12], default 0.5, dimensionless: smallest step */
#define EG2D_PARAM_AF_DTAU_MAX      101  /* (0, 1e12], >= dtau_min, auto (default): largest step */
#define EG2D_PARAM_AF_STEPS         102  /* [4, 1000] integer, auto (default): steps M per cycle */
#define EG2D_PARAM_AF_A             103  /* (-1, 10], default 0: Warming-Beam a */
#define EG2D_PARAM_AF_B             104  /* (0, 10], default 1: Warming-Beam b */
#define EG2D_PARAM_AF_RELAXATION    105  /* (0, 4), auto (default: omega = 2b): omega of
                                            Ly & Norrison (2007) eq 7 */
#define EG2D_PARAM_MG_CYCLE         110  /* 1 = V cycle, 2 = W cycle (default) */
#define EG2D_PARAM_MG_PRE_SMOOTH    111  /* [0, 20] integer, default 2: sweeps before the coarse
                                            correction */
#define EG2D_PARAM_MG_POST_SMOOTH   112  /* [0, 20] integer, default 1: sweeps after it (pre + post
                                            >= 1, else eg2d_iterate/solve fail with EG2D_ERR_STATE) */
#define EG2D_PARAM_MG_FMG           113  /* 0 or 1 (default): full-multigrid start from an initial
                                            grid; 0: cycles from the grid as it is */
#define EG2D_PARAM_MG_COARSEST      114  /* [3, 1e9] integer, default 5, nodes: a direction with this
                                            many nodes or fewer is not coarsened further */
#define EG2D_PARAM_WALL_DECAY       200  /* [0.01, 10], default 0.3, per cell: decay rate a of the
                                            wall control, which acts as exp(-a (m-1)) at depth m */
#define EG2D_PARAM_WALL_RELAXATION  201  /* (0, 1], default 0.1: under-relaxation of the wall
                                            control's updates between iterations */
#define EG2D_PARAM_WALL_GROWTH      202  /* [1, 1.5], default 1.15: cell-to-cell growth of the
                                            marched wall layer (EG2D_PARAM_WALL_LAYER 1) */
#define EG2D_PARAM_WALL_LAYER       203  /* 0, 1, 2 or 3 (default): the layer EG2D_ORTHO_WALL makes
                                            at walls with a height: 0 the control alone, 1 marched
                                            and held, 2 hybrid, 3 automatic (eg2d_set_orthogonality) */
#define EG2D_PARAM_SVG_QUALITY      300  /* -1 (default) or an EG2D_QUALITY_* id with per-cell
                                            values: the metric EG2D_FORMAT_SVG colours cells by */
#define EG2D_PARAM_SPAN             301  /* (0, 1e30], default 1, length: the thickness (z) of the
                                            one layer of cells of EG2D_FORMAT_OPENFOAM and
                                            EG2D_PLOT3D_EXTRUDED */
#define EG2D_PARAM_HERMITE_SPACING  400  /* (0, 10], default 1, dimensionless: alpha of
                                            EG2D_INIT_HERMITE */
#define EG2D_PARAM_HERMITE_SIDES       401  /* [0, 15] integer, default 0: mask, sum of
                                               (1 << EG2D_SIDE_*), of the Hermite sides; 0: JMIN
                                               and JMAX in eta only */
#define EG2D_PARAM_HERMITE_HEIGHT_JMIN 402  /* [0, 1e30], default 0 (alpha x the uniform spacing),
                                               length: first-cell height h of JMIN */
#define EG2D_PARAM_HERMITE_HEIGHT_IMAX 403  /* the same for IMAX */
#define EG2D_PARAM_HERMITE_HEIGHT_JMAX 404  /* JMAX */
#define EG2D_PARAM_HERMITE_HEIGHT_IMIN 405  /* IMIN (= EG2D_PARAM_HERMITE_HEIGHT_JMIN + side) */
#define EG2D_PARAM_MARCH_DISTANCE      410  /* (0, 1e30], length, auto (default): D, 10 x the
                                               diagonal of JMIN's bounding box */
#define EG2D_PARAM_MARCH_FIRST_HEIGHT  411  /* (0, 1e30], length, auto (default): h_1, the one whose
                                               constant ratio r = 1 + (G-1)/2 reaches D */
#define EG2D_PARAM_MARCH_GROWTH        412  /* [1, 3], default 1.2: G, the largest layer ratio */
#define EG2D_PARAM_MARCH_SMOOTHING     413  /* [0, 20], default 0.5: eps_c, strength of the explicit
                                               (and twice it, implicit) dissipation */
#define EG2D_PARAM_MARCH_AREA_SMOOTHING 414 /* [0, 1000] integer, default 20: area-smoothing passes
                                               per layer */
#define EG2D_PARAM_MARCH_END_IMIN      415  /* EG2D_MARCH_END_* (below), default FREE: the i = 0 end
                                               of a single-block or C-grid march */
#define EG2D_PARAM_MARCH_END_IMAX      416  /* the same for the i = ni-1 end */
#define EG2D_PARAM_AIRFOIL_FARFIELD      420  /* [2, 1e6] chords, default 100: the far field's least
                                                 distance from the section (a C-grid's outflow
                                                 this far behind the trailing edge) */
#define EG2D_PARAM_AIRFOIL_LE_SPACING    421  /* (0, 0.1] chords, auto (default: a tenth of the
                                                 section's mean spacing): spacing at the
                                                 leading edge */
#define EG2D_PARAM_AIRFOIL_TE_SPACING    422  /* (0, 0.1] chords, auto (default: a quarter of the
                                                 mean spacing): spacing at the trailing edge, along
                                                 a blunt base and the C-grid cut's first */
#define EG2D_PARAM_AIRFOIL_WAKE_NODES    423  /* [2, 1e8] integer, auto (default: about 0.21 (ni-1)):
                                                 C-grid cut nodes a side, the trailing edge's index
                                                 (eg2d_get_cut gives the count in use) */
#define EG2D_PARAM_AIRFOIL_TRAILING_EDGE 424  /* EG2D_AIRFOIL_TE_BLUNT (default) or _SHARPEN (below):
                                                 what an open trailing edge becomes */
#define EG2D_PARAM_AIRFOIL_O_TE_BASE     425  /* [0, 0.01] chords, default 5e-5: O-grid: a sharp
                                                 trailing edge is cut back to a straight base this
                                                 thick, part of the wall; 0 keeps it one node */

/* Values of EG2D_PARAM_MARCH_END_IMIN/IMAX: open ends of a single-block or
 * C-grid march (O-grids have none). */
#define EG2D_MARCH_END_FREE      0  /* the end node steps along its own normal */
#define EG2D_MARCH_END_CONSTANT_X 1 /* x stays that of JMIN's end, y follows the neighbour (a
                                       symmetry plane x = const) */
#define EG2D_MARCH_END_CONSTANT_Y 2 /* the same with y = const */
#define EG2D_MARCH_END_SPLAY     3  /* the end cell widens in proportion to the layer height,
                                       so the end line splays outward */

/* Values of EG2D_PARAM_AIRFOIL_TRAILING_EDGE. */
#define EG2D_AIRFOIL_TE_BLUNT   0  /* kept as a blunt base: straight, part of the wall */
#define EG2D_AIRFOIL_TE_SHARPEN 1  /* each surface moved towards the base's midpoint in
                                      proportion to its distance along the chord */

/* What the last run did (eg2d_get_run_info). */
#define EG2D_RUN_SOLVER       0  /* the EG2D_SOLVER_* that ran */
#define EG2D_RUN_LEVELS       1  /* grid levels in use at the end (1: the fine grid alone) */
#define EG2D_RUN_LEVELS_BUILT 2  /* levels the grid's size allowed (multigrid, nested) */
#define EG2D_RUN_EVENTS       3  /* changes of strategy during the run */

/* Quality metrics (eg2d_get_quality, eg2d_get_cell_quality,
 * EG2D_PARAM_SVG_QUALITY). Angles in degrees, areas in length squared. */
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
#define EG2D_QUALITY_ORTHO_MAX_JMIN  40  /* largest deviation from 90 degrees at a side
                                            (ORTHO_MAX_JMIN + side); summary only */
#define EG2D_QUALITY_ORTHO_MAX_IMAX  41
#define EG2D_QUALITY_ORTHO_MAX_JMAX  42
#define EG2D_QUALITY_ORTHO_MAX_IMIN  43
#define EG2D_QUALITY_ORTHO_MEAN_JMIN 50  /* mean deviation at a side (ORTHO_MEAN_JMIN + side) */
#define EG2D_QUALITY_ORTHO_MEAN_IMAX 51
#define EG2D_QUALITY_ORTHO_MEAN_JMAX 52
#define EG2D_QUALITY_ORTHO_MEAN_IMIN 53
#define EG2D_QUALITY_SCALED_JACOBIAN 60  /* smallest over cells of the least sin(corner angle),
                                            signed by the grid's orientation: 1 for a rectangle,
                                            < 0 in a folded cell; per cell: its least (the Verdict
                                            quadrilateral scaled Jacobian, Stimpson et al. 2007) */

/* The wall layer as measured (eg2d_get_wall_layer); lengths in the
 * boundary's unit. */
#define EG2D_WALL_FIRST_MIN     0  /* smallest first-cell height */
#define EG2D_WALL_FIRST_MEDIAN  1  /* median first-cell height */
#define EG2D_WALL_FIRST_MAX     2  /* largest first-cell height */
#define EG2D_WALL_GROWTH        3  /* largest growth off the wall (EG2D_WALL_ROWS cells) */
#define EG2D_WALL_ANGLE         4  /* largest deviation from the wall normal, degrees */
#define EG2D_WALL_NODES         5  /* nodes measured */
#define EG2D_WALL_NODES_NEEDED  6  /* node count across the layer for growth 1.2; 0: met */
#define EG2D_WALL_ROWS 30          /* cells off the wall over which the growth is measured */

/* File formats (eg2d_write; eg2d_read_plot3d gives the Plot3D ones). */
#define EG2D_FORMAT_PLOT3D       0  /* Plot3D whole grid, Fortran-unformatted binary */
#define EG2D_FORMAT_PLOT3D_ASCII 1  /* the same numbers as text */
#define EG2D_FORMAT_VTS          2  /* VTK XML StructuredGrid with the per-cell metrics */
#define EG2D_FORMAT_CGNS         3  /* CGNS (the optional plugin libeg2d_cgns.so) */
#define EG2D_FORMAT_GMV          4  /* GMV ASCII */
#define EG2D_FORMAT_MATLAB       5  /* a Matlab/Octave script that plots the grid */
#define EG2D_FORMAT_SVG          6  /* a picture, cells coloured by EG2D_PARAM_SVG_QUALITY */
#define EG2D_FORMAT_SU2          7  /* SU2 native mesh with the patches as markers */
#define EG2D_FORMAT_OPENFOAM     8  /* an OpenFOAM case directory (polyMesh) */
#define EG2D_FORMAT_REPORT       9  /* the grid's report as text */
#define EG2D_FORMAT_REPORT_JSON 10  /* the same as one JSON object */
#define EG2D_FORMAT_VTM         11  /* VTK XML multiblock: NAME.vtm naming a .vts a block in NAME/ */
/* Plot3D variants: flags OR-ed into EG2D_FORMAT_PLOT3D or _PLOT3D_ASCII. */
#define EG2D_PLOT3D_3D         0x100   /* the 3D form with one k-plane, z = 0 */
#define EG2D_PLOT3D_MULTI      0x200   /* the multi-grid header (a grid count of 1) */
#define EG2D_PLOT3D_SINGLE     0x400   /* 4-byte reals (binary only) */
#define EG2D_PLOT3D_BIG_ENDIAN 0x800   /* big-endian (binary only) */
#define EG2D_PLOT3D_NO_MARKERS 0x1000  /* a C stream: no Fortran record markers */
#define EG2D_PLOT3D_EXTRUDED   0x2000  /* two k-planes, z = 0 and EG2D_PARAM_SPAN; implies 3D */

/* Point distributions on [0, 1] (eg2d_distribution, eg2d_curve_points,
 * eg2d_set_side_curve). */
#define EG2D_DIST_UNIFORM     0  /* s = u */
#define EG2D_DIST_EXPONENTIAL 1  /* p1 = beta */
#define EG2D_DIST_TANH_ONE    2  /* p1 = delta, one-sided */
#define EG2D_DIST_TANH_TWO    3  /* p1 = b, p2 = c, two-sided */
#define EG2D_DIST_VINOKUR     4  /* p1, p2 = the first and last spacings */

/* Flags of eg2d_set_side_curve. */
#define EG2D_CURVE_REVERSE 1  /* use the curve from its end to its start */
#define EG2D_CURVE_ORIENT  2  /* reverse it when, and only when, it runs against the grid */
#define EG2D_CURVE_SLIDING 4  /* the side's nodes slide along the curve */

/* Flags of eg2d_curve_naca4. */
#define EG2D_NACA_CLOSED_TE 1  /* the sharp, closed trailing edge */

/* Clustering maps (eg2d_clustering_map). */
#define EG2D_CLUSTER_LINE       0  /* dense at a */
#define EG2D_CLUSTER_TWO_LINES  1  /* dense at a and b */
#define EG2D_CLUSTER_BOUNDARIES 2  /* dense at 0 and 1 */

/* Boundary patch types (eg2d_set_patch, eg2d_get_patch). */
#define EG2D_PATCH_WALL     0  /* a no-slip (or slip) solid wall: OpenFOAM wall, CGNS BCWall */
#define EG2D_PATCH_FARFIELD 1  /* free stream: OpenFOAM patch, CGNS BCFarfield */
#define EG2D_PATCH_OUTFLOW  2  /* OpenFOAM patch, CGNS BCOutflow */
#define EG2D_PATCH_INFLOW   3  /* OpenFOAM patch, CGNS BCInflow */
#define EG2D_PATCH_SYMMETRY 4  /* OpenFOAM symmetry, CGNS BCSymmetryPlane */
#define EG2D_PATCH_CUT      5  /* reported only (eg2d_get_patch): the O-grid's periodic cut,
                                  the C-grid's wake; never set */

/*=====================================================================
 * 4) Create and boundary
 *===================================================================*/
/* A grid of ni x nj nodes, ni, nj >= 3 (and ni*nj must fit the address
 * space). *grid is set to NULL on failure. Defaults: single-block topology,
 * Winslow system, multigrid solver, tolerance 1e-8, automatic relaxation. */
EG2D_API int eg2d_create(int ni, int nj, eg2d_grid **grid);

/* Frees everything; NULL is a no-op. */
EG2D_API void eg2d_destroy(eg2d_grid *grid);

/* The topology, an EG2D_TOPO_*.
 *  SINGLE  four sides, all fixed.
 *  O       periodic in i: JMIN is the inner and JMAX the outer closed curve
 *          (first point == last point); columns i = 0 and i = ni-1 are the
 *          same physical points (the branch cut), solved with the interior.
 *  C       a C-grid round a body with a wake cut (ni >= 7): JMIN runs from
 *          the outflow end of the lower wake to the trailing edge, round the
 *          body and back along the upper wake; JMAX is the far field, IMIN
 *          and IMAX the two outflow lines. The cut is read from JMIN: the
 *          leading run of points i = 0..w with point i equal to point
 *          ni-1-i (to 1e-8 of JMIN's size); w is the trailing edge. The
 *          cut's inner nodes 0 < i < w are solved with the interior (the two
 *          wake halves stay the same points); i = 0 and i = w stay fixed.
 * Changing the topology forgets the boundary, the grid, the interior lines
 * and the patches. EG2D_ERR_ARGUMENT for an unknown id. */
EG2D_API int eg2d_set_topology(eg2d_grid *grid, int topology);
EG2D_API int eg2d_get_topology(const eg2d_grid *grid, int *topology);
/* C-grid: w, the trailing edge's index on JMIN as set (node (i, 0) is node
 * (ni-1-i, 0) for i = 0..w; after eg2d_set_airfoil the count of
 * EG2D_PARAM_AIRFOIL_WAKE_NODES). 0 while JMIN is not set and on the other
 * topologies. */
EG2D_API int eg2d_get_cut(const eg2d_grid *grid, int *wake);

/* Sets one side (EG2D_SIDE_*) from its points in increasing index, in the
 * boundary's length unit. Corners shared with a side already set must agree
 * to 1e-8 of the boundary's size, or the call fails with EG2D_ERR_BOUNDARY
 * and sets nothing. On an O-grid only JMIN and JMAX exist and each must be a
 * closed curve. On a C-grid JMIN must hold the wake cut (EG2D_TOPO_C). A
 * side set after the grid was initialised moves only the boundary: the
 * interior is kept as a warm start. */
EG2D_API int eg2d_set_side(eg2d_grid *grid, int side, const double *x, const double *y);

/* Sets the whole boundary ring from ni*nj arrays in Fortran order; only the
 * boundary nodes are read (for an O-grid: rows j = 0 and j = nj-1). Errors
 * as eg2d_set_side. */
EG2D_API int eg2d_set_boundary(eg2d_grid *grid, const double *x, const double *y);

/* Boundary patches. Each side, or a stretch of one, carries a type
 * (EG2D_PATCH_*) and a name, which the solver-ready formats write as its
 * boundary condition (SU2 marker, OpenFOAM patch, CGNS BC_t). Where the
 * user sets none, the topology's defaults hold: single block: each side one
 * patch "jmin", "imax", "jmax", "imin", all WALL; O-grid: JMIN "wall"
 * (WALL), JMAX "farfield" (FARFIELD), the periodic cut internal; C-grid:
 * JMIN's body "wall" (WALL), its wake stretches the cut, JMAX "farfield",
 * IMIN and IMAX "outflow" (OUTFLOW). A patch set replaces the default on
 * its stretch only. Patches are kept across boundary changes and forgotten
 * with the topology. Details: docs/methods.md, "Boundary patches".
 *
 * eg2d_set_patch gives nodes first..last of `side`, 0 <= first < last <=
 * (side length) - 1, a type (EG2D_PATCH_WALL..SYMMETRY) and a name: 1 to 32
 * characters, a letter first, then letters, digits, '_' or '-'. Two
 * stretches may share a name only with the same type; a patch of exactly
 * the range of an existing one replaces it. EG2D_ERR_ARGUMENT, nothing
 * changed, for a side the topology lacks, a range outside the side or
 * overlapping another patch, a bad type or name, or a stretch of a C-grid's
 * wake cut (checked when the patches are used if JMIN was not yet set). */
EG2D_API int eg2d_set_patch(eg2d_grid *grid, int side, int first, int last, int type, const char *name);
/* Forgets the user's patches: the defaults hold again. */
EG2D_API int eg2d_clear_patches(eg2d_grid *grid);
/* The boundary as the writers see it: the user's patches, the defaults on
 * the rest and the cut (type EG2D_PATCH_CUT; an O-grid's as side IMIN,
 * nodes 0..nj-1), in the order JMIN, IMAX, JMAX, IMIN and by increasing
 * index: every boundary edge lies in exactly one. *count is their number;
 * eg2d_get_patch gives the index-th (0-based) with its name into name[size]
 * (NUL-terminated, cut short to fit; name may be NULL with size 0). Any
 * output pointer may be NULL. EG2D_ERR_STATE on a C-grid before JMIN is
 * set; EG2D_ERR_ARGUMENT for an index out of range. */
EG2D_API int eg2d_get_patch_count(const eg2d_grid *grid, int *count);
EG2D_API int eg2d_get_patch(const eg2d_grid *grid, int index, int *side, int *first, int *last, int *type,
                            char *name, int size);

/*=====================================================================
 * 5) Initial grid
 *===================================================================*/
/* Fills the interior from the boundary with an EG2D_INIT_* method. Needs
 * the whole boundary (EG2D_INIT_HYPERBOLIC: JMIN alone). The boundary is
 * the one set: a C-grid's wake cut and sliding sides, which a solve moves,
 * start again from the points given, so a handle re-initialised after a
 * solve runs exactly as a new one. This call and eg2d_solve/eg2d_iterate
 * refuse, with EG2D_ERR_BOUNDARY and nothing changed, a boundary that
 * crosses itself (the message names the segments and the point) and one
 * that encloses no area.
 *  TFI         linear transfinite interpolation (the grid-generation
 *              lecture notes eq 2.2).
 *  HERMITE     TFI with Hermite blending in eta and the orthogonal projector
 *              (the lecture notes eqs 2.4-2.6): lines leave JMIN and JMAX
 *              normal to them with d r/d eta of length alpha |r(i,nj-1) -
 *              r(i,0)| / (nj-1), alpha = EG2D_PARAM_HERMITE_SPACING; linear
 *              in xi. Can fold on strongly curved sides. With
 *              EG2D_PARAM_HERMITE_SIDES: Hermite at the chosen sides, in both
 *              directions, lines at 90 degrees with first cells of height
 *              EG2D_PARAM_HERMITE_HEIGHT_<side>; EG2D_ERR_ARGUMENT for a
 *              chosen side the topology lacks, EG2D_ERR_FOLDED when the grid
 *              still folds at the shortest reach of the derivative.
 *  HYPERBOLIC  marches the grid out from JMIN layer by layer (Steger &
 *              Chaussee 1980, Chan & Steger 1992; docs/hyperbolic.md): each
 *              layer orthogonal to the one before, with the areas of the
 *              schedule h_k = h_1 r^(k-1) (EG2D_PARAM_MARCH_*, lengths in the
 *              boundary's unit), r in [1/G, G] such that the heights add up
 *              to D. The grid made, outer side included, becomes the
 *              boundary (sides set before are replaced, sliding dropped). An
 *              O-grid marches outward, a C-grid away from its body, a single
 *              block to the left of JMIN as it runs. Errors, the handle
 *              keeping what it had: EG2D_ERR_FOLDED if a layer folds (the
 *              message names it), EG2D_ERR_STATE if JMIN is not set or
 *              interior lines are, EG2D_ERR_ARGUMENT if h_1 cannot reach D
 *              with growth <= G in nj-1 layers (the message gives the
 *              reachable distance), EG2D_ERR_DIVERGED if a layer system is
 *              singular (JMIN with repeated points).
 * Details: docs/methods.md, "Initial grid". */
EG2D_API int eg2d_initialize(eg2d_grid *grid, int method);

/* A start grid of the user's own: whole ni*nj arrays, boundary included
 * (which then becomes the boundary). For an O-grid, columns 0 and ni-1 must
 * agree. */
EG2D_API int eg2d_set_coordinates(eg2d_grid *grid, const double *x, const double *y);

/* Interior lines: a grid line inside the domain held on a curve of the
 * user's. direction EG2D_XI is the column i = index (nj points, JMIN to
 * JMAX), EG2D_ETA the row j = index (ni points, IMIN to IMAX; on an O-grid a
 * closed curve); index in [1, ni-2] (resp. [1, nj-2]). x, y are the line's
 * nodes in increasing index, ends included; the ends must be the
 * boundary's nodes where the line meets it (to 1e-8 of the boundary's
 * size), and a column and a row must share their crossing node. A line of
 * the same direction and index is replaced; points are copied. Columns need
 * the single-block topology (EG2D_ERR_UNSUPPORTED on O- and C-grids); rows
 * work on all three. TFI and Hermite TFI fill each sub-block between the
 * lines (piecewise TFI, Thompson, Warsi & Mastin 1985); every solver keeps
 * the lines' nodes fixed; EG2D_INIT_HYPERBOLIC fails with EG2D_ERR_STATE
 * and EG2D_ORTHO_WALL makes no marched wall layer while lines are set; a
 * grid given by eg2d_set_coordinates gets the lines' points. Setting or
 * clearing a line restarts the run like
 * a new start grid; on an initialised grid the new line's nodes move onto
 * it at once. Errors, the handle unchanged: EG2D_ERR_ARGUMENT for a bad
 * direction, index, NULL or non-finite point; EG2D_ERR_BOUNDARY for ends off
 * the boundary, an open O-grid row or crossing lines that disagree. Lines
 * are forgotten with the topology. Details: docs/methods.md. */
EG2D_API int eg2d_set_interior_line(eg2d_grid *grid, int direction, int index, const double *x, const double *y);
/* Forgets every interior line: their nodes are unknowns again. */
EG2D_API int eg2d_clear_interior_lines(eg2d_grid *grid);

/*=====================================================================
 * 6) System, controls and walls
 *
 * Control terms turn the Winslow system into the full equation of
 * docs/NUMERICS.md
 *   alpha (r_xixi + Phi r_xi) - 2 beta r_xieta + gamma (r_etaeta + Psi r_eta)
 *     + J^2 (P r_xi + Q r_eta) = 0
 * (plus Khattri's (2006) parameter-space terms). A grid has at most one
 * control of each kind below; different kinds add up. Controls are kept
 * across boundary changes and re-derived from the new boundary. They need
 * the Winslow system: eg2d_iterate/eg2d_solve with another system and any
 * control set fail with EG2D_ERR_STATE and change nothing. Every control
 * works with every solver and on O-grids (distances in xi the short way
 * round the cut). Each call validates all its arguments first; a failed
 * call changes nothing.
 *===================================================================*/
/* The system, an EG2D_SYSTEM_*; EG2D_ERR_ARGUMENT for an unknown id.
 * EG2D_SYSTEM_VARIATIONAL (Brackbill & Saltzman 1982): the interior nodes
 * minimise, with the boundary fixed,
 *     V = a A/Abar + b S + c O/Abar + d W
 * S the sum over edges of |r_q - r_p|^2 (spacing), A the sum over cells of
 * area^2, O the sum over cell corners of (u.v)^2 of the corner's edges
 * (orthogonality; with EG2D_PARAM_VARIATIONAL_ORTHOGONALITY_FORM 1 the
 * squared cotangents (u.v)^2/(u x v)^2, scaled by Abar), W Winslow's
 * functional at the corners (Charakhch'yan & Ivanenko 1997), Abar the mean
 * cell area; the weights a, b, c, d are EG2D_PARAM_VARIATIONAL_*
 * (dimensionless; setting them all 0 is EG2D_ERR_ARGUMENT). The residual is
 * V's gradient scaled like the other systems'. With EG2D_PARAM_FOLD_CHECK 1
 * no step folds a cell; where V's minimum folds cells the run ends with
 * EG2D_ERR_NOT_CONVERGED (the message says so). Solvers: MULTIGRID (a
 * Newton minimiser, or FAS cycles for S alone and on C-grids), PSOR and
 * NESTED; LSOR and AF fail with EG2D_ERR_STATE. Control terms need
 * EG2D_SYSTEM_WINSLOW (EG2D_ERR_STATE). Details and measurements:
 * docs/methods.md, "System, controls and walls". */
EG2D_API int eg2d_set_system(eg2d_grid *grid, int system);

/* Thompson's attraction (docs/NUMERICS.md, "Source terms"), in index units:
 *   P = -sum a sign(xi - line) exp(-decay |xi - line|)  (direction EG2D_XI)
 *   Q = -sum a sign(eta - line) exp(-decay |eta - line|) (direction EG2D_ETA)
 * A positive amplitude attracts lines of that family toward `line`, a
 * negative one repels them. line in [0, ni-1] (resp. [0, nj-1]); decay >= 0;
 * amplitude finite. Ly & Norrison (2007) eq 14 is direction EG2D_ETA with
 * amplitude mu and decay kappa. Sources accumulate until eg2d_clear_sources.
 * The strength of a given amplitude depends on the physical size of the
 * cells (P enters times J^2). */
EG2D_API int eg2d_add_line_source(eg2d_grid *grid, int direction, double line, double amplitude, double decay);
/* Attraction of both families toward the point (xi, eta):
 *   P -= a sign(xi - xi0) exp(-decay d), Q -= a sign(eta - eta0) exp(-decay d),
 *   d = sqrt((xi - xi0)^2 + (eta - eta0)^2). */
EG2D_API int eg2d_add_point_source(eg2d_grid *grid, double xi, double eta, double amplitude, double decay);
/* Removes every line and point source. */
EG2D_API int eg2d_clear_sources(eg2d_grid *grid);

/* The user's own P and Q per node (ni*nj, Fortran order), as Petrilli's
 * (1989) p1/p2 arrays: the term J^2 (P r_xi + Q r_eta). A positive P pushes
 * xi-lines toward larger xi. Either pointer may be NULL (that one is zero);
 * both NULL removes the arrays. Values must be finite. The arrays are
 * copied. */
EG2D_API int eg2d_set_source_arrays(eg2d_grid *grid, const double *P, const double *Q);

/* Orthogonality at the boundary, an EG2D_ORTHO_*; NONE removes it.
 *  MIDDLECOFF_THOMAS  Petrilli (1989) section 4: Phi from the point
 *      distribution of the eta = const boundaries, Psi from the xi = const
 *      ones (none on an O-grid), interpolated inward. Nearly orthogonal on
 *      smooth curved boundaries; zero away from the corners on straight
 *      segments.
 *  WALL  the first-cell height of eg2d_set_wall_spacing and lines at 90
 *      degrees at each wall side. EG2D_PARAM_WALL_LAYER chooses how:
 *      0  a Sorenson (GRAPE)-type control updated between iterations,
 *         decaying inward (EG2D_PARAM_WALL_DECAY), under-relaxed
 *         (EG2D_PARAM_WALL_RELAXATION); not graded.
 *      1  C- and O-grids round smooth bodies whose only wall is JMIN: a
 *         layer marched along the normals (EG2D_PARAM_WALL_GROWTH) and
 *         held, the rows above solved with a fixed control. Experimental.
 *      2  O- and C-grids whose only wall is JMIN: the hybrid layer (Steger
 *         & Sorenson 1980): the hyperbolic march's rows held, the rows
 *         above bent onto JMAX by frozen controls; JMAX, IMIN and IMAX keep
 *         their lines, their nodes may move along them.
 *      3  (default) the hybrid layer where it meets its checks, else the
 *         control of 0; the graded layer at every other set of walls of a
 *         single block or an O-grid.
 *      A wall covers its side's EG2D_PATCH_WALL stretches (the whole side
 *      when none). The automatic relaxation is 1 while the control is
 *      active. A run converges only when the control is settled too; the
 *      control starts over after any change of the start grid, the
 *      boundary, the topology or the controls. The run says which layer it
 *      made, and every fallback (eg2d_get_run_event).
 * Details and measurements: docs/methods.md, "Orthogonality at the
 * boundary and wall layers". */
EG2D_API int eg2d_set_orthogonality(eg2d_grid *grid, int method);
/* Makes `side` (EG2D_SIDE_*, one the topology has) a wall for
 * EG2D_ORTHO_WALL: height > 0 is the first-cell height (distance of the first
 * interior node from the wall along the normal, in the boundary's length
 * unit); 0 asks for orthogonality only; a negative height makes the side no
 * wall again. While no side has been made a wall, EG2D_ORTHO_WALL treats
 * every side of the topology as a wall with height 0. May be called before
 * or after eg2d_set_orthogonality. A height >= 0 on a grid with no
 * orthogonality control turns EG2D_ORTHO_WALL on (a wall asked for is a
 * wall control asked for); eg2d_set_orthogonality(grid, EG2D_ORTHO_NONE)
 * afterwards turns it off, and EG2D_ORTHO_MIDDLECOFF_THOMAS set before is
 * kept (the heights wait for EG2D_ORTHO_WALL). */
EG2D_API int eg2d_set_wall_spacing(eg2d_grid *grid, int side, double height);
/* Makes `side` a wall whose first-cell height varies along it: n must be
 * the side's node count (ni for EG2D_SIDE_JMIN and _JMAX, nj for _IMIN and
 * _IMAX) and heights[k] > 0 the height at its node k (in increasing i or
 * j), in the boundary's length unit: a height for y+ 1 from a skin
 * friction that varies along the wall, or the first cells of a blockMesh
 * edge grading. Otherwise as eg2d_set_wall_spacing(grid, side, the least
 * of them). The graded wall layer (a single block, a set of blocks) and
 * the wall control's updates hold each node's height; the marched and
 * hybrid layers (EG2D_PARAM_WALL_LAYER 1 and 2) march one height, so an
 * O- or C-grid's JMIN given heights node by node takes the updates instead
 * (a run event says so). heights NULL: the side is no wall (as a negative
 * height). eg2d_set_wall_spacing on the side, or a new topology, forgets
 * the heights node by node. The array is copied. EG2D_ERR_ARGUMENT for a
 * wrong n or a height that is not finite and positive (naming its node). */
EG2D_API int eg2d_set_wall_spacing_nodes(eg2d_grid *grid, int side, int n, const double *heights);

/* Adaptive control from a parameter-space grid (Khattri 2006): s, t are an
 * ni*nj grid on the unit square (Fortran order), unfolded: s_xi t_eta -
 * s_eta t_xi of one sign at every unknown node (O-grid: s may jump by a
 * constant at the cut). The physical grid inherits its distribution: where
 * the parameter grid is dense, so is the result. Both NULL removes it.
 * Arrays are copied. */
EG2D_API int eg2d_set_parameter_grid(eg2d_grid *grid, const double *s, const double *t);

/* Khattri's (2006) clustering maps of [0, 1] onto itself, an EG2D_CLUSTER_*,
 * sampled at n >= 2 uniform points u_k = k/(n-1) into u_out[k]; increasing,
 * u(0) = 0, u(1) = 1, with slope strength/(e^strength - 1) at the
 * attracting points:
 *   LINE       dense at a in (0, 1)                      (default strength 3)
 *   TWO_LINES  dense at a and b, 0 < a < b < 1           (default strength 3)
 *   BOUNDARIES dense at 0 and 1, split at a in (0, 1)    (default strength 4)
 * strength > 0, or 0 for the default; b is ignored unless TWO_LINES. No
 * grid: failures are reported by eg2d_last_error(NULL). */
EG2D_API int eg2d_clustering_map(int kind, double a, double b, double strength, int n, double *u_out);
/* The tensor-product parameter grid s(i, j) = u[i], t(i, j) = v[j] (ni*nj
 * arrays s, t) from two increasing distributions u (ni values), v (nj). */
EG2D_API int eg2d_tensor_parameter_grid(int ni, int nj, const double *u, const double *v, double *s, double *t);

/* Weight-function adaptivity (the grid-generation lecture notes): w per
 * node (ni*nj, Fortran order, finite and > 0); larger w = denser grid.
 * Along each index direction the spacing follows 1/w: Phi = 2 (w_e -
 * w_w)/(w_w + 2 w_c + w_e), Psi likewise. For solution-adaptive
 * regridding, set the new weights and solve again from the current grid.
 * NULL removes it. */
EG2D_API int eg2d_set_weight(eg2d_grid *grid, const double *w);

/* The control terms in force, per node (ni*nj, Fortran order), as the P
 * and Q of Thompson, Thames & Mastin (1974): every control above summed and
 * written as J^2 (P r_xi + Q r_eta), evaluated on the current grid (central
 * differences, index units). A dynamic control (EG2D_ORTHO_WALL's) gives
 * its current state. Nodes not solved for (the boundary, rows held by a
 * wall layer, nodes where J = 0) are 0; no control, or the Laplace system:
 * all 0. Needs an initialised grid (EG2D_ERR_STATE); either pointer may be
 * NULL, not both. */
EG2D_API int eg2d_get_controls(const eg2d_grid *grid, double *P, double *Q);

/*=====================================================================
 * 7) Solvers and the run
 *===================================================================*/
/* Selects a solver, an EG2D_SOLVER_*; EG2D_ERR_UNSUPPORTED for an id this
 * library lacks. One iteration is, per solver:
 *   PSOR       one lexicographic point SOR sweep.
 *   LSOR       one sweep of xi-lines then one of eta-lines.
 *   AF         one pseudo-time step: a xi and an eta line sweep.
 *   NESTED     one point SOR sweep of the full grid; the first after a new
 *              start first converges the coarser grids, coarse to fine
 *              (Petrilli 1989).
 *   MULTIGRID  one FAS cycle (EG2D_PARAM_MG_*); the first after an initial
 *              grid is the full-multigrid start.
 * Details: docs/methods.md, "Solvers and the run". */
EG2D_API int eg2d_set_solver(eg2d_grid *grid, int solver);
EG2D_API int eg2d_get_solver(const eg2d_grid *grid, int *solver);
/* A solver's short name ("psor"), or NULL if this library has no such solver. */
EG2D_API const char *eg2d_solver_name(int solver);

/* Relaxation factor omega in (0, 2); 0 = automatic: the optimum of the
 * Laplace model problem on the grid's size, approached from 1 over the
 * first sweeps; a sweep that moves the grid far more than the one before
 * is redone with less over-relaxation. PSOR, LSOR and NESTED; multigrid and
 * AF do not use it. */
EG2D_API int eg2d_set_relaxation(eg2d_grid *grid, double omega);
/* Stop when residual <= tolerance (default 1e-8), tolerance in (0, 1). */
EG2D_API int eg2d_set_tolerance(eg2d_grid *grid, double tolerance);
/* Iteration limit of one eg2d_solve call (default 100000), >= 1. */
EG2D_API int eg2d_set_max_iterations(eg2d_grid *grid, int max_iterations);

/* Generic parameters: every setting has an EG2D_PARAM_* id (the table in
 * section 3), bounds and a default; the typed setters are shorthands for
 * these. EG2D_ERR_ARGUMENT, nothing changed, for an unknown id or a value
 * out of bounds (or not whole for an integer parameter). */
EG2D_API int eg2d_set_parameter(eg2d_grid *grid, int param, double value);
EG2D_API int eg2d_get_parameter(const eg2d_grid *grid, int param, double *value);
/* Bounds and default of a parameter, without a grid. */
EG2D_API int eg2d_parameter_bounds(int param, double *lower, double *upper, double *default_value);

/* The AF cycle (Ly & Norrison 2007): pseudo-time steps in [dtau_min,
 * dtau_max] (dimensionless) over M = steps per cycle; dtau_max = 0 and
 * steps = 0 are automatic. Fails with EG2D_ERR_ARGUMENT (and changes
 * nothing) for a value out of its range or dtau_min > dtau_max. Setting
 * EG2D_PARAM_AF_DTAU_MIN/MAX one by one is checked the same way. */
EG2D_API int eg2d_set_af_cycle(eg2d_grid *grid, double dtau_min, double dtau_max, int steps);
/* The Warming-Beam time rule (Ly & Norrison 2007, Table 1): Euler implicit
 * a = 0, b = 1 (default); three-point backward a = 1/2, b = 1; trapezoidal
 * a = 0, b = 1/2. The explicit rules (b = 0) are unstable here and
 * rejected (EG2D_ERR_ARGUMENT). */
EG2D_API int eg2d_set_af_time_rule(eg2d_grid *grid, double a, double b);

/* Called after every iteration with the iteration count of the grid (it
 * counts across calls) and the residual; a nonzero return stops the run
 * with EG2D_ERR_INTERRUPTED, keeping the iterations done. With
 * EG2D_PARAM_MONITOR_SET_UP 1 it is also called during a run's set-up (its
 * start grid, the layers of a march) with a residual of +infinity; stopped
 * there, the run returns EG2D_ERR_INTERRUPTED with the handle as it was
 * before the call. NULL removes it. */
typedef int (*eg2d_monitor_fn)(void *user, int iteration, double residual);
EG2D_API int eg2d_set_monitor(eg2d_grid *grid, eg2d_monitor_fn fn, void *user);

/* Does exactly `iterations` iterations (>= 0; one sweep, or one cycle of a
 * multilevel solver) and stores the residual after them in *residual
 * (residual may be NULL). Initialises by TFI first if the grid has only a
 * boundary. */
EG2D_API int eg2d_iterate(eg2d_grid *grid, int iterations, double *residual);

/* Iterates until residual <= tolerance: EG2D_OK, or EG2D_ERR_NOT_CONVERGED
 * after max_iterations, after EG2D_PARAM_STALL_ITERATIONS without progress
 * (automatic: a count that depends on the solver and the size; the grid
 * restored to its best iteration) or when the variational system's fold
 * guard stops it, EG2D_ERR_DIVERGED, EG2D_ERR_INTERRUPTED. The messages of
 * DIVERGED and of a stall end with the run's events (eg2d_get_run_event).
 * A converged grid is checked for folded cells (EG2D_ERR_FOLDED, see
 * EG2D_PARAM_FOLD_CHECK). */
EG2D_API int eg2d_solve(eg2d_grid *grid);

/*=====================================================================
 * 8) Results and quality
 *===================================================================*/
EG2D_API int eg2d_get_size(const eg2d_grid *grid, int *ni, int *nj);
/* Copies the ni*nj node coordinates (Fortran order). Needs an initialised grid. */
EG2D_API int eg2d_get_coordinates(const eg2d_grid *grid, double *x, double *y);
/* The residual (docs/NUMERICS.md) of the current grid. Needs an initialised grid. */
EG2D_API int eg2d_get_residual(const eg2d_grid *grid, double *residual);
/* Iterations done since the grid was last initialised or given coordinates. */
EG2D_API int eg2d_get_iterations(const eg2d_grid *grid, int *iterations);

/* What the last eg2d_iterate or eg2d_solve actually ran, so that no change
 * of strategy is silent: eg2d_get_run_info gives one figure (EG2D_RUN_*),
 * eg2d_get_run_event the k-th change of strategy (k from 0 to
 * EG2D_RUN_EVENTS - 1) with the iteration during which it happened and a
 * sentence that says what and why. Both may be called from the monitor,
 * where they describe the run so far. Before any run: solver -1, 1 level,
 * no events. EG2D_ERR_ARGUMENT for an unknown `what`, an index out of range
 * or a NULL pointer; the message is cut to size - 1 bytes and always
 * terminated (size 0 with message NULL asks for nothing but the iteration;
 * size < 0 is an error). */
EG2D_API int eg2d_get_run_info(const eg2d_grid *grid, int what, int *value);
EG2D_API int eg2d_get_run_event(const eg2d_grid *grid, int index, int *iteration, char *message, int size);

/* Quality of the current grid (it must be initialised), an EG2D_QUALITY_*
 * metric. Cell (i, j), i < ni-1, j < nj-1, has the corners (i,j), (i+1,j),
 * (i+1,j+1), (i,j+1); per-cell arrays hold (ni-1)*(nj-1) values, cell
 * (i, j) at i + (ni-1)*j. A cell is folded when one of its corners turns
 * against the grid's orientation (the sign of the total area; left- and
 * right-handed grids are both legal). Orthogonality at a side: at each
 * boundary node (corners excluded; an O-grid's closed sides count every
 * node once) the deviation from 90 degrees of the angle between the
 * boundary's tangent (central difference) and the grid line leaving it.
 * eg2d_get_quality gives the scalar summary; an orthogonality metric of a
 * side the topology lacks is EG2D_ERR_ARGUMENT. */
EG2D_API int eg2d_get_quality(const eg2d_grid *grid, int metric, double *value);
/* The per-cell values of a metric into values[(ni-1)*(nj-1)];
 * EG2D_ERR_ARGUMENT for a metric without per-cell values (orthogonality). */
EG2D_API int eg2d_get_cell_quality(const eg2d_grid *grid, int metric, double *values);

/* The wall layer at a side as a flow solver sees it (EG2D_WALL_*), measured
 * on the grid as it is: over the side's EG2D_PATCH_WALL stretches (all of
 * the side when it has none), at every node but a stretch's two ends and
 * its corners with the nodes beside them. Heights are normal to the wall
 * (perpendicular to its central difference), in the boundary's length
 * unit; the growth is the largest ratio of a cell to the one below it along
 * the line leaving the wall, over its first EG2D_WALL_ROWS cells; the angle
 * is the largest deviation of that line's first segment from the wall
 * normal, in degrees. EG2D_WALL_NODES_NEEDED is the smallest node count
 * across the layer that the last run's wall layer found would keep the
 * growth within 1.2, 0 when met. Needs an initialised grid
 * (EG2D_ERR_STATE); EG2D_ERR_ARGUMENT for a side the topology lacks, an
 * unknown `what`, a NULL value, or a side with no node to measure
 * (EG2D_WALL_NODES is then 0 through no error: ask it first). */
EG2D_API int eg2d_get_wall_layer(const eg2d_grid *grid, int side, int what, double *value);

/*=====================================================================
 * 9) Files
 *===================================================================*/
/* Writes the current grid (it must be initialised) to `path` in an
 * EG2D_FORMAT_* (Plot3D: with EG2D_PLOT3D_* flags OR-ed in). The file is
 * written to a temporary in the same directory and renamed over `path` only
 * when complete: a failed write never leaves a half-written file under
 * `path` (an existing file there is kept). A file that cannot be written is
 * EG2D_ERR_IO with the path and the system's reason.
 *  PLOT3D        the 2D whole-grid form, Fortran-unformatted, little-endian,
 *                8-byte reals: record 1 "ni nj" (int32), record 2
 *                x(1..ni*nj) y(1..ni*nj); PLOT3D_ASCII the same as text.
 *                e.g. EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI.
 *  VTS, GMV      with every per-cell metric as cell data.
 *  CGNS          one structured zone with the per-cell metrics, the patches
 *                as a ZoneBC and the cut as a 1-to-1 connection; needs the
 *                plugin libeg2d_cgns.so (EG2D_PLUGIN_DIR says where), else
 *                EG2D_ERR_UNSUPPORTED.
 *  MATLAB, SVG   pictures (Khattri 2006's script; an SVG image).
 *  SU2, OPENFOAM solver-ready: the patches are the boundary conditions and
 *                a cut is interior. A C-grid needs JMIN set (EG2D_ERR_STATE);
 *                a patch on the cut is EG2D_ERR_ARGUMENT. OPENFOAM: `path`
 *                is a case directory (made if missing, its parent must
 *                exist), one layer of cells EG2D_PARAM_SPAN thick; takes no
 *                flags.
 *  REPORT, REPORT_JSON  sizes, the last run, the wall layer and the quality.
 *  VTM           VTK's multiblock form, as VTK's own writer lays it out:
 *                `path` (NAME.vtm, a vtkMultiBlockDataSet) names the
 *                blocks' files NAME/NAME_0.vts, ... (each as VTS writes
 *                it); the grid is its one block. The directory NAME (the
 *                path less its extension; a path with none is
 *                EG2D_ERR_ARGUMENT) is made if missing; the .vtm is put
 *                in place after its blocks, and a failure leaves no new
 *                block file (eg2d_format_info: EG2D_WRITES_FILE, the .vtm;
 *                its directory goes with it). Takes no flags.
 * Every format's layout: docs/methods.md, "Files". */
EG2D_API int eg2d_write(const eg2d_grid *grid, const char *path, int format);

/* Reads grid `block` (0-based) of a Plot3D whole-grid file of any variant
 * eg2d_write makes except EXTRUDED, detecting which it holds: ASCII,
 * Fortran-unformatted (either byte order, 4- or 8-byte reals) or C stream
 * binary, 2D or 3D with one k-plane (z is ignored), single- or multi-grid.
 * Gives the variant in *format (an EG2D_FORMAT_PLOT3D* id with its
 * EG2D_PLOT3D_* flags), the number of grids in *nblocks and the block's
 * size in *ni, *nj (each pointer may be NULL). x and y (ni*nj each, Fortran
 * order) may both be NULL to ask the size first; the arrays can go to
 * eg2d_set_coordinates. A file that is none of these, a block with nk > 1
 * or a truncated file is EG2D_ERR_IO naming the path and what was found.
 * Errors are reported by eg2d_last_error(NULL). */
EG2D_API int eg2d_read_plot3d(const char *path, int block, int *format, int *nblocks, int *ni, int *nj,
                              double *x, double *y);
/* The same with the caller's capacity: x and y hold `capacity` values each,
 * and a block of more than capacity nodes is EG2D_ERR_ARGUMENT, nothing
 * written. Use this one: eg2d_read_plot3d trusts the file not to grow
 * between a size query and the read. */
EG2D_API int eg2d_read_plot3d_into(const char *path, int block, int capacity, int *format, int *nblocks, int *ni,
                                   int *nj, double *x, double *y);

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

/*=====================================================================
 * 10) Curves and airfoils
 *
 * A curve (eg2d_curve) is a second opaque handle: a plane curve r(t),
 * t in [0, 1], with its arc length (the grid-generation lecture notes
 * sections 2.4-2.5, eq 2.11). Curve calls have no grid: their errors are
 * reported by eg2d_last_error(NULL) (per thread). A curve is immutable once
 * made and may be shared by threads and grids; eg2d_set_side_curve copies
 * its points. The normalized arc length of every point given out is exact
 * to about 1e-12 (1e-11 for callback curves).
 *===================================================================*/
typedef void (*eg2d_curve_fn)(void *user, double t, double *x, double *y);

/* Straight segments through n >= 2 points. */
EG2D_API int eg2d_curve_polyline(int n, const double *x, const double *y, eg2d_curve **curve);
/* The cubic spline through n >= 2 points, parameterised by chord length:
 * periodic when the last point repeats the first (a smooth closed curve),
 * natural (zero curvature) ends otherwise. */
EG2D_API int eg2d_curve_spline(int n, const double *x, const double *y, eg2d_curve **curve);
/* A user curve: fn(user, t, &x, &y) for t in [0, 1]; it must be smooth on
 * [0, 1] and is called only there, from the calling thread, during curve
 * calls (not after eg2d_curve_destroy). A non-finite point fails the call. */
EG2D_API int eg2d_curve_function(eg2d_curve_fn fn, void *user, eg2d_curve **curve);
/* NACA 4-digit section "MPTT" ("0012", "2412"), chord 1 from the leading edge
 * (0, 0) to the trailing edge (1, 0), running from the trailing edge along the
 * lower surface to the leading edge and back along the upper surface
 * (clockwise). flags: EG2D_NACA_CLOSED_TE for the sharp trailing edge
 * (thickness coefficient -0.1036: a closed curve, as an O- or C-grid needs);
 * 0 for the standard open one (-0.1015, thickness 0.0021 at x = 1 for 0012). */
EG2D_API int eg2d_curve_naca4(const char *digits, int flags, eg2d_curve **curve);
/* An airfoil from a Selig or Lednicer coordinate file, as a spline through
 * all its points oriented like eg2d_curve_naca4. A line of exactly two
 * numbers is a point; text lines before the first point are the header,
 * text after the last is ignored, blank lines are skipped; Lednicer's
 * counts are told by content. The points may run either way round and
 * start anywhere: the outline is turned and cut at its trailing edge.
 * EG2D_ERR_IO if the file cannot be read, EG2D_ERR_ARGUMENT naming the line
 * for text between points, a non-finite number, a line longer than 4096
 * bytes or one with control bytes, or Lednicer counts that disagree with
 * the surfaces. Details: docs/methods.md, "Curves and airfoils". */
EG2D_API int eg2d_curve_read_airfoil(const char *path, eg2d_curve **curve);
/* Frees a curve; NULL is a no-op. */
EG2D_API void eg2d_curve_destroy(eg2d_curve *curve);

/* Total arc length. */
EG2D_API int eg2d_curve_length(const eg2d_curve *curve, double *length);
/* The point at normalized arc length s in [0, 1]. */
EG2D_API int eg2d_curve_evaluate(const eg2d_curve *curve, double s, double *x, double *y);

/* n points of a distribution (EG2D_DIST_*) on [0, 1] into s[n],
 * s_k = s(u_k), u_k = k/(n-1); s_0 = 0, s_{n-1} = 1 (the grid-generation
 * lecture notes 2.5):
 *  UNIFORM      s = u.
 *  EXPONENTIAL  p1 = beta != 0, |beta| <= 700: s = (e^(beta u) - 1)/(e^beta - 1);
 *               beta > 0 clusters at s = 0, beta < 0 at s = 1.
 *  TANH_ONE     p1 = delta in (0, 700]: s = 1 + tanh(delta (u-1)/2)/tanh(delta/2);
 *               clusters at s = 0.
 *  TANH_TWO     p1 = b in (0, 350], p2 = c in [0, 1]: s = (tanh(b (u-c)) - A)/(B - A),
 *               A = tanh(-b c), B = tanh(b (1-c)); c = 1 clusters at s = 0,
 *               c = 0 at s = 1, c = 1/2 at both.
 *  VINOKUR      p1, p2 > 0: the first and last spacings, met to 1e-11
 *               relative (Vinokur 1983); p1 + p2 < 1 (eg2d_curve_points and
 *               eg2d_set_side_curve: in the curve's length unit, below its
 *               length), n >= 3.
 * EG2D_ERR_ARGUMENT for an unknown id, n < 2 or a parameter out of range. */
EG2D_API int eg2d_distribution(int distribution, int n, double p1, double p2, double *s);

/* The parameter p1 of a distribution that gives a wanted first spacing
 * s_1 - s_0 = first_spacing (a fraction of the length, in (0, 1)) with n
 * points, into *p1, met to 1e-12 relative (VINOKUR: 1e-11; its p1 is the
 * first spacing itself once the pair with p2, the last spacing, is checked
 * attainable). EXPONENTIAL and TANH_ONE ignore p2; TANH_TWO takes c = p2
 * and returns the smallest b that gives the spacing. EG2D_ERR_ARGUMENT,
 * with *p1 unchanged and a message that names the range of first spacings
 * reachable, when no parameter gives it (exactly 1/(n-1), a spacing the
 * function cannot reach within its parameter's bound); also for UNIFORM,
 * an unknown id, n < 2, first_spacing outside (0, 1), p2 out of range, p1
 * NULL. Reported by eg2d_last_error(NULL). Details: docs/methods.md. */
EG2D_API int eg2d_distribution_parameter(int distribution, int n, double first_spacing, double p2, double *p1);

/* n >= 2 points of a curve at the normalized arc lengths of a distribution. */
EG2D_API int eg2d_curve_points(const eg2d_curve *curve, int n, int distribution, double p1, double p2,
                               double *x, double *y);

/* Puts the side's points on a curve with a distribution (as
 * eg2d_curve_points; the side's corner checks and rules are eg2d_set_side's).
 * A curve that runs against the grid (its ends match an adjacent side's
 * corners the wrong way round; or, with no adjacent side set, it turns the
 * other way than the opposite side) fails with EG2D_ERR_BOUNDARY and a
 * message that says so, unless flags (EG2D_CURVE_*) ask:
 *  REVERSE  use the curve from its end to its start (s -> 1 - s);
 *  ORIENT   reverse it when, and only when, it runs against the grid;
 *  SLIDING  the side slides (single-block grids only, else
 *           EG2D_ERR_UNSUPPORTED): after every iteration each node of the
 *           side but the corners moves along the curve to the foot of the
 *           perpendicular from its neighbour on the first interior line,
 *           keeping its order, so grid lines meet the side at right angles.
 *           Setting the side again (eg2d_set_side, eg2d_set_boundary,
 *           eg2d_set_coordinates, a topology) ends the sliding. */
EG2D_API int eg2d_set_side_curve(eg2d_grid *grid, int side, const eg2d_curve *curve, int distribution,
                                 double p1, double p2, int flags);

/* The wall spacing for a target y+ on a body of the given chord at Reynolds
 * number Re (based on chord), from the turbulent flat-plate estimate:
 * Cf = (2 log10(Re) - 0.65)^-2.3 (Schlichting 1979, eq 21.16) and
 * height = chord y+ / (Re sqrt(Cf/2)), in the chord's length unit.
 * y+ > 0, 1e3 <= Re <= 1e9, chord > 0, else EG2D_ERR_ARGUMENT. */
EG2D_API int eg2d_first_cell_height(double yplus, double reynolds, double chord, double *height);

/* Sets the topology (EG2D_TOPO_O or EG2D_TOPO_C) and the whole boundary of
 * an airfoil grid round `section`, a curve from its trailing edge along one
 * surface to the leading edge and back along the other (eg2d_curve_naca4,
 * eg2d_curve_read_airfoil). Lengths are in chords (the leading edge is the
 * point farthest from the trailing edge's midpoint); a trailing-edge gap
 * above 1e-7 chords is open (EG2D_PARAM_AIRFOIL_TRAILING_EDGE). The section
 * is re-panelled between EG2D_PARAM_AIRFOIL_TE_SPACING and _LE_SPACING;
 * O-grid: JMIN the section, JMAX a circle EG2D_PARAM_AIRFOIL_FARFIELD
 * chords out; C-grid: JMIN the lower cut, the section and the upper cut
 * (EG2D_PARAM_AIRFOIL_WAKE_NODES), JMAX the far field, IMIN and IMAX the
 * outflow. The default patches then name the wall, the far field and the
 * outflow. EG2D_ERR_ARGUMENT, the handle unchanged, when ni leaves fewer
 * than 9 nodes on the section or the spacings do not fit it. The
 * EG2D_PARAM_AIRFOIL_* parameters set afterwards make the boundary again
 * while it is still the one this call made. The run's defaults become an
 * airfoil grid's, for each parameter the caller has not set (before or
 * after this call): EG2D_PARAM_TOLERANCE 1e-10 and, on a C-grid, the
 * multigrid cycle V(1,2) (EG2D_PARAM_MG_CYCLE 1, _PRE_SMOOTH 1,
 * _POST_SMOOTH 2). For a wall-resolved grid set the first cell with
 * eg2d_set_wall_spacing(grid, EG2D_SIDE_JMIN, h) (eg2d_first_cell_height)
 * and solve: that is the eg2d airfoil command's grid. The layout in full:
 * docs/methods.md; a walk-through: docs/airfoil.md. */
EG2D_API int eg2d_set_airfoil(eg2d_grid *grid, const eg2d_curve *section, int topology);

/*=====================================================================
 * 11) Sets of blocks (multi-block)
 *
 * A set joins single-block grids node to node along whole sides or parts
 * of sides, in either direction, and solves them as one grid: a joined
 * side's nodes are solved like interior nodes, their stencil spanning both
 * blocks, so grid lines cross the joins without kinks. The vertices (the
 * end nodes of each join: where blocks meet each other or the domain's
 * boundary) stay where the blocks' boundaries put them. Each block is a
 * grid made as usual (eg2d_create, its sides); the set refers to the grids
 * (it does not own them) and writes its solution into them, so each
 * block's results and files are the usual calls on its grid. A grid
 * destroyed while in a set leaves the set refusing to run (EG2D_ERR_STATE).
 * In this version: single-block grids (an O- or C-grid as a single block
 * joined to itself), the Laplace or Winslow system,
 * each block's control terms (sources, source arrays, parameter grid,
 * weights, EG2D_ORTHO_MIDDLECOFF_THOMAS: each on its own block; a joined
 * node takes the terms its block gives there, or where the block gives
 * none (its boundary) those one line in), block 0's solver
 * (EG2D_SOLVER_MULTIGRID over the whole set, PSOR, LSOR or NESTED) and
 * settings (tolerance, iteration limit, stall window, relaxation,
 * multigrid cycle). Walls: a block side given a height by
 * eg2d_set_wall_spacing (over its EG2D_PATCH_WALL stretches; Winslow)
 * grades every grid line of the set that leaves it, through the joins, to
 * that first cell, turned to the wall's normal; the lines keep the
 * spacing the blocks' sides give them elsewhere, so the sides that meet a
 * wall should be spaced for it (the run's events say how much the layer
 * grows). The blocks then start from TFI. A block with interior lines or
 * the variational system, and any other solver, is refused
 * (EG2D_ERR_UNSUPPORTED). A set and its grids belong to one thread at a
 * time.
 *===================================================================*/

typedef struct eg2d_blocks eg2d_blocks;

/* A new, empty set in *set (NULL on failure). */
EG2D_API int eg2d_blocks_create(eg2d_blocks **set);
/* Frees the set (NULL: nothing); its grids are not freed. */
EG2D_API void eg2d_blocks_destroy(eg2d_blocks *set);
/* The message of the set's last failed call ("" after none); set NULL:
 * the thread's (eg2d_last_error(NULL)). */
EG2D_API const char *eg2d_blocks_last_error(const eg2d_blocks *set);

/* Adds `grid` as the set's next block; *block receives its index (0, 1, ...).
 * EG2D_ERR_ARGUMENT for a NULL or a grid that is in the set already. */
EG2D_API int eg2d_blocks_add(eg2d_blocks *set, eg2d_grid *grid, int *block);

/* Names a block: the name of its zone in the files that hold a zone a
 * block (CGNS, VTK multiblock). 1 to 32 letters, digits, '_' or '-', a
 * letter first, and no other block's name; "block" and a number is a
 * block's name until it is named ("block0", "block1", ...), so a name of
 * that form is only the block's own. EG2D_ERR_ARGUMENT naming the rule or
 * the block that has the name; nothing changes then. */
EG2D_API int eg2d_blocks_set_name(eg2d_blocks *set, int block, const char *name);
/* Block `block`'s name, valid until the set is changed or destroyed; NULL
 * for a NULL set or a block the set has not. */
EG2D_API const char *eg2d_blocks_name(const eg2d_blocks *set, int block);

/* Joins nodes first_a..last_a of side side_a (EG2D_SIDE_*) of block_a to
 * nodes first_b..last_b of side side_b of block_b, node to node: node
 * first_a is node first_b, and so on. Node indices count along the side in
 * increasing i or j from 0; first > last runs the other way. Both ranges
 * span the same number of nodes, at least two; no node of a side may be in
 * two joins (two joins may share an end node). A block may be joined to
 * itself: a single block whose sides meet (an O-grid's IMIN and IMAX, a
 * C-grid's two wake halves on JMIN), so that an O- or C-grid is a block of
 * a set; the set then solves it as that topology does (the cut's nodes
 * like interior ones). EG2D_ERR_ARGUMENT naming the join otherwise (two
 * ranges of one side that share nodes included), EG2D_ERR_UNSUPPORTED for
 * a block of O- or C-grid topology (join its sides instead),
 * EG2D_ERR_STATE for a destroyed block. The coordinates are compared by
 * eg2d_blocks_check. */
EG2D_API int eg2d_blocks_join(eg2d_blocks *set, int block_a, int side_a, int first_a, int last_a, int block_b,
                              int side_b, int first_b, int last_b);

/* Holds join `join` (0 for the set's first successful eg2d_blocks_join,
 * 1 for the next, ...) with held = 1, or frees it again with 0 (the
 * default): a held join's nodes stay where the blocks' sides put them, as
 * the domain's boundary does, and its end nodes are held vertices. The
 * lines then meet it from either block as they meet a boundary (blockMesh's
 * way): a wake or a slot line the caller places, where a free join would
 * float to where the elliptic system puts it. eg2d_blocks_get_kinks leaves
 * held joins out; the writers treat them as any join. EG2D_ERR_ARGUMENT
 * for a join the set has not or a held other than 0 and 1. */
EG2D_API int eg2d_blocks_hold_join(eg2d_blocks *set, int join, int held);

/* Checks the set as eg2d_blocks_solve will: every block's boundary set
 * (EG2D_ERR_STATE), the joined nodes coincide within 1e-8 of the set's
 * extent (EG2D_ERR_BOUNDARY naming both nodes and their distance), the set
 * connected (EG2D_ERR_STATE naming a block no join reaches), one system and
 * what this version supports (above). Changes nothing. */
EG2D_API int eg2d_blocks_check(eg2d_blocks *set);

/* Checks the set (the joins on the blocks' sides as given), starts every
 * block from its TFI grid when one is not initialised or the blocks' grids
 * disagree at a join (a block initialised again alone after a solve) and
 * iterates the set to block 0's tolerance (NUMERICS.md's residual over
 * the set, on the extent of the whole set). EG2D_OK: every block holds its
 * part of the solution, and eg2d_get_run_info and eg2d_get_run_event on
 * any block describe the set's run (its solver, the levels multigrid had
 * over the set, what was solved, and a set that could not be coarsened:
 * multigrid over a set coarsens while every block has at least 4 cells
 * each way, whatever their counts). Block 0's monitor
 * (eg2d_set_monitor) is called after every iteration with the set's
 * iteration count and residual; a nonzero return stops the run with
 * EG2D_ERR_INTERRUPTED. EG2D_ERR_NOT_CONVERGED (the iteration limit or the
 * stall window) and EG2D_ERR_INTERRUPTED leave the last iterate in the
 * blocks; EG2D_ERR_DIVERGED leaves them as they were. */
EG2D_API int eg2d_blocks_solve(eg2d_blocks *set);

/* The last eg2d_blocks_solve's iterations (sweeps over the set) and
 * residual, and the number of nodes it solved for. EG2D_ERR_STATE before a
 * run. Either output may be NULL. */
EG2D_API int eg2d_blocks_get_run(const eg2d_blocks *set, int *iterations, double *residual, int *unknowns);

/* How the grid lines cross the joins, in degrees, from the blocks' current
 * coordinates: *at_joins the largest turn of a grid line at a joined
 * node (between its segments on either side of the join), *nearby the
 * largest turn of the same lines at the nodes one line into each block.
 * Lines that cross without kinks have *at_joins no larger than *nearby;
 * blocks interpolated on their own (TFI) show larger turns at the joins.
 * Vertices are left out. EG2D_ERR_STATE unless every block is initialised
 * and the set checks; 0 and 0 for a set without joined nodes. */
EG2D_API int eg2d_blocks_get_kinks(const eg2d_blocks *set, double *at_joins, double *nearby);

/* Writes the set to `path`. EG2D_FORMAT_SU2 (one zone) and
 * EG2D_FORMAT_OPENFOAM (a case directory, as eg2d_write makes) take it as
 * one mesh: the joined nodes one point, the joins interior faces, the
 * blocks' patches (eg2d_set_patch on each block; those of the same name
 * one patch, the joined edges in none) the boundary, its cells block by
 * block (OpenFOAM: a cellZone a block, named as the block; a mesh written
 * without zones removes an earlier cellZones). EG2D_FORMAT_PLOT3D
 * and _PLOT3D_ASCII (with their flags) hold a zone a block, in block
 * order, in a multi-grid file; EG2D_FORMAT_CGNS a zone a block (named as
 * the block, eg2d_blocks_set_name; CGNS readers number zones in the order
 * of their names; EG2D_ERR_ARGUMENT for a block named as a patch, the
 * base's family) with its boundary conditions less the joined edges and each join
 * as a 1-to-1 connection from both zones; EG2D_FORMAT_VTM a .vts a block
 * (NAME/NAME_0.vts, ...) that the .vtm names as the block (see eg2d_write), which ParaView and
 * VTK's vtkXMLMultiBlockDataReader read as the set. Any other format: EG2D_ERR_UNSUPPORTED
 * naming those (write each block's grid with eg2d_write). EG2D_ERR_STATE
 * unless the set checks and every block is initialised; EG2D_ERR_IO as
 * eg2d_write. All or nothing, as eg2d_write. */
EG2D_API int eg2d_blocks_write(const eg2d_blocks *set, const char *path, int format);

#ifdef __cplusplus
}
#endif
#endif /* EG2D_H */
