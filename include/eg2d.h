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
 * precise message for the last failed call on a grid.
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
 *  - eg2d_version, eg2d_status_string, eg2d_solver_name,
 *    eg2d_parameter_bounds and the list calls (eg2d_list_*,
 *    eg2d_parameter_info, eg2d_format_info, eg2d_quality_cell_field) need
 *    no handle and are safe from any thread.
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
 * Lists: what this library has, by name
 *
 * Every kind of id (solvers, parameters, formats, quality metrics, systems,
 * initialisers, orthogonality methods, topologies, point distributions) is
 * one table inside the library. These calls read it, so a program (the eg2d
 * command, a case-file reader, a GUI) needs no copy of its own. Every id
 * this library knows is listed.
 * Names are short lower-case words ("multigrid", "wall_growth", "vts"),
 * valid for the life of the process; no handle, safe from any thread.
 *===================================================================*/
#define EG2D_LIST_SOLVERS        0
#define EG2D_LIST_PARAMETERS     1
#define EG2D_LIST_FORMATS        2
#define EG2D_LIST_QUALITY        3
#define EG2D_LIST_SYSTEMS        4
#define EG2D_LIST_INITIALIZERS   5
#define EG2D_LIST_ORTHOGONALITY  6
#define EG2D_LIST_TOPOLOGIES     7
#define EG2D_LIST_DISTRIBUTIONS  8

/* The number of entries of `list`. EG2D_ERR_ARGUMENT: an unknown list, NULL. */
EG2D_API int eg2d_list_count(int list, int *count);
/* Entry `index` (0 <= index < count, in increasing id order): its id and
 * name (either pointer may be NULL). EG2D_ERR_ARGUMENT: an unknown list, an
 * index out of range. */
EG2D_API int eg2d_list_entry(int list, int index, int *id, const char **name);
/* The name of `id` in `list`, or NULL when this build has no such id. */
EG2D_API const char *eg2d_list_name(int list, int id);
/* The id named `name` in `list` (exact, case-sensitive). EG2D_ERR_ARGUMENT:
 * no such name; the message (eg2d_last_error(NULL)) lists the valid ones. */
EG2D_API int eg2d_list_find(int list, const char *name, int *id);

/* What a parameter takes (EG2D_LIST_PARAMETERS), as bits of *kind: */
#define EG2D_PARAM_KIND_REAL      0  /* any value within its bounds */
#define EG2D_PARAM_KIND_INTEGER   1  /* whole numbers only */
#define EG2D_PARAM_KIND_FLAG      2  /* 0 (off) or 1 (on); also INTEGER */
#define EG2D_PARAM_KIND_AUTOMATIC 4  /* 0 means "chosen by the library", even outside the bounds */
#define EG2D_PARAM_KIND_OPEN_LOWER 8  /* the lower bound itself is excluded */
#define EG2D_PARAM_KIND_OPEN_UPPER 16 /* the upper bound itself is excluded */
/* A parameter's kind, its unit ("1" for a pure number, "length" for the
 * grid's coordinate unit, "nodes", "iterations", "degrees"...) and a one-line
 * summary; any pointer may be NULL. Bounds and default: eg2d_parameter_bounds.
 * EG2D_ERR_ARGUMENT: no such parameter. */
EG2D_API int eg2d_parameter_info(int param, int *kind, const char **unit, const char **summary);

/* What a format writes (EG2D_LIST_FORMATS), as bits of *kind: */
#define EG2D_FORMAT_KIND_FILE      0  /* one file */
#define EG2D_FORMAT_KIND_DIRECTORY 1  /* a directory of files (OpenFOAM's polyMesh case) */
/* A format's kind and the usual suffix of its file or directory (".vts",
 * ".report.json", "_foam"); either pointer may be NULL. EG2D_ERR_ARGUMENT:
 * no such format. (Whether a plugin format can be written here, CGNS
 * without its plugin, is said by eg2d_write: EG2D_ERR_UNSUPPORTED.) */
EG2D_API int eg2d_format_info(int format, int *kind, const char **suffix);

/* The name of a quality metric's per-cell field (the field name in .vts and
 * .gmv files and of eg2d_get_cell_quality's values: "area" for both
 * EG2D_QUALITY_MIN_AREA and MAX_AREA), or NULL when the metric is a summary
 * only (the EG2D_QUALITY_ORTHO_* metrics) or unknown. */
EG2D_API const char *eg2d_quality_cell_field(int metric);

/*=====================================================================
 * Creating a grid
 *===================================================================*/
/* A grid of ni x nj nodes, ni, nj >= 3 (and ni*nj must fit the address
 * space). *grid is set to NULL on failure. Defaults: single-block topology,
 * Winslow system, multigrid solver, tolerance 1e-8, automatic relaxation. */
EG2D_API int eg2d_create(int ni, int nj, eg2d_grid **grid);

/* Frees everything; NULL is a no-op. */
EG2D_API void eg2d_destroy(eg2d_grid *grid);

/* Topologies. SINGLE: four sides, all fixed. O: periodic in i; JMIN is the
 * inner and JMAX the outer closed curve (first point == last point), columns
 * i = 0 and i = ni-1 are the same physical points (the branch cut) and are
 * solved for with the interior. C: a C-grid around a body with a wake cut
 * (ni >= 7): JMIN runs from the outflow end of the lower wake to the trailing
 * edge, around the body, and back along the upper wake to the outflow; JMAX
 * is the far field, IMIN and IMAX the two outflow lines. The wake length is
 * read from JMIN: the leading run of points i = 0..w with point i equal to
 * point ni-1-i (to 1e-8 of JMIN's size) is the cut, w the trailing edge. The
 * cut's inner nodes 0 < i < w are solved for with the interior (their
 * neighbours across the cut are the upper half's row j = 1), so the two wake
 * halves stay the same points and the grid stays smooth across the cut; the
 * outflow point i = 0 and the trailing edge i = w stay fixed.
 * Changing the topology forgets the boundary and the grid. */
#define EG2D_TOPO_SINGLE 0
#define EG2D_TOPO_O      1
#define EG2D_TOPO_C      2
EG2D_API int eg2d_set_topology(eg2d_grid *grid, int topology);
EG2D_API int eg2d_get_topology(const eg2d_grid *grid, int *topology);
/* C-grid: w, the trailing edge's index on JMIN read from the side as set
 * (above): node (i, 0) is node (ni-1-i, 0) for i = 0..w, the cut's nodes
 * a side (EG2D_PARAM_AIRFOIL_WAKE_NODES's count after eg2d_set_airfoil).
 * 0 while JMIN is not set and on the other topologies. */
EG2D_API int eg2d_get_cut(const eg2d_grid *grid, int *wake);

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
 * JMAX exist and each must be a closed curve. On a C-grid JMIN must hold the
 * wake cut (see EG2D_TOPO_C). A side set after the grid was
 * initialised moves only the boundary: the interior is kept as a warm start. */
EG2D_API int eg2d_set_side(eg2d_grid *grid, int side, const double *x, const double *y);

/* Sets the whole boundary ring from ni*nj arrays in Fortran order; only the
 * boundary nodes are read (for an O-grid: rows j = 0 and j = nj-1). */
EG2D_API int eg2d_set_boundary(eg2d_grid *grid, const double *x, const double *y);

/*=====================================================================
 * Initial grid
 *===================================================================*/
#define EG2D_INIT_TFI     0  /* linear transfinite interpolation, the grid-generation lecture notes eq 2.2 */
#define EG2D_INIT_HERMITE 1  /* TFI with Hermite blending in eta and the orthogonal
                                projector (the grid-generation lecture notes eqs 2.4-2.6): grid lines leave JMIN
                                and JMAX normal to them, with d r/d eta of length
                                alpha * |r(i,nj-1) - r(i,0)| / (nj-1), alpha =
                                EG2D_PARAM_HERMITE_SPACING; linear TFI in xi (none on an
                                O-grid). Can fold on strongly curved sides. With
                                EG2D_PARAM_HERMITE_SIDES: Hermite at the chosen sides, in
                                both directions, with a first-cell height per side (below) */

/* Fills the interior from the boundary. Needs the whole boundary. The
 * boundary is the one set: a C-grid's wake cut and sliding sides, which a
 * solve moves, start again from the points given, so a handle re-initialised
 * after a solve runs exactly as a new one. This call and eg2d_solve /
 * eg2d_iterate refuse, with EG2D_ERR_BOUNDARY and nothing changed, a
 * boundary that crosses itself (the message names the two sides' segments
 * and the point; segments that only touch at a node are not taken for a
 * crossing) and one that encloses no area. */
EG2D_API int eg2d_initialize(eg2d_grid *grid, int method);

/* A start grid of the user's own: whole ni*nj arrays, boundary included
 * (which then becomes the boundary). For an O-grid, columns 0 and ni-1 must
 * agree. */
EG2D_API int eg2d_set_coordinates(eg2d_grid *grid, const double *x, const double *y);

/* Interior lines: a grid line inside the domain held on a curve of the
 * user's, e.g. where a shock or a shear layer will sit. direction EG2D_XI
 * is the column i = index (a xi = const line, nj points, from JMIN to
 * JMAX), EG2D_ETA the row j = index (an eta = const line, ni points, from
 * IMIN to IMAX; on an O-grid a closed curve, first point == last, like
 * JMIN); index in [1, ni-2] (resp. [1, nj-2]). x, y are the line's nodes in
 * increasing index, ends included; the ends must be the boundary's nodes
 * where the line meets it (to 1e-8 of the boundary's size; checked against
 * the sides set, and again when the grid is initialised or run), and a
 * column and a row must share their crossing node (the column's point is
 * used there). A line of the same direction and index is replaced; points
 * are copied. Columns need the single-block topology (EG2D_ERR_UNSUPPORTED
 * on O- and C-grids); rows work on all three.
 * TFI and Hermite TFI (eg2d_initialize, and the TFI a first run makes)
 * pass through the lines: the lines cut the grid into sub-blocks, each
 * filled by the method as a grid of its own whose sides are pieces of the
 * boundary and of the lines (piecewise TFI, Thompson, Warsi & Mastin 1985);
 * the grid line then holds the curve's points exactly, and the spacing
 * across it is continuous, its slope not. With EG2D_PARAM_HERMITE_SIDES only
 * the grid's own sides are chosen, not the lines; the eta-only form (mask
 * 0) treats each sub-block's rows next to a line as its JMIN/JMAX.
 * EG2D_INIT_HYPERBOLIC fails with EG2D_ERR_STATE while lines are set.
 * Every solver and system (eg2d_iterate, eg2d_solve) keeps the lines'
 * nodes fixed, as an interior boundary (Dirichlet nodes: the residual
 * leaves them out, multigrid keeps them as coarse nodes). A grid given by
 * eg2d_set_coordinates gets the lines' points. EG2D_ORTHO_WALL makes no
 * marched wall layer on a grid with lines (its updates instead). Setting or
 * clearing a line restarts the run like a new start grid (iterations count
 * from 0); on an initialised grid a new line's nodes move onto it at once
 * and the rest stays: eg2d_initialize again for a TFI through it. Errors: EG2D_ERR_ARGUMENT for a bad direction, index, NULL or
 * non-finite point, EG2D_ERR_BOUNDARY for ends off the boundary, an open
 * O-grid row or crossing lines that disagree; the handle is then unchanged.
 * Lines are forgotten with the topology (eg2d_set_topology). */
EG2D_API int eg2d_set_interior_line(eg2d_grid *grid, int direction, int index, const double *x, const double *y);
/* Forgets every interior line: their nodes are unknowns again. */
EG2D_API int eg2d_clear_interior_lines(eg2d_grid *grid);

/*=====================================================================
 * System, solver and run settings
 *===================================================================*/
#define EG2D_SYSTEM_LAPLACE     0  /* Amsden-Hirt, x_xixi + x_etaeta = 0: linear */
#define EG2D_SYSTEM_WINSLOW     1  /* Winslow / Thompson-Thames-Mastin (default) */
#define EG2D_SYSTEM_VARIATIONAL 2  /* minimise V = aA + bS + cO (below) */
/* EG2D_SYSTEM_VARIATIONAL (the grid-generation lecture notes, "Variational
 * methods"; Brackbill & Saltzman 1982): the interior nodes minimise, with
 * the boundary fixed (sliding sides follow as with the other systems),
 *     V = a A/Abar + b S + c O/Abar + d W
 *     S = sum over the grid's edges of |r_q - r_p|^2            (spacing)
 *     A = sum over the cells of area^2                           (area)
 *     O = sum over the cells, over each cell's four corners, of the squared
 *         dot product (u.v)^2 of the two edges u, v leaving the corner
 *                                                                (orthogonality)
 *     W = Abar/4 times the sum over the corners of (|u|^2 + |v|^2)/(u x v)
 *                                                                (smoothness)
 * every physical edge and cell once (an O-grid's cut, a C-grid's wake).
 * Abar, the mean cell area (enclosed area / cells), makes every term a
 * length squared: the weights a, b, c, d (EG2D_PARAM_VARIATIONAL_*) are
 * dimensionless, and only their ratios matter. S's minimiser is the
 * Amsden-Hirt grid (a = c = d = 0: exactly EG2D_SYSTEM_LAPLACE's
 * equations); A pulls the cell areas together; O pulls the corners to 90
 * degrees. W is Brackbill & Saltzman's own smoothness integral (Winslow's
 * functional, int (g11 + g22)/J), at the corners as Charakhch'yan &
 * Ivanenko (1997) discretise it: it grows without bound as a corner turns
 * flat or a cell collapses, a barrier that keeps V's minimum unfolded
 * (d = 0 by default: the lecture notes' V). With
 * EG2D_PARAM_VARIATIONAL_ORTHOGONALITY_FORM 1, O is instead scale-invariant:
 *     c Abar O',  O' = sum over the corners of (u.v)^2/(u x v)^2
 * (the squared cotangent, g12^2/g; cf. the scale-invariant orthogonality
 * functional g12^2/(g11 g22) in Knupp & Steinberg 1993 and Farrashkhalvat &
 * Miles 2003). The lecture notes' dot products weigh a corner by its edges'
 * lengths to the 4th power, so O's minimum puts the turning of the grid
 * lines into small cells and shrinks them (on the swan and the dome, A and
 * O alone stop at the fold guard); the cotangents weigh every corner alike
 * and grow without bound as it turns flat. Measured (bench/RESULTS.md, the
 * course notes' domains at 65^2-257^2): a = 0, b = 1, c = 2, d = 1 with
 * the cotangent form has a smaller mean and largest angle deviation than
 * Winslow's on the valley, the almost-convex domain, the swan, the dome,
 * the antenna and the rose; on the annulus 1 <= r <= 3 (equally spaced
 * boundary points) both grids are the polar one, whose deviation,
 * 180/(ni-1) degrees at every corner, is the least any unfolded grid on
 * those boundary points can have.
 * The residual is V's gradient, scaled like the other systems':
 *   residual = max over unknown nodes of max(|dV/dx|, |dV/dy|) / (tr H / 2) / L
 * with H the 2x2 block of V's (Gauss-Newton) Hessian at the node: about the
 * largest node move a pointwise Newton step would make, as a fraction of
 * L; with a = c = d = 0 it is EG2D_SYSTEM_LAPLACE's residual.
 * Fold guard (EG2D_PARAM_FOLD_CHECK 1, the default): no step may fold a
 * cell; a step goes at most half the way to where a cell corner would turn
 * flat. Where V's minimum folds or collapses cells (possible with d = 0)
 * the grid stays unfolded short of it and the gradient stops falling: the
 * run ends with EG2D_ERR_NOT_CONVERGED when the guard shortened the last
 * steps and they lowered the residual by less than 1.25x (the message says
 * so; PSOR and NESTED run to the iteration limit). With d > 0 or
 * ORTHOGONALITY_FORM 1 (c > 0) V is infinite on a flat corner, its minimum
 * unfolded, and shortened steps are the way to it: the multigrid run then
 * goes on through them (up to 500 in a row, then EG2D_ERR_NOT_CONVERGED).
 * V need not be convex, and on the way from a saddle to its minimum the
 * residual can wander while V falls: the Newton minimiser (below) ends a
 * run with EG2D_ERR_NOT_CONVERGED for want of progress only after 40
 * Newton steps in which neither the residual fell by 1.25x nor V by 1e-9
 * of itself. S alone folds where Amsden-Hirt does: on non-convex domains (the elliptic-grid course notes'
 * swan and valley) and on the annulus 1 <= r <= 3 with n x (n/2+1) nodes.
 * The guard keeps unfolded cells unfolded but cannot unfold a start that
 * is folded (the course notes' antenna: its TFI start folds): such a start
 * (an initial grid no iteration has touched) is first solved with
 * Winslow's equations by multigrid (at most 50 cycles, to the tolerance),
 * and the run's note says so with the folded cells before and after.
 * With FOLD_CHECK 0 V is minimised without the guard (then eg2d_solve does
 * not check folds either; W, if on, still keeps cells unfolded).
 * Solvers: EG2D_SOLVER_MULTIGRID runs, where V is not S alone and the grid
 * has no C-grid wake cut, a global Newton minimiser (one iteration = one
 * Newton step; grid sequencing from the coarser grids first, the linear
 * systems solved by conjugate gradients preconditioned with a Galerkin
 * multigrid V-cycle); S alone and C-grids: FAS cycles of point Newton
 * steps. PSOR and NESTED: the same point step, over-relaxed. LSOR and AF
 * fail with EG2D_ERR_STATE (their line systems are Winslow's form).
 * Control terms need EG2D_SYSTEM_WINSLOW (EG2D_ERR_STATE).
 * Cost (bench/RESULTS.md, eg2d_bench --variational): S alone takes the
 * cycles of Laplace (2-3); a = 3, b = 1 converges in 4 Newton steps at
 * 257 x 257 on the swan (0.7 s); larger area or orthogonality weights take
 * tens to hundreds of steps there (the Newton steps are shortened near the
 * fold barrier and where V is far from convex; bench/RESULTS.md). */
EG2D_API int eg2d_set_system(eg2d_grid *grid, int system);

#define EG2D_SOLVER_PSOR      0  /* point SOR (Gauss-Seidel at omega = 1) */
#define EG2D_SOLVER_LSOR      1  /* line SOR, alternating directions; the periodic
                                    direction of an O-grid is solved as a cyclic system */
#define EG2D_SOLVER_AF        2  /* approximate factorisation, false transients */
#define EG2D_SOLVER_NESTED    3  /* coarse-to-fine, Petrilli (1989) */
#define EG2D_SOLVER_MULTIGRID 4  /* FAS multigrid (the default); see EG2D_PARAM_MG_* */
/* What one iteration is, per solver:
 *   PSOR    one lexicographic point SOR sweep (omega: EG2D_PARAM_RELAXATION).
 *   AF      one pseudo-time step: a xi and an eta line sweep (see the AF
 *           parameters below; EG2D_PARAM_RELAXATION does not apply).
 *   NESTED  one point SOR sweep of the full grid; the first iteration after a
 *           new start (initialisation, new coordinates, system, controls or
 *           solver) first converges the equations on the coarsest grid of
 *           the multigrid hierarchy (any ni, nj; see EG2D_PARAM_MG_*), adds
 *           its change, interpolated, to the next finer grid, converges
 *           there, and so on up to the full grid (Petrilli 1989's
 *           coarse-to-fine scheme). The start is kept unless this would fold
 *           cells (then the run says so: eg2d_get_run_event).
 *           EG2D_PARAM_RELAXATION applies on every level (automatic: aimed
 *           at each level's size).
 *   LSOR    one sweep of xi-lines then one of eta-lines (omega: EG2D_PARAM_RELAXATION).
 *   MULTIGRID one FAS cycle (EG2D_PARAM_MG_*); the first after an initial
 *           grid is the full-multigrid start. EG2D_PARAM_RELAXATION does not apply. */
/* Selects a solver; EG2D_ERR_UNSUPPORTED for an id this library lacks. */
EG2D_API int eg2d_set_solver(eg2d_grid *grid, int solver);
EG2D_API int eg2d_get_solver(const eg2d_grid *grid, int *solver);
/* A solver's short name ("psor"), or NULL if this library has no such solver. */
EG2D_API const char *eg2d_solver_name(int solver);

/* Relaxation factor omega in (0, 2); 0 = automatic. The automatic factor
 * (point SOR, line SOR, nested) aims at the optimum of the Laplace model
 * problem on the grid's size (the elliptic-grid course notes' for points; for lines the line-SOR
 * optimum per direction; nested at most 1.95). From a new start it rises
 * from 1 to that aim over about 9/(2 - aim) sweeps (over-relaxing straight
 * from TFI can fold a Winslow grid; Laplace point SOR and nested start at
 * the aim). A sweep that moves the grid more than 3 times as much as the
 * previous one is undone and redone with half the over-relaxation
 * (omega - 1); after the rise, a move 10 times the least since also halves
 * it. Multigrid does not use it. */
EG2D_API int eg2d_set_relaxation(eg2d_grid *grid, double omega);
/* Stop when residual <= tolerance (default 1e-8), tolerance in (0, 1). */
EG2D_API int eg2d_set_tolerance(eg2d_grid *grid, double tolerance);
/* Iteration limit of one eg2d_solve call (default 100000), >= 1. */
EG2D_API int eg2d_set_max_iterations(eg2d_grid *grid, int max_iterations);

/* Generic parameters, zstd-style: every setting has an id, bounds and a
 * default; the typed setters above are shorthands for these. Values are
 * doubles; an integer parameter takes only whole values. Ids are fixed and
 * grouped with gaps: 0-99 run, 100-199 solvers, 200-299 controls, 300-399 output,
 * 400-499 geometry and initial grid. */
#define EG2D_PARAM_RELAXATION         0  /* (0, 2), 0 = automatic           */
#define EG2D_PARAM_TOLERANCE          1  /* (0, 1),  default 1e-8           */
#define EG2D_PARAM_MAX_ITERATIONS     2  /* [1, 1e9], default 100000        */
#define EG2D_PARAM_DIVERGENCE_FACTOR  3  /* [10, 1e12], default 1e4: a residual this many times
                                            the best of the run (and above 1e-2) is divergence */
#define EG2D_PARAM_FOLD_CHECK         4  /* 1 (default): eg2d_solve returns EG2D_ERR_FOLDED when
                                            the converged grid has folded cells; 0: it does not.
                                            EG2D_SYSTEM_VARIATIONAL: 1 also guards every step
                                            against folding a cell; 0 minimises without it */
#define EG2D_PARAM_STALL_ITERATIONS   5  /* [0, 1e9], integer, 0 (default) = automatic: eg2d_solve
                                            ends EG2D_ERR_NOT_CONVERGED when this many iterations
                                            in a row bring neither the residual nor the wall
                                            control's remaining change 10% below its best, the
                                            grid restored to the best iteration and the message
                                            giving the run's events (their cause). Automatic:
                                            200 for multigrid; max(500, 2 max(ni, nj)) for the
                                            other solvers. Not for EG2D_SYSTEM_VARIATIONAL,
                                            whose minimiser has its own stop test */
#define EG2D_PARAM_MONITOR_SET_UP     6  /* 0 (default) or 1: the monitor is also called during
                                            a run's set-up (eg2d_monitor_fn), with a residual
                                            of +infinity; 0 keeps it to iterations, as a monitor
                                            written for iterations alone expects */
/* The weights a, b, c, d of EG2D_SYSTEM_VARIATIONAL (system parameters 10-19),
 * dimensionless: each in [0, 1e6], not all 0 (a setting that would make
 * them all 0 fails with EG2D_ERR_ARGUMENT: set the new weight before zeroing
 * the old). The defaults are S alone (the Amsden-Hirt grid, which folds on
 * non-convex domains: see the fold guard above). Measured on the course
 * notes' domains (tests/c/test_variational.c at 33 x 33, bench/RESULTS.md
 * to 257 x 257): a = 10, b = 1, c = 1 gives a smaller ratio of the largest
 * to the smallest cell area than Winslow's; a = 10, b = 1, c = 5 a smaller
 * mean deviation of the corner angles from 90 degrees, but it stalls at the
 * fold guard near the swan's and the dome's non-right corners; a = 0,
 * b = 1, c = 2, d = 1 with ORTHOGONALITY_FORM 1 a smaller mean and largest
 * deviation than Winslow's on all four single-block domains. On the course
 * notes' antenna (a stem joined to a half disc: two reflex corners) the
 * minimum of a = 10, b = 1, c = 1 (and of a = 3, b = 1) folds the cells at
 * the reflex corners, so the fold guard stops it; a = 10, b = 1, c = 1,
 * d = 1 with ORTHOGONALITY_FORM 1 (both barriers) converges there with an
 * area ratio below Winslow's at 65 x 65 to 257 x 257. */
#define EG2D_PARAM_VARIATIONAL_AREA          10  /* a, default 0 */
#define EG2D_PARAM_VARIATIONAL_SPACING       11  /* b, default 1 */
#define EG2D_PARAM_VARIATIONAL_ORTHOGONALITY 12  /* c, default 0 */
#define EG2D_PARAM_VARIATIONAL_SMOOTHNESS    13  /* d, default 0 */
#define EG2D_PARAM_VARIATIONAL_ORTHOGONALITY_FORM 14  /* 0 (default): O as dot products;
                                                     1: as squared cotangents (above) */
/* Multigrid (EG2D_SOLVER_MULTIGRID): FAS cycles smoothed by incomplete-LU
 * sweeps of the nine-point operator (two orderings) on a single block, by
 * alternating line Gauss-Seidel on O- and C-grids. One iteration is one
 * cycle; with PARAM_MG_FMG the first iteration after eg2d_initialize (or
 * the first run's own TFI start) is a full-multigrid start: solve on the
 * coarsest grid, interpolate, one cycle per finer level. A grid set with
 * eg2d_set_coordinates, or one already iterated, is kept as the start.
 * Coarsening works for any node count: each coarse level has ceil(m/2)
 * cells for m fine cells (a C-grid's trailing edges stay nodes), uniform in
 * its own index, down to PARAM_MG_COARSEST nodes (an O-grid keeps at least 8
 * cells round); so every size gets about log2(n) levels and the same cycle
 * count. Winslow coarsens one direction alone when the other cannot,
 * Laplace only both together; a grid too small for any coarse level runs
 * the pre + post smoothing sweeps per iteration and says so
 * (eg2d_get_run_event). A coarse level whose grid breaks down (non-finite)
 * is dropped for the rest of the run, with the levels below it, and the run
 * says so. While a control is recomputed from the grid
 * between iterations (wall orthogonality), each cycle follows one update of
 * it (see EG2D_ORTHO_WALL); a cycle that folds cells, or 20 without
 * progress, make the rest of the run one line Gauss-Seidel sweep in each
 * direction per iteration. */
#define EG2D_PARAM_MG_CYCLE         110  /* 1 = V cycle, 2 = W cycle (default)             */
#define EG2D_PARAM_MG_PRE_SMOOTH    111  /* [0, 20], default 2: smoothing sweeps (ILU in both
                                              orderings, or xi-lines then eta-lines) before the
                                              coarse correction */
#define EG2D_PARAM_MG_POST_SMOOTH   112  /* [0, 20], default 1: and after it (pre + post >= 1,
                                              else eg2d_iterate/solve fail with EG2D_ERR_STATE) */
#define EG2D_PARAM_MG_FMG           113  /* 1 (default): full-multigrid start from an initial
                                              grid; 0: V/W cycles from the grid as it is */
#define EG2D_PARAM_MG_COARSEST      114  /* [3, 1e9], default 5: a direction with this many nodes
                                              or fewer is not coarsened further */
/* Controls (200-299), see "Grid control" below. */
#define EG2D_PARAM_WALL_DECAY       200  /* [0.01, 10], default 0.3: decay rate a (per cell) of the
                                            wall control, which acts as exp(-a (m-1)) at depth m */
#define EG2D_PARAM_WALL_RELAXATION  201  /* (0, 1], default 0.1: under-relaxation of the wall
                                            control's updates between iterations */
#define EG2D_PARAM_WALL_GROWTH      202  /* [1, 1.5], default 1.15: cell-to-cell growth of the
                                            marched wall layer (EG2D_PARAM_WALL_LAYER) */
#define EG2D_PARAM_WALL_LAYER       203  /* 0, 1, 2 or 3 (default): the layer EG2D_ORTHO_WALL
                                            makes at walls with a height.
                                            0: the Sorenson-type control alone; 1: C-grids
                                            and O-grids round bodies without sharp corners
                                            whose only wall is JMIN march a layer along the
                                            normals and hold it; 2: such O- and C-grids get
                                            the hybrid layer of the hyperbolic march;
                                            3: automatic: the hybrid layer on an O- or
                                            C-grid whose only wall is JMIN where its rows
                                            grow by at most 1.25 and its first cells are
                                            within 1% and 0.5 degrees, else 0 there; the
                                            graded layer at every other wall of a single
                                            block or an O-grid (see EG2D_ORTHO_WALL; the
                                            run says which) */
#define EG2D_PARAM_SVG_QUALITY      300  /* output 300-399. EG2D_FORMAT_SVG colours cells by this
                                            EG2D_QUALITY_* metric (one with per-cell values);
                                            -1 (default): no colouring */
#define EG2D_PARAM_SPAN             301  /* (0, 1e30], default 1: the thickness (z) of the one
                                            layer of cells of the 3-D files: EG2D_FORMAT_OPENFOAM
                                            and EG2D_PLOT3D_EXTRUDED */
#define EG2D_PARAM_HERMITE_SPACING  400  /* geometry and initial grid 400-499. (0, 10], default 1:
                                            alpha of EG2D_INIT_HERMITE */
/* EG2D_INIT_HERMITE at chosen sides (the grid-generation lecture notes eqs 2.3-2.6, the
 * Boolean sum of Hermite projectors in xi and in eta). With EG2D_PARAM_HERMITE_SIDES
 * a mask of sides, sum of (1 << EG2D_SIDE_*) in [1, 15], each chosen side gets the
 * Hermite projector with the orthogonal derivative, in both directions when
 * sides of both families are chosen; a direction with no chosen side is
 * blended linearly, one with one chosen side quadratically (value at both
 * sides, derivative at the chosen one). The derivative at each node of a
 * chosen side is solved from the discrete form of eqs 2.5-2.6: the first
 * interior node of the grid line leaving the side lies on the side's normal
 * (perpendicular to the central difference r(k+1) - r(k-1)), at the
 * distance h = EG2D_PARAM_HERMITE_HEIGHT_<side> from it (the first cell's
 * height, in the boundary's length unit; 0, the default: alpha times the
 * node's line length over its cells, as EG2D_PARAM_HERMITE_SPACING's alpha
 * does for the eta-only form). So lines leave the side at 90 degrees with
 * first cells of height h, to round-off, except at the node next to a
 * corner where two chosen sides meet: one node (1, 1) cannot lie on both
 * sides' normals at both heights unless the corner is a right angle; it is
 * put where the two normals cross when that lies within [h/2, 2h] of both
 * sides, else halfway between the two wanted positions. Fold guard: the
 * derivative's reach (its blending function psi_0(s) = s (1 - s/sigma)^2
 * for s < sigma, 0 beyond; sigma = 1 is eq 2.4's) is halved while the grid
 * has folded cells, down to 3 cells; the first nodes do not move. Errors
 * (eg2d_initialize, the grid unchanged): EG2D_ERR_ARGUMENT for a side the
 * topology lacks (an O-grid has only JMIN and JMAX), EG2D_ERR_FOLDED when
 * the grid still folds at the shortest reach (first cells too large for the
 * sides' curvature or for an acute corner between two chosen sides).
 * Measured (tests/c/test_hermite_sides.c): with h half the uniform spacing
 * on every chosen side, the course notes' valley, almost-convex, swan, dome
 * and antenna (all four sides) and the annulus and the rose in a circle
 * (JMIN, JMAX) at 33 x 33 and 65 x 65 have no folded cell (the antenna's
 * linear TFI has 102 and 408; the reach is cut to 1/4-1/8 on the single
 * blocks, where eq 2.4's full reach folds up to 1822 cells), lines within
 * 4e-12 degrees of normal and heights within 1e-13 relative; with h the
 * uniform spacing the swan and the dome fold at their acute corners. A mask of 0 (the default) keeps the eta-only form
 * above unchanged. */
#define EG2D_PARAM_HERMITE_SIDES       401  /* [0, 15], default 0 */
#define EG2D_PARAM_HERMITE_HEIGHT_JMIN 402  /* h of JMIN: [0, 1e30], default 0 (alpha x the uniform spacing) */
#define EG2D_PARAM_HERMITE_HEIGHT_IMAX 403  /* the same for IMAX */
#define EG2D_PARAM_HERMITE_HEIGHT_JMAX 404  /* JMAX */
#define EG2D_PARAM_HERMITE_HEIGHT_IMIN 405  /* IMIN (= EG2D_PARAM_HERMITE_HEIGHT_JMIN + side) */
EG2D_API int eg2d_set_parameter(eg2d_grid *grid, int param, double value);
EG2D_API int eg2d_get_parameter(const eg2d_grid *grid, int param, double *value);
/* Bounds and default of a parameter, without a grid. */
EG2D_API int eg2d_parameter_bounds(int param, double *lower, double *upper, double *default_value);

/* Solver parameters (100-199). */

/* Approximate factorisation, EG2D_SOLVER_AF (Ly & Norrison (2007) eqs 5-13): false
 * transients r_tau = L(r), the Warming-Beam time rule with parameters a, b,
 * and the implicit operator factored into a xi and an eta line operator (the
 * mixed derivative is left explicit); the xi lines of an O-grid are cyclic,
 * so the branch cut moves with the interior, and a C-grid's wake cut is a xi
 * line whose nodes the eta lines run through. One iteration = one time step =
 * one xi and one eta line sweep. The pseudo-time step is one number for
 * the whole grid, dtau / D, with D the geometric mean over the unknown nodes
 * of 2(alpha+gamma) (Laplace: D = 4), so dtau is dimensionless: at dtau = 1
 * and omega = 1 the explicit part is one Jacobi step at a node of average
 * cells. (A step per node, dtau / (2(alpha+gamma)), diverges on airfoil
 * O-grids: the small wall cells then move as far in index space as the far
 * field while their lagged coefficients are far off.) The steps run
 * through a cycle of M steps spaced geometrically from dtau_min to dtau_max
 * with repeated end points (dtau_1 = dtau_2, dtau_(M-1) = dtau_M), and the
 * cycle repeats. Every default works untouched; the automatic values are
 * dtau_max = 4 (n-1)^2 / pi^2 with n = max(ni, nj) (the step that resolves
 * the smoothest mode) and the smallest M whose steps grow by at most 2x;
 * whenever the residual rises 100x above the best of the run, the automatic
 * dtau_max is divided by 4 and the cycle restarts (large steps can be
 * unstable with controls that follow the grid, such as wall orthogonality). */
#define EG2D_PARAM_AF_DTAU_MIN      100  /* (0, 1e12], default 0.5                       */
#define EG2D_PARAM_AF_DTAU_MAX      101  /* (0, 1e12], >= dtau_min; 0 = automatic (default) */
#define EG2D_PARAM_AF_STEPS         102  /* M in [4, 1000]; 0 = automatic (default)       */
#define EG2D_PARAM_AF_A             103  /* Warming-Beam a in (-1, 10], default 0         */
#define EG2D_PARAM_AF_B             104  /* Warming-Beam b in (0, 10], default 1          */
#define EG2D_PARAM_AF_RELAXATION    105  /* omega of Ly & Norrison (2007) eq 7 in (0, 4); 0 = automatic
                                            (default): omega = 2b, so omega/b = 2, the
                                            Peaceman-Rachford choice. The generic
                                            relaxation does not apply to AF. */

/* The AF cycle: steps in [dtau_min, dtau_max] over M = steps per cycle.
 * dtau_max = 0 and steps = 0 are automatic. Fails with EG2D_ERR_ARGUMENT
 * (and changes nothing) for a value out of its range or dtau_min > dtau_max.
 * Setting EG2D_PARAM_AF_DTAU_MIN/MAX one by one is checked the same way. */
EG2D_API int eg2d_set_af_cycle(eg2d_grid *grid, double dtau_min, double dtau_max, int steps);
/* The Warming-Beam time rule (Ly & Norrison (2007) Table 1): Euler implicit a = 0, b = 1
 * (default); three-point backward a = 1/2, b = 1; trapezoidal a = 0, b = 1/2.
 * The explicit rules (b = 0) are unstable here (Ly & Norrison (2007)) and rejected. */
EG2D_API int eg2d_set_af_time_rule(eg2d_grid *grid, double a, double b);

/*=====================================================================
 * Running
 *===================================================================*/
/* Called after every iteration with the iteration count of the grid (it
 * counts across calls) and the residual; a nonzero return stops the run
 * with EG2D_ERR_INTERRUPTED, keeping the iterations done. With
 * EG2D_PARAM_MONITOR_SET_UP 1 it is also called before the first iteration
 * of a run that makes its start grid or wall layer (the first run, and any
 * after a change to the boundary, the start or the controls), as the set-up
 * goes: once the start grid is there and then at every layer of a march
 * (the first call at 0.1% of a 1793x513 C-grid's run, whose first iteration
 * ends at 85% of it), with the iteration count so far and a residual of
 * +infinity (none yet); stopped there, the run returns EG2D_ERR_INTERRUPTED
 * with the handle as it was before the call. NULL removes it. */
typedef int (*eg2d_monitor_fn)(void *user, int iteration, double residual);
EG2D_API int eg2d_set_monitor(eg2d_grid *grid, eg2d_monitor_fn fn, void *user);

/* Does exactly `iterations` iterations (>= 0; one sweep, or one cycle of a
 * multilevel solver) and stores the residual after them in *residual
 * (residual may be NULL). Initialises by TFI first if the grid has only a
 * boundary. */
EG2D_API int eg2d_iterate(eg2d_grid *grid, int iterations, double *residual);

/* Iterates until residual <= tolerance: EG2D_OK, or EG2D_ERR_NOT_CONVERGED
 * after max_iterations, after EG2D_PARAM_STALL_ITERATIONS without progress
 * (or when the variational system's fold guard stops it, see
 * EG2D_SYSTEM_VARIATIONAL), EG2D_ERR_DIVERGED, EG2D_ERR_INTERRUPTED. The
 * messages of DIVERGED and of a stall end with the run's events (the
 * fallbacks that led there: eg2d_get_run_event).
 * A converged grid is checked for folded cells (EG2D_ERR_FOLDED, see
 * PARAM_FOLD_CHECK). */
EG2D_API int eg2d_solve(eg2d_grid *grid);

/*=====================================================================
 * Curves and point distributions (the grid-generation lecture notes sections 2.4-2.5)
 *===================================================================*/
/* A curve is a second opaque handle: a plane curve r(t), t in [0, 1], with
 * its arc length. Curve calls have no grid: their errors are reported by
 * eg2d_last_error(NULL) (per thread). A curve is immutable once made and may
 * be shared by threads and grids; eg2d_set_side_curve copies its points.
 *
 * Arc length (the grid-generation lecture notes eq 2.11) is tabulated by 5-point Gauss-Legendre
 * panels refined until halving a panel changes the length by less than
 * 1e-14 of it, and inverted by safeguarded Newton iteration: the normalized
 * arc length of every point given out is exact to about 1e-12 (1e-11 for
 * callback curves, whose speed |r'(t)| comes from fourth-order differences,
 * which assume r is smooth on [0, 1]). */
typedef struct eg2d_curve eg2d_curve;
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
#define EG2D_NACA_CLOSED_TE 1
EG2D_API int eg2d_curve_naca4(const char *digits, int flags, eg2d_curve **curve);
/* An airfoil from a Selig or Lednicer coordinate file, as a spline through
 * all its points oriented like eg2d_curve_naca4. A line of exactly two numbers
 * (blanks, tabs or one comma between; LF, CRLF or CR ends) is a point; text
 * lines before the first point are the header (none, a name, or several),
 * text after the last point is ignored, blank lines are skipped. Lednicer's
 * counts "NU NL" are told by content: whole numbers > 1 off the outline the
 * other points draw, which starts at its leading edge; counts that disagree
 * with the surfaces found (where x jumps back to the leading edge) are
 * refused, naming both. The points may run either way round and start
 * anywhere (at the trailing edge, as Selig's do, or at the leading edge): the
 * outline is turned and cut at its trailing edge: where the file's ends are
 * when they lie there, else at the point farthest along the chord, or at a
 * blunt base, the edge there that runs across the chord;
 * consecutive repeated points count once. EG2D_ERR_IO if the file cannot be
 * read, EG2D_ERR_ARGUMENT naming the line (quoted, non-printable bytes as
 * \xNN, cut to 60 characters) for text between points, a non-finite
 * number, a line longer than 4096 bytes or one with control bytes. */
EG2D_API int eg2d_curve_read_airfoil(const char *path, eg2d_curve **curve);
/* Frees a curve; NULL is a no-op. */
EG2D_API void eg2d_curve_destroy(eg2d_curve *curve);

/* Total arc length. */
EG2D_API int eg2d_curve_length(const eg2d_curve *curve, double *length);
/* The point at normalized arc length s in [0, 1] (the grid-generation lecture notes' x(s)). */
EG2D_API int eg2d_curve_evaluate(const eg2d_curve *curve, double s, double *x, double *y);

/* Distributions of n points on [0, 1], s_k = s(u_k), u_k = k/(n-1); s_0 = 0,
 * s_{n-1} = 1. Spacings below are s_1 - s_0 (first) and s_{n-1} - s_{n-2} (last).
 *  UNIFORM      s = u.
 *  EXPONENTIAL  p1 = beta != 0, |beta| <= 700: s = (e^(beta u) - 1)/(e^beta - 1)
 *               (the grid-generation lecture notes after eq 2.12); first spacing (e^(beta/(n-1)) - 1)/(e^beta - 1);
 *               beta > 0 clusters at s = 0, beta < 0 at s = 1.
 *  TANH_ONE     p1 = delta in (0, 700]: s = 1 + tanh(delta (u-1)/2)/tanh(delta/2)
 *               (the grid-generation lecture notes eq 2.13); clusters at s = 0; first spacing
 *               1 + tanh(delta (1/(n-1) - 1)/2)/tanh(delta/2), last 1 - s(1 - 1/(n-1)).
 *  TANH_TWO     p1 = b in (0, 350], p2 = c in [0, 1]: s = (tanh(b (u-c)) - A)/(B - A),
 *               A = tanh(-b c), B = tanh(b (1-c)) (the grid-generation lecture notes end of 2.5). The slope is
 *               largest at u = c, so points thin out there and gather toward the
 *               ends: c = 1 is TANH_ONE with delta = 2b (clusters at s = 0, the seed's
 *               attraction point 1 - c), c = 0 clusters at s = 1, c = 1/2 at both.
 *               Both tanh maps are evaluated in sinh/cosh form, without
 *               cancellation: a first spacing of 1e-12 keeps its relative accuracy.
 *  VINOKUR      p1, p2 > 0: the first and last spacings, in the curve's length
 *               units (eg2d_distribution: fractions of 1), met to 1e-11 relative:
 *               Vinokur's two-sided tanh/tan function (J. Comput. Phys. 50, 1983)
 *               with its end slopes corrected iteratively. p1 + p2 < length, n >= 3. */
#define EG2D_DIST_UNIFORM     0
#define EG2D_DIST_EXPONENTIAL 1
#define EG2D_DIST_TANH_ONE    2
#define EG2D_DIST_TANH_TWO    3
#define EG2D_DIST_VINOKUR     4
EG2D_API int eg2d_distribution(int distribution, int n, double p1, double p2, double *s);

/* The parameter p1 that gives a wanted first spacing s_1 - s_0 =
 * first_spacing (a fraction of the length, in (0, 1), as eg2d_distribution's
 * s) with n points, into *p1, such that eg2d_distribution(distribution, n,
 * *p1, p2, s) meets it to 1e-12 relative (VINOKUR: 1e-11):
 *  EXPONENTIAL  beta (p2 ignored): beta > 0 for a first spacing below the
 *               uniform 1/(n-1), beta < 0 above it; the first spacing falls
 *               strictly as beta grows, so there is one answer.
 *  TANH_ONE     delta (p2 ignored): below 1/(n-1) only (it clusters at s = 0).
 *  TANH_TWO     b for the given c = p2. The first spacing falls as b grows
 *               when c >= 1/2 and rises when c = 0; in between it can rise
 *               and then fall, and the smallest b that gives it is returned.
 *  VINOKUR      p1 is the first spacing itself: *p1 = first_spacing once the
 *               pair (first_spacing, p2 = the last spacing) is checked to be
 *               attainable.
 * The parameter is found by scanning its range (a geometric grid) for the
 * first sign change of s_1 - first_spacing and bisecting to the last bit.
 * EG2D_ERR_ARGUMENT, with *p1 unchanged and a message that names
 * first_spacing and the range of first spacings the function reaches
 * within its parameter's bound, when no parameter gives it: exactly
 * 1/(n-1) (that is UNIFORM: the parameter would be 0), one above it for
 * TANH_ONE or TANH_TWO with c >= 1/2, below it for TANH_TWO with c = 0,
 * one beyond what |beta| <= 700, delta <= 700 or b <= 350 reach;
 * also for UNIFORM (no parameter), an unknown id, n < 2, a first_spacing
 * outside (0, 1), a p2 out of its range, p1 NULL. No grid: failures are
 * reported by eg2d_last_error(NULL). */
EG2D_API int eg2d_distribution_parameter(int distribution, int n, double first_spacing, double p2, double *p1);

/* n >= 2 points of a curve at the normalized arc lengths of a distribution. */
EG2D_API int eg2d_curve_points(const eg2d_curve *curve, int n, int distribution, double p1, double p2,
                               double *x, double *y);

/* Puts the side's points on a curve with a distribution (as
 * eg2d_curve_points; the side's corner checks and rules are eg2d_set_side's).
 * Direction (the grid-generation lecture notes figure 1.13): a side whose curve runs against the grid
 * fails with EG2D_ERR_BOUNDARY and a message that says so, unless flags ask:
 *  EG2D_CURVE_REVERSE  use the curve from its end to its start (s -> 1 - s);
 *  EG2D_CURVE_ORIENT   reverse it when, and only when, it runs against the grid;
 *  EG2D_CURVE_SLIDING  the side slides (single-block grids only, else
 *                      EG2D_ERR_UNSUPPORTED): after every iteration of every
 *                      solver, each node of the side except the corners moves
 *                      along the curve to the foot of the perpendicular from its
 *                      neighbour on the first interior line (Overture's
 *                      slip-orthogonal condition), keeping its order (a node
 *                      moves at most halfway to its neighbours' positions), so
 *                      grid lines meet the side at right angles. Setting the
 *                      side again (eg2d_set_side, eg2d_set_boundary,
 *                      eg2d_set_coordinates, a topology) ends the sliding.
 * Running against the grid means: its ends match the corners of an adjacent
 * side already set the wrong way round; or, with no adjacent side set, it
 * turns the other way than the opposite side (O- and C-grids: the signed area
 * of the closed side; single block: the direction from first to last point). */
#define EG2D_CURVE_REVERSE 1
#define EG2D_CURVE_ORIENT  2
#define EG2D_CURVE_SLIDING 4
EG2D_API int eg2d_set_side_curve(eg2d_grid *grid, int side, const eg2d_curve *curve, int distribution,
                                 double p1, double p2, int flags);

/* The wall spacing for a target y+ on a body of the given chord at Reynolds
 * number Re (based on chord), from the turbulent flat-plate estimate (as
 * Construct2D offers): Cf = (2 log10(Re) - 0.65)^-2.3 (Schlichting,
 * Boundary-Layer Theory, 1979, eq 21.16) and height = chord y+ / (Re sqrt(Cf/2)).
 * y+ > 0, 1e3 <= Re <= 1e9, chord > 0. */
EG2D_API int eg2d_first_cell_height(double yplus, double reynolds, double chord, double *height);

/*=====================================================================
 * Queries
 *===================================================================*/
EG2D_API int eg2d_get_size(const eg2d_grid *grid, int *ni, int *nj);
/* Copies the ni*nj node coordinates (Fortran order). Needs an initialised grid. */
EG2D_API int eg2d_get_coordinates(const eg2d_grid *grid, double *x, double *y);
/* The residual (docs/NUMERICS.md) of the current grid. Needs an initialised grid. */
EG2D_API int eg2d_get_residual(const eg2d_grid *grid, double *residual);
/* Iterations done since the grid was last initialised or given coordinates. */
EG2D_API int eg2d_get_iterations(const eg2d_grid *grid, int *iterations);

/* What the last eg2d_iterate or eg2d_solve actually ran, so that no change of
 * strategy is silent: eg2d_get_run_info gives one figure, eg2d_get_run_event
 * the k-th change of strategy (k from 0 to EG2D_RUN_EVENTS - 1) with the
 * iteration during which it happened and a sentence that says what and why
 * ("multigrid: the 9x5 level went non-finite ...; it and the 1 coarser ones
 * are dropped, ..."; "multigrid: a cycle under the wall control added folded
 * cells ...; the run goes on with line sweeps"). Both may be called from the
 * monitor, where they describe the run so far. Before any run: solver -1, 1
 * level, no events. EG2D_ERR_ARGUMENT for an unknown `what`, an index out of
 * range or a NULL pointer; the message is cut to size - 1 bytes and always
 * terminated (size 0 with message NULL asks for nothing but the iteration;
 * size < 0 is an error). */
#define EG2D_RUN_SOLVER       0  /* the EG2D_SOLVER_* that ran */
#define EG2D_RUN_LEVELS       1  /* grid levels in use at the end (1: the fine grid alone) */
#define EG2D_RUN_LEVELS_BUILT 2  /* levels the grid's size allowed (multigrid, nested) */
#define EG2D_RUN_EVENTS       3  /* changes of strategy during the run */
EG2D_API int eg2d_get_run_info(const eg2d_grid *grid, int what, int *value);
EG2D_API int eg2d_get_run_event(const eg2d_grid *grid, int index, int *iteration, char *message, int size);

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
#define EG2D_QUALITY_SCALED_JACOBIAN 60 /* smallest over cells of the least over a cell's corners of
                                           sin(corner angle), signed by the grid's orientation: 1 for a
                                           rectangle, < 0 in a folded cell; per cell: that least (the
                                           Verdict quadrilateral scaled Jacobian, Stimpson et al. 2007) */
/* The scalar summary of a metric. An orthogonality metric of a side the
 * topology lacks (IMIN/IMAX of an O-grid) is EG2D_ERR_ARGUMENT. */
EG2D_API int eg2d_get_quality(const eg2d_grid *grid, int metric, double *value);
/* The per-cell values of a metric into values[(ni-1)*(nj-1)];
 * EG2D_ERR_ARGUMENT for a metric without per-cell values (orthogonality). */
EG2D_API int eg2d_get_cell_quality(const eg2d_grid *grid, int metric, double *values);

/* The wall layer at a side as a flow solver sees it, measured on the grid as
 * it is: over the side's stretches of type EG2D_PATCH_WALL (all of the side
 * when it has none), at every node but a stretch's two ends and its corners
 * with the nodes beside them (a trailing edge, where the wall has no
 * tangent). Heights are normal to the wall (perpendicular to its central
 * difference), in the boundary's length unit; the growth is the largest
 * ratio of a cell to the one below it along the line leaving the wall, over
 * its first 30 cells (EG2D_WALL_ROWS); the angle is the largest deviation of
 * that line's first segment from the wall normal, in degrees.
 * EG2D_WALL_NODES_NEEDED is what the last run's wall layer found it needs:
 * the smallest node count across the layer (nj for a wall at JMIN or JMAX,
 * ni at IMIN or IMAX) whose growth is within 1.2, and 0 when the layer meets
 * it (or made no graded layer); the run's event says the same. Needs an
 * initialised grid (EG2D_ERR_STATE); EG2D_ERR_ARGUMENT for a side the
 * topology lacks, an unknown `what`, a NULL value, or a side with no node to
 * measure (NODES is then 0 through no error: ask it first). */
#define EG2D_WALL_ROWS 30
#define EG2D_WALL_FIRST_MIN     0  /* smallest first-cell height */
#define EG2D_WALL_FIRST_MEDIAN  1  /* median first-cell height */
#define EG2D_WALL_FIRST_MAX     2  /* largest first-cell height */
#define EG2D_WALL_GROWTH        3  /* largest growth off the wall (EG2D_WALL_ROWS cells) */
#define EG2D_WALL_ANGLE         4  /* largest deviation from the wall normal, degrees */
#define EG2D_WALL_NODES         5  /* nodes measured */
#define EG2D_WALL_NODES_NEEDED  6  /* node count across the layer for growth 1.2; 0: met */
EG2D_API int eg2d_get_wall_layer(const eg2d_grid *grid, int side, int what, double *value);

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
 *   EG2D_PLOT3D_EXTRUDED the 3D form with two k-planes, z = 0 and z =
 *                      EG2D_PARAM_SPAN: one layer of cells, for 3-D tools
 *                      such as OpenFOAM's plot3dToFoam (without -2D; it
 *                      merges the cut's coincident points). Implies 3D.
 *                      eg2d_read_plot3d does not read it back (nk = 2).
 * e.g. eg2d_write(g, "grid.x", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI).
 *
 * EG2D_FORMAT_VTS: VTK XML StructuredGrid (ASCII, 17 significant digits),
 * points with z = 0 and every per-cell quality metric as cell data (arrays
 * "folded", "area", "skewness", "aspect_ratio", "smoothness_i", "smoothness_j").
 * EG2D_FORMAT_CGNS: one base (cell dimension 2, physical dimension 2), one
 * structured zone "eg2d" with CoordinateX, CoordinateY, the per-cell
 * metrics as a cell-centred FlowSolution "Quality", and the boundary
 * patches (eg2d_set_patch) as a ZoneBC: one BC_t per stretch, named by its
 * patch (a name's further stretches name_2, name_3, ...), of type BCWall,
 * BCFarfield, BCOutflow, BCInflow or BCSymmetryPlane on its vertex
 * PointRange, in the Family_t of its patch name (whose FamilyBC has that
 * type). A cut is a ZoneGridConnectivity of the zone with itself, listed
 * from both sides: an O-grid's i = 1 with i = ni ("cut_imin", "cut_imax",
 * transform [1, 2]); a C-grid's lower wake i = 1..w+1, j = 1 with the
 * upper wake i = ni..ni-w ("wake_lower", "wake_upper", transform [-1, -2];
 * w the trailing-edge index). It is an optional
 * part: libeg2d loads the plugin libeg2d_cgns.so (built when libcgns is
 * found, installed next to libeg2d.so; EG2D_PLUGIN_DIR overrides where it is
 * looked for) when this format is asked for, so that libeg2d itself never
 * depends on libcgns; without the plugin the call is EG2D_ERR_UNSUPPORTED.
 * EG2D_FORMAT_GMV: GMV ASCII ("gmvinput ascii", nodes with z = 0, quad
 * cells, the per-cell metrics as cell variables), Khattri's (2006) format.
 * EG2D_FORMAT_MATLAB: a Matlab/Octave script that sets xl(i,j), yl(i,j)
 * (1-based, 17 digits) and plots the grid with the boundary in red, Khattri (2006).
 * EG2D_FORMAT_SVG: a picture for a browser: grid lines, the boundary drawn
 * thicker, and cells coloured by the metric EG2D_PARAM_SVG_QUALITY when it
 * is set (blue = best to red = worst of the grid, with a legend).
 *
 * Solver-ready formats: the boundary patches (eg2d_set_patch) become the
 * boundary conditions, and a cut (O-grid, C-grid wake) is interior: its
 * duplicate nodes are merged, or connected 1-to-1 in CGNS. A C-grid needs
 * JMIN set (EG2D_ERR_STATE before); a patch left on the cut is
 * EG2D_ERR_ARGUMENT.
 * EG2D_FORMAT_SU2: SU2's native mesh, NDIME= 2: the cells as quadrilaterals
 * (type 9) with corners counter-clockwise, the points (17 digits) with the
 * cut's duplicates merged, and NMARK markers, one per patch name
 * (MARKER_TAG= name) with its boundary edges as lines (type 3): every
 * boundary edge in exactly one marker.
 * EG2D_FORMAT_OPENFOAM: `path` is an OpenFOAM case directory (made if
 * missing; its parent must exist) for a 2-D run. constant/polyMesh holds
 * the grid as one layer of hexahedra between z = 0 and z =
 * EG2D_PARAM_SPAN (points, faces, owner, neighbour, boundary; ASCII), the
 * cut merged into internal faces, a patch per patch name (type wall for
 * EG2D_PATCH_WALL, symmetry for SYMMETRY, patch for the others) and the
 * front and back faces as the patch "frontAndBack" of type empty.
 * system/controlDict, fvSchemes and fvSolution are written, minimal, where
 * the case has none (so checkMesh runs on it as it is; a case's own files
 * are kept). Each file is written all-or-nothing and the mesh files are put
 * in place together once all are complete; directories the call made are
 * removed again when it fails. Takes no flags.
 *
 * Reports, one per grid, after Construct2D's stats file:
 * EG2D_FORMAT_REPORT as text, EG2D_FORMAT_REPORT_JSON as one JSON object
 * ("ni", "nj", "topology", "cells", "points", "run", "wall",
 * "skewness_max_deg", "aspect_ratio_max", "area_min", "folded_cells"):
 * the sizes (points with a cut's duplicates merged); the last run's solver,
 * iterations (multigrid: cycles), residual and wall-clock seconds (the
 * time of the last eg2d_iterate or eg2d_solve); over the inner nodes of the
 * patches of type EG2D_PATCH_WALL (a stretch's two ends, a trailing edge
 * or a corner, excluded) the first-cell height normal to the wall (min,
 * max, mean), the largest ratio of consecutive spacings along the grid
 * lines leaving the wall within the wall layer (the rows held by a marched
 * layer, EG2D_PARAM_WALL_LAYER, else the first third of the rows) and the
 * deviation of the first line from the wall normal (max, mean, degrees);
 * then the largest skewness and aspect ratio, the smallest cell area and
 * the folded cells as EG2D_QUALITY_* defines them. "wall" is null without
 * a wall patch. */
#define EG2D_FORMAT_PLOT3D       0
#define EG2D_FORMAT_PLOT3D_ASCII 1
#define EG2D_FORMAT_VTS          2
#define EG2D_FORMAT_CGNS         3
#define EG2D_FORMAT_GMV          4
#define EG2D_FORMAT_MATLAB       5
#define EG2D_FORMAT_SVG          6
#define EG2D_FORMAT_SU2          7
#define EG2D_FORMAT_OPENFOAM     8
#define EG2D_FORMAT_REPORT       9
#define EG2D_FORMAT_REPORT_JSON 10
#define EG2D_PLOT3D_3D         0x100
#define EG2D_PLOT3D_MULTI      0x200
#define EG2D_PLOT3D_SINGLE     0x400
#define EG2D_PLOT3D_BIG_ENDIAN 0x800
#define EG2D_PLOT3D_NO_MARKERS 0x1000
#define EG2D_PLOT3D_EXTRUDED   0x2000
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
/* The same with the caller's capacity: x and y hold `capacity` values each,
 * and a block of more than capacity nodes is EG2D_ERR_ARGUMENT ("PATH: grid
 * B has NI x NJ = N nodes, more than capacity = C"), nothing written. Use
 * this one: eg2d_read_plot3d trusts the file not to grow between a size
 * query and the read, and would write past the caller's arrays if it did. */
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
 * Grid control
 *
 * Control terms turn the Winslow system into the full equation of docs/NUMERICS.md
 *   alpha (r_xixi + Phi r_xi) - 2 beta r_xieta + gamma (r_etaeta + Psi r_eta)
 *     + J^2 (P r_xi + Q r_eta) = 0
 * (plus Khattri's (2006) parameter-space terms). A grid has at most one control of
 * each kind below; different kinds add up. Controls are kept across
 * boundary changes and re-derived from the new boundary. They need the
 * Winslow system: eg2d_iterate/eg2d_solve with EG2D_SYSTEM_LAPLACE and any
 * control set fail with EG2D_ERR_STATE and change nothing. Every control
 * works with every solver and with the O-grid topology (there xi is
 * periodic: distances in xi are taken the short way round the cut).
 * Each call validates all its arguments first; a failed call changes nothing.
 *===================================================================*/
#define EG2D_XI  0  /* a xi = const line (i index), acts on P */
#define EG2D_ETA 1  /* an eta = const line (j index), acts on Q */

/* Thompson's attraction (docs/NUMERICS.md, "Source terms"), in index units:
 *   P = -sum a sign(xi - line) exp(-decay |xi - line|)  (direction EG2D_XI)
 *   Q = -sum a sign(eta - line) exp(-decay |eta - line|) (direction EG2D_ETA)
 * A positive amplitude attracts lines of that family toward `line`, a
 * negative one repels them. line in [0, ni-1] (resp. [0, nj-1]); decay >= 0;
 * amplitude finite. Ly & Norrison (2007) eq 14 is direction EG2D_ETA with amplitude mu and
 * decay kappa: (line 0, 100, 0.2) clusters eta-lines at the inner wall of an
 * O-grid. Sources accumulate until eg2d_clear_sources. The strength of a given
 * amplitude depends on the physical size of the cells (P enters times J^2). */
EG2D_API int eg2d_add_line_source(eg2d_grid *grid, int direction, double line, double amplitude, double decay);
/* Attraction of both families toward the point (xi, eta):
 *   P -= a sign(xi - xi0) exp(-decay d), Q -= a sign(eta - eta0) exp(-decay d),
 *   d = sqrt((xi - xi0)^2 + (eta - eta0)^2). */
EG2D_API int eg2d_add_point_source(eg2d_grid *grid, double xi, double eta, double amplitude, double decay);
/* Removes every line and point source. */
EG2D_API int eg2d_clear_sources(eg2d_grid *grid);

/* The user's own P and Q per node (ni*nj, Fortran order), as Petrilli's (1989)
 * p1/p2 arrays: the term J^2 (P r_xi + Q r_eta). A positive P pushes xi-lines
 * toward larger xi. Either pointer may be NULL (that one is zero); both NULL
 * removes the arrays. Values must be finite. The arrays are copied. */
EG2D_API int eg2d_set_source_arrays(eg2d_grid *grid, const double *P, const double *Q);

/* Orthogonality at the boundary.
 * MIDDLECOFF_THOMAS: Petrilli (1989) section 4: Phi from the point distribution of
 *   the eta = const boundaries, Psi from the xi = const ones (none on an
 *   O-grid), interpolated linearly inward. It makes lines leave smooth
 *   curved boundaries nearly orthogonally; on boundaries made of straight
 *   segments and corners it is zero away from the corners (Petrilli (1989) fig. 7).
 * WALL with EG2D_PARAM_WALL_LAYER = 1, on a C-grid or on an O-grid round a
 *   body without sharp corners whose only wall is JMIN with a height h: at
 *   initialisation a layer of (nj-1)/3 rows is marched along the wall
 *   normals, first cell h, each cell EG2D_PARAM_WALL_GROWTH times the last
 *   (on a C-grid's wake cut h grows with the cut's spacing, up to a fifth of
 *   the column; the outflow sides' points are placed along those sides to
 *   follow the layer), and held: the solvers work on the rows above it, with
 *   a fixed control that continues the layer's growth to the far side
 *   (Thomas & Middlecoff 1980's construction from the layer's top row and
 *   JMAX). The first cells have the height exactly and leave the wall at 90
 *   degrees; the run reports the layer (eg2d_get_run_event). Experimental:
 *   see bench/RESULTS.md for where it does not yet converge.
 * WALL with EG2D_PARAM_WALL_LAYER = 2, on an O- or C-grid whose only wall
 *   is JMIN with a height h (a sharp trailing edge included): the hybrid
 *   layer (Steger & Sorenson 1980). At initialisation the hyperbolic march
 *   (EG2D_INIT_HYPERBOLIC, first cell h, the ratio that reaches the least
 *   distance of JMAX from JMIN in nj-1 layers) makes a grid; its rows
 *   1..2(nj-1)/3 are put back along each grid line from the line's first
 *   height to the march's own last cell below the layer's top (the log of
 *   the cells a quadratic in the row, so the ratio of consecutive cells
 *   changes linearly and the spacing runs on into the rows above), and
 *   held; the rows
 *   above are solved with the controls Phi, Psi that make the marched grid
 *   an exact solution, kept within |Phi|, |Psi| <= 1 (frozen for the run),
 *   which bend it onto the JMAX set. The first cells have the height h and
 *   leave the wall along the march's lines (within 0.1 degree of normal on
 *   the benchmark's airfoils); within the layer each line grows by one
 *   ratio, about the schedule's. A march that folds goes back at least 64
 *   layers and goes on with the next larger EG2D_PARAM_MARCH_SMOOTHING of
 *   1, 2, 4 and 8; one that folds at 8 is made again from the wall with
 *   each of them; one that still cannot be made (EG2D_ERR_FOLDED or
 *   EG2D_ERR_ARGUMENT of EG2D_INIT_HYPERBOLIC)
 *   leaves the control below. JMAX keeps its line, but its nodes move
 *   along it to where the march's lines reach it (the ends stay). On a
 *   C-grid the march starts at EG2D_PARAM_MARCH_SMOOTHING 4 (the cut's
 *   lines fan out from the trailing edge; then 8, 2, 1 and the value set),
 *   the cut is held with the layer, and its first cells are h up to 0.03
 *   layer thicknesses from the trailing edge, then grow as (ds / ds_0)^3
 *   (ds the cut's spacing, ds_0 that where they start to grow) up to the
 *   largest whose cells need not shrink, which the far wake keeps: its
 *   lines are straightened and their cells take one shape, so the cells
 *   of neighbouring lines stay alike (OpenFOAM's checkMesh passes the
 *   every-other-node coarser grids). IMIN and IMAX move their nodes like
 *   JMAX. The run says which layer it made, the retries, the moves and any
 *   clipping (eg2d_get_run_event).
 * WALL with EG2D_PARAM_WALL_LAYER = 3 (the default): on an O- or C-grid
 *   whose only wall is JMIN, the hybrid layer of 2 is made and kept when
 *   the march's rows grow by at most 1.25 and its first cells are within 1%
 *   of h and 0.5 degrees of the wall's normal; otherwise (too few rows for
 *   the far field at that first cell, a first cell too coarse for the
 *   wall's curvature) the control below, and a run event says why
 *   (eg2d_get_run_event). Every other set of walls with a height, on a
 *   single block (one wall, two opposite, walls meeting at corners) or an
 *   O-grid (JMIN and JMAX, a body in a pipe), gets the graded layer: before
 *   the solve each grid line leaving a wall is re-spaced along itself,
 *   its cells growing geometrically from the wall's first cell (from both
 *   walls' between two). When that start's cells are all within 30
 *   degrees of square, it is kept: its lines are turned to the walls'
 *   normals over their first rows, the controls Phi, Psi are those that
 *   make it an exact solution of the equations, and the control below
 *   closes what is left at the wall. Otherwise the controls are each
 *   line's one-dimensional inversion (Thomas & Middlecoff 1980), one
 *   multigrid cycle on them smooths the grid (whatever the solver), and
 *   then each line is re-spaced along itself to the layer's cells near the
 *   walls, turned to the normals, and the controls are replaced by those
 *   that keep that grid for the run. A graded wall has converged when no
 *   node's first cell or angle would change by more than 0.1% of its
 *   height, whatever the tolerance. A wall covers the stretches of its side
 *   whose patches are of type EG2D_PATCH_WALL (the whole side when none
 *   is); on the rest of the side the first cell blends (a smoothstep in its
 *   log) from h to the spacing at the corner the stretch reaches, as NASA's
 *   flat-plate and bump grids do ahead of the plate. A side that is no wall
 *   and meets a wall keeps its points when its first cell there is within
 *   10% of the layer's and its cells grow by at most 1.2 (the lines beside
 *   it then take its shape); otherwise its nodes are moved along it to the
 *   layer's spacing (to the shape of the side opposite when that one is
 *   kept, as a wall's points always are), and the run says so; so does a
 *   kept side whose own points grow by more than 1.2. A folded start (the TFI start of
 *   a curved duct with clustered sides) is first solved without controls,
 *   and the run says so. The first cell is always h; where the rows are
 *   too few for it to grow by at most 1.2 within EG2D_WALL_ROWS cells, the
 *   run's event names the node count that would do, and so does
 *   eg2d_get_wall_layer (EG2D_WALL_NODES_NEEDED). The layer's figures are
 *   eg2d_get_wall_layer's. Set 0 for the control alone everywhere.
 * WALL otherwise: a Sorenson (GRAPE)-type control, updated between iterations, that
 *   makes the grid lines leave each wall side at 90 degrees with the
 *   first-cell height of eg2d_set_wall_spacing; its influence decays into the
 *   interior (EG2D_PARAM_WALL_DECAY) and its updates are under-relaxed
 *   (EG2D_PARAM_WALL_RELAXATION). It does not use the wall's curvature and
 *   works on walls with corners. At convergence the first interior node
 *   sits on the wall normal at the requested height (normal = perpendicular
 *   to the wall's central difference r(k+1) - r(k-1)), except where the
 *   control's coefficient limits bind (a sharp trailing edge with a large
 *   height: the node stops short). On a single block the end nodes next to
 *   a corner shared with another wall side are left free.
 *   The layer it makes is not graded: the control acts on the first rows
 *   (exp(-a (m-1))), so the growth from the wall is not bounded; a flow
 *   solver that needs a bounded growth should check
 *   EG2D_QUALITY_SMOOTHNESS_J, or use the marched layer above.
 *   On a C-grid the wake cut of JMIN counts as wall too: the nodes next to
 *   it on both sides get the height. There the cut node next to the
 *   trailing edge can keep sliding along the cut at larger heights, and
 *   eg2d_solve then returns EG2D_ERR_NOT_CONVERGED with a grid whose first
 *   cells already have the height.
 *   While it is active, the automatic relaxation (EG2D_PARAM_RELAXATION 0)
 *   is 1: over-relaxing its strong terms diverges at sharp trailing edges.
 *   With EG2D_SOLVER_MULTIGRID each cycle follows one update; a cycle that
 *   folds cells, or 20 cycles in which neither the residual nor the
 *   control's remaining change halves, hand the run over to line sweeps,
 *   and the run says so (eg2d_get_run_event).
 *   A run converges only when the control is settled too (its remaining
 *   change within the tolerance). The control starts over from zero after
 *   any change of the start grid (eg2d_initialize, eg2d_set_coordinates),
 *   the boundary, the topology or the controls: its coefficients belong to
 *   the grid they were found on.
 *   Measured cycle counts, layer growth and limits: bench/RESULTS.md,
 *   "The wall control in numbers".
 * NONE removes either. */
#define EG2D_ORTHO_NONE              0
#define EG2D_ORTHO_MIDDLECOFF_THOMAS 1
#define EG2D_ORTHO_WALL              2
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

/* Adaptive control from a parameter-space grid (Khattri (2006)): s, t are an ni*nj
 * grid on the unit square (Fortran order), unfolded: s_xi t_eta - s_eta t_xi
 * of one sign at every unknown node (O-grid: s may jump by a constant at
 * the cut, e.g. run from 0 to 1 round the grid). The physical grid inherits
 * its distribution: where the parameter grid is dense, so is the result.
 * Both NULL removes it. Arrays are copied. */
EG2D_API int eg2d_set_parameter_grid(eg2d_grid *grid, const double *s, const double *t);

/* Khattri's (2006) clustering maps of [0, 1] onto itself, sampled at n >= 2
 * uniform points u_k = k/(n-1) into u_out[k]; increasing, u(0) = 0, u(1) = 1,
 * with slope strength/(e^strength - 1) at the attracting points:
 *   LINE       dense at a in (0, 1)                      (Cluster_X_Near, strength 3)
 *   TWO_LINES  dense at a and b, 0 < a < b < 1           (Cluster_Two_Lines, 3)
 *   BOUNDARIES dense at 0 and 1, split at a in (0, 1)    (Bound_Clust, 4)
 * strength > 0 (0 = the seed's value above); b is ignored unless TWO_LINES.
 * No grid: failures are reported by eg2d_last_error(NULL). */
#define EG2D_CLUSTER_LINE       0
#define EG2D_CLUSTER_TWO_LINES  1
#define EG2D_CLUSTER_BOUNDARIES 2
EG2D_API int eg2d_clustering_map(int kind, double a, double b, double strength, int n, double *u_out);
/* The tensor-product parameter grid s(i, j) = u[i], t(i, j) = v[j] (ni*nj
 * arrays s, t) from two increasing distributions u (ni values), v (nj). */
EG2D_API int eg2d_tensor_parameter_grid(int ni, int nj, const double *u, const double *v, double *s, double *t);

/* Weight-function adaptivity (the grid-generation lecture notes): w per node (ni*nj, Fortran order,
 * finite and > 0); larger w = denser grid. Along each index direction the
 * spacing follows 1/w: Phi = 2 (w_e - w_w)/(w_w + 2 w_c + w_e), Psi likewise,
 * which a one-dimensional grid satisfies exactly as w ds = const with
 * midpoint weights. For solution-adaptive regridding, set the new weights
 * and solve again from the current grid. NULL removes it. */
EG2D_API int eg2d_set_weight(eg2d_grid *grid, const double *w);

/* The control terms in force, per node (ni*nj, Fortran order), as the P
 * and Q of Thompson, Thames & Mastin (1974): every control above summed and
 * written as J^2 (P r_xi + Q r_eta), that is P = C_xi / J^2 and
 * Q = C_eta / J^2 with C_xi, C_eta the coefficients of r_xi, r_eta in
 * docs/NUMERICS.md, evaluated on the current grid (central differences,
 * index units). Sources and source arrays give their own P, Q; Phi and Psi
 * (MIDDLECOFF_THOMAS, the weight, a wall layer's rows) give alpha Phi / J^2
 * and gamma Psi / J^2; the parameter grid's terms likewise. A dynamic
 * control (EG2D_ORTHO_WALL's Sorenson-type one) gives its current state:
 * after a run, its last update. Only nodes the equation is solved at have
 * values: the boundary, rows held by a wall layer and nodes where J = 0 are
 * 0 (an O-grid's column ni-1 and a C-grid's upper wake repeat the nodes they
 * coincide with). No control, or the Laplace system: all 0. Needs an
 * initialised grid (EG2D_ERR_STATE); either pointer may be NULL, not both. */
EG2D_API int eg2d_get_controls(const eg2d_grid *grid, double *P, double *Q);

/*=====================================================================
 * Hyperbolic marching
 *===================================================================*/
/* eg2d_initialize(grid, EG2D_INIT_HYPERBOLIC) marches the grid out from
 * side JMIN, layer by layer (Steger & Chaussee 1980, Chan & Steger 1992;
 * docs/hyperbolic.md): each new layer is orthogonal to the one before and
 * its cells have the areas the marching schedule asks for, solved
 * implicitly per layer (a 2x2 block-tridiagonal system, cyclic on O-grids).
 * Only JMIN is needed: the march writes every other node, the outer side
 * JMAX and the open sides IMIN/IMAX included, and the grid it makes becomes
 * the boundary (as with eg2d_set_coordinates: sides set before are
 * replaced, sliding sides are dropped). The direction: an O-grid marches
 * outward from its closed curve, a C-grid away from its body (JMIN as for
 * EG2D_TOPO_C), a single block to the left of JMIN as it runs (JMIN along
 * +x marches towards +y), whichever way the curves run.
 * Schedule: layer k = 1..nj-1 has height h_k = h_1 r^(k-1), where r in
 * [1/G, G] makes the heights add up to the distance D. The first interior
 * node lies h_1 from JMIN along the normal (area smoothing moves it
 * slightly where the curve turns sharply). Each layer's mean step along
 * its normals is its height, so the outer side lies about D from JMIN (the
 * measured figures: bench/RESULTS.md, docs/hyperbolic.md). Sharp convex edges (a trailing edge) march along the bisector
 * of their angle; dissipation, scaled by Chan & Steger's sensors, and area
 * smoothing keep concave corners and the far field from folding. At a
 * convex corner of 45 to 135 degrees between straighter neighbours (a
 * blunt base's) the explicit dissipation moves the node by at most a tenth
 * of its step, so that the corner's cells do not fold at a large
 * EG2D_PARAM_MARCH_SMOOTHING. Errors:
 * EG2D_ERR_FOLDED if a layer folds (the message names the layer and its
 * first folded cell; the handle keeps what it had); EG2D_ERR_STATE if JMIN is
 * not set; EG2D_ERR_ARGUMENT if h_1 cannot reach D with growth <= G in
 * nj-1 layers (the message gives the reachable distance); EG2D_ERR_DIVERGED
 * if a layer system is singular (JMIN with repeated points). The parameters
 * (lengths in the unit of the coordinates; docs/hyperbolic.md): */
#define EG2D_INIT_HYPERBOLIC 2
#define EG2D_PARAM_MARCH_DISTANCE      410  /* D: [0, 1e30], 0 (default) = 10 x the diagonal of
                                               JMIN's bounding box */
#define EG2D_PARAM_MARCH_FIRST_HEIGHT  411  /* h_1: [0, 1e30], 0 (default) = the h_1 whose constant
                                               ratio r = 1 + (G-1)/2 reaches D */
#define EG2D_PARAM_MARCH_GROWTH        412  /* G: [1, 3], default 1.2 */
#define EG2D_PARAM_MARCH_SMOOTHING     413  /* eps_c: [0, 20], default 0.5: strength of the explicit
                                               (and twice it, implicit) dissipation */
#define EG2D_PARAM_MARCH_AREA_SMOOTHING 414 /* [0, 1000], default 20: area-smoothing passes per layer.
                                               More passes (with less dissipation) give more
                                               orthogonal cells on airfoil O-grids, but at concave
                                               corners marched with first cells near the node
                                               spacing they can fold (docs/hyperbolic.md) */
#define EG2D_PARAM_MARCH_END_IMIN      415  /* EG2D_MARCH_END_* of the i = 0 end (single block,    */
#define EG2D_PARAM_MARCH_END_IMAX      416  /* C-grid) and of the i = ni-1 end; default FREE       */
/* Open ends of a single-block or C-grid march (O-grids have none): */
#define EG2D_MARCH_END_FREE      0  /* the end node steps along its own normal */
#define EG2D_MARCH_END_CONSTANT_X 1 /* x stays that of JMIN's end, y follows the neighbour (a
                                       symmetry plane x = const) */
#define EG2D_MARCH_END_CONSTANT_Y 2 /* the same with y = const */
#define EG2D_MARCH_END_SPLAY     3  /* the end cell widens in proportion to the layer height,
                                       so the end line splays outward */

/* Airfoil grids (eg2d_set_airfoil), as Construct2D's front end makes them. */
#define EG2D_PARAM_AIRFOIL_FARFIELD      420  /* [2, 1e6] chords, default 100: the far field's
                                                 least distance from the section (a C-grid's
                                                 outflow this far behind the trailing edge) */
#define EG2D_PARAM_AIRFOIL_LE_SPACING    421  /* (0, 0.1] chords, 0 (default): a tenth of the
                                                 section's mean spacing: the spacing along the
                                                 section at its leading edge */
#define EG2D_PARAM_AIRFOIL_TE_SPACING    422  /* (0, 0.1] chords, 0 (default): a quarter of the
                                                 mean spacing: at the trailing edge, the spacing
                                                 along a blunt base and the C-grid cut's first
                                                 (with a blunt base: the base's own, the base
                                                 split into equal cells near this) */
#define EG2D_PARAM_AIRFOIL_WAKE_NODES    423  /* C-grid: cut nodes a side, the trailing edge's
                                                 index i; 0 (default): about 0.21 (ni-1), a
                                                 multiple of the largest power of two up to 64
                                                 that divides (ni-1)/2 and keeps it within
                                                 0.02 (ni-1) of that (385: 80, 1793: 384);
                                                 eg2d_get_cut gives the count in use */
#define EG2D_PARAM_AIRFOIL_TRAILING_EDGE 424  /* an open trailing edge: EG2D_AIRFOIL_TE_BLUNT
                                                 (default) or EG2D_AIRFOIL_TE_SHARPEN */
#define EG2D_AIRFOIL_TE_BLUNT   0  /* kept as a blunt base: straight, part of the wall */
#define EG2D_AIRFOIL_TE_SHARPEN 1  /* each surface moved towards the base's midpoint in
                                      proportion to its distance along the chord */
#define EG2D_PARAM_AIRFOIL_O_TE_BASE     425  /* O-grid: [0, 0.01] chords, default 5e-5: a sharp
                                                 trailing edge (or one sharpened) is cut back
                                                 along the chord, at most 0.005 chords, to a
                                                 straight base this thick, part of the wall, so
                                                 that the edge is two corners of about 90 degrees
                                                 (a single node leaves two cells of about 172);
                                                 0 keeps the sharp edge a single node. C-grids
                                                 keep a sharp edge on their cut */
/* Sets the topology (EG2D_TOPO_O or EG2D_TOPO_C) and the whole boundary of
 * an airfoil grid round `section`, a curve from its trailing edge along one
 * surface to the leading edge and back along the other (eg2d_curve_naca4,
 * eg2d_curve_read_airfoil). The leading edge is the point farthest from the
 * trailing edge's midpoint; the chord runs from it to that midpoint, and
 * lengths are in chords. A trailing-edge gap above 1e-7 chords is open.
 *   The section: re-panelled by Vinokur's distribution on each surface from
 *   EG2D_PARAM_AIRFOIL_TE_SPACING to EG2D_PARAM_AIRFOIL_LE_SPACING; an open
 *   trailing edge kept as a straight base with nodes about that spacing
 *   apart, the section's first cells at its corners the base's spacing
 *   (EG2D_AIRFOIL_TE_BLUNT) or closed (EG2D_AIRFOIL_TE_SHARPEN).
 *   O-grid: JMIN the section (and base; a sharp or sharpened trailing edge
 *   cut back to a base EG2D_PARAM_AIRFOIL_O_TE_BASE thick, unless that is
 *   0), JMAX the circle of radius R + 1/2
 *   about the mid-chord (R = EG2D_PARAM_AIRFOIL_FARFIELD), uniform in angle from
 *   the trailing edge's direction.
 *   C-grid: JMIN the lower cut (EG2D_PARAM_AIRFOIL_WAKE_NODES nodes from the
 *   outflow), the section (a blunt base's lower half first, from its
 *   midpoint), the upper cut; the cut runs along the chord line from the
 *   trailing edge, or from a blunt base's midpoint along the base's normal
 *   (the two agree on a symmetric section; a right angle on both sides of
 *   the cut), its cells growing geometrically from the trailing-edge
 *   spacing (a base's: the section's and the cut's first cells are the
 *   base's) to the outflow, R = EG2D_PARAM_AIRFOIL_FARFIELD chords
 *   downstream; the far field and outflow below are laid out along the
 *   cut's direction. JMAX: the lines R + 1 chords above and below the cut
 *   (at the cut nodes' stations) and the half circle of that radius about
 *   the trailing edge between, its nodes by Vinokur's distribution from the
 *   trailing-edge spacing at both ends; IMIN and IMAX: the outflow lines,
 *   uniform.
 * The default patches (eg2d_set_patch) then name the wall (the section and
 * base), the far field and the outflow. EG2D_ERR_ARGUMENT when ni leaves
 * fewer than 9 nodes on the section or the spacings do not fit it; the
 * handle is then unchanged. The EG2D_PARAM_AIRFOIL_* parameters may be set
 * before or after: set after, they make the boundary again (the same as set
 * before; a value it cannot take is refused with the handle unchanged)
 * while the boundary is still the one eg2d_set_airfoil made, and no longer
 * once a side has been set otherwise. For a wall-resolved grid set the
 * first cell with eg2d_set_wall_spacing(grid, EG2D_SIDE_JMIN, h)
 * (eg2d_first_cell_height) and solve: the default wall layer is the hybrid
 * one (the wall control, EG2D_ORTHO_WALL, comes with the height). */
EG2D_API int eg2d_set_airfoil(eg2d_grid *grid, const eg2d_curve *section, int topology);

/*=====================================================================
 * Boundary patches
 *
 * Each side, or a stretch of one, carries a type and a name, which the
 * solver-ready formats write as its boundary condition: an SU2 marker
 * (EG2D_FORMAT_SU2), an OpenFOAM patch (EG2D_FORMAT_OPENFOAM) and a CGNS
 * BC_t (EG2D_FORMAT_CGNS). Where the user sets none, the topology's
 * defaults hold:
 *   single block  each side one patch, "jmin", "imax", "jmax", "imin", all
 *                 EG2D_PATCH_WALL (a closed box until told otherwise: set
 *                 the inflow, outflow or far field yourself);
 *   O-grid        JMIN "wall" (WALL), JMAX "farfield" (FARFIELD); the
 *                 periodic i-cut is internal: its faces are merged (SU2,
 *                 OpenFOAM) or a 1-to-1 connection (CGNS);
 *   C-grid        JMIN's body stretch, from trailing edge to trailing edge,
 *                 "wall" (WALL); JMIN's two wake stretches are the cut,
 *                 merged or connected 1-to-1 like the O-grid's; JMAX
 *                 "farfield" (FARFIELD); IMIN and IMAX "outflow" (OUTFLOW).
 * A patch the user sets replaces the default on its stretch; the rest of
 * the side keeps the default. Patches are kept across boundary changes and
 * forgotten with the topology (eg2d_set_topology).
 *===================================================================*/
#define EG2D_PATCH_WALL     0  /* a no-slip (or slip) solid wall: OpenFOAM wall, CGNS BCWall */
#define EG2D_PATCH_FARFIELD 1  /* free stream: OpenFOAM patch, CGNS BCFarfield */
#define EG2D_PATCH_OUTFLOW  2  /* OpenFOAM patch, CGNS BCOutflow */
#define EG2D_PATCH_INFLOW   3  /* OpenFOAM patch, CGNS BCInflow */
#define EG2D_PATCH_SYMMETRY 4  /* OpenFOAM symmetry, CGNS BCSymmetryPlane */
#define EG2D_PATCH_CUT      5  /* reported only (eg2d_get_patch): the O-grid's periodic cut,
                                  the C-grid's wake; never set */
/* Gives nodes first..last (0 <= first < last <= side length - 1, in
 * increasing index along `side`) of a side, i.e. the last - first edges
 * between them, a type (EG2D_PATCH_WALL..SYMMETRY) and a name: 1 to 32
 * characters, a letter first, then letters, digits, '_' or '-' (every
 * target format takes it as is; "frontAndBack" is the OpenFOAM writer's).
 * Two stretches may share a name (one marker) only with the same type.
 * A patch of exactly the range of an existing one replaces it.
 * EG2D_ERR_ARGUMENT for a side the topology lacks (an O-grid has only JMIN
 * and JMAX), a range outside the side or overlapping another patch, a bad
 * type or name, or, on a C-grid whose JMIN is set, a stretch of the wake
 * cut. A patch set on a C-grid before JMIN is checked against the cut when
 * the patches are used (eg2d_get_patch, eg2d_write): a patch on the cut is
 * EG2D_ERR_ARGUMENT there. */
EG2D_API int eg2d_set_patch(eg2d_grid *grid, int side, int first, int last, int type, const char *name);
/* Forgets the user's patches: the defaults hold again. */
EG2D_API int eg2d_clear_patches(eg2d_grid *grid);
/* The boundary as the writers see it: the user's patches, the defaults on
 * the rest and the cut (type EG2D_PATCH_CUT; an O-grid's as side IMIN,
 * nodes 0..nj-1), side by side in the order JMIN, IMAX, JMAX, IMIN and by
 * increasing index: every boundary edge lies in exactly one of them.
 * *count is their number; eg2d_get_patch gives the index-th (0-based) with
 * its name into name[size] (NUL-terminated, cut short to fit; name may be
 * NULL with size 0). Any output pointer may be NULL. EG2D_ERR_STATE on a
 * C-grid before JMIN is set (the cut is read from it); EG2D_ERR_ARGUMENT
 * for an index out of range. */
EG2D_API int eg2d_get_patch_count(const eg2d_grid *grid, int *count);
EG2D_API int eg2d_get_patch(const eg2d_grid *grid, int index, int *side, int *first, int *last, int *type,
                            char *name, int size);

#ifdef __cplusplus
}
#endif
#endif /* EG2D_H */
