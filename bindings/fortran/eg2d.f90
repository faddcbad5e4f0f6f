! eg2d.f90 -- module eg2d, the Fortran interface of libeg2d.
!
! Two layers in one module (`use eg2d`):
!  1. the C API itself (eg2d_capi.inc, generated from eg2d.h by
!     tools/gen_bindings.py): bind(C) interfaces and the constants under the
!     C names, for line-by-line translations of C;
!  2. Fortran-friendly wrappers under their own names: the type eg2d_grid_t
!     (owns a handle, frees it in its final procedure) whose procedures take
!     x(:,:) arrays with shape checks and an optional `status`. Without
!     `status` a failing call stops the program with eg2d_last_error's
!     message; with it, the status is returned and g%last_error() has the text.
!
!     type(eg2d_grid_t) :: g
!     call g%create(65, 65)
!     call g%set_side(EG2D_SIDE_JMIN, xb, yb)      ... the four sides
!     call g%solve(status=rc)
!     if (rc /= EG2D_OK) print *, g%last_error()
!     call g%get_coordinates(x, y)                 ! x(ni,nj), y(ni,nj)
!
! Arrays are real(c_double) (= real(kind(1d0)) with gfortran); node (i, j) of
! the C manual is x(i+1, j+1) here.
module eg2d
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_funptr, c_char, c_size_t, &
       c_null_ptr, c_null_funptr, c_null_char, c_associated, c_f_pointer, c_funloc
  implicit none
  private

  include 'eg2d_capi.inc'

  ! C's strlen, to turn the library's const char * into Fortran strings (private).
  interface
    function c_strlen(s) bind(C, name='strlen') result(n)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: s
      integer(c_size_t) :: n
    end function c_strlen
  end interface

  ! The real kind of every coordinate array.
  integer, parameter, public :: eg2d_dp = c_double

  ! A grid: the handle of eg2d_create and the text of its last failure.
  ! Do not copy a created grid by assignment (both copies would own the handle).
  type, public :: eg2d_grid_t
    type(c_ptr), private :: handle = c_null_ptr
    character(:), allocatable, private :: message
  contains
    procedure :: create => grid_create
    procedure :: destroy => grid_destroy
    procedure :: c_handle => grid_c_handle
    procedure :: last_error => grid_last_error
    procedure :: set_topology => grid_set_topology
    procedure :: get_topology => grid_get_topology
    procedure :: get_cut => grid_get_cut
    procedure :: set_side => grid_set_side
    procedure :: set_boundary => grid_set_boundary
    procedure :: set_interior_line => grid_set_interior_line
    procedure :: clear_interior_lines => grid_clear_interior_lines
    procedure :: initialize => grid_initialize
    procedure :: set_coordinates => grid_set_coordinates
    procedure :: set_system => grid_set_system
    procedure :: set_solver => grid_set_solver
    procedure :: get_solver => grid_get_solver
    procedure :: set_relaxation => grid_set_relaxation
    procedure :: set_tolerance => grid_set_tolerance
    procedure :: set_max_iterations => grid_set_max_iterations
    procedure :: set_parameter => grid_set_parameter
    procedure :: get_parameter => grid_get_parameter
    procedure :: set_af_cycle => grid_set_af_cycle
    procedure :: set_af_time_rule => grid_set_af_time_rule
    procedure :: set_monitor => grid_set_monitor
    procedure :: iterate => grid_iterate
    procedure :: solve => grid_solve
    procedure :: get_size => grid_get_size
    procedure :: get_coordinates => grid_get_coordinates
    procedure :: get_residual => grid_get_residual
    procedure :: get_iterations => grid_get_iterations
    procedure :: get_run_info => grid_get_run_info
    procedure :: get_run_event => grid_get_run_event
    procedure :: get_quality => grid_get_quality
    procedure :: get_wall_layer => grid_get_wall_layer
    procedure :: get_cell_quality => grid_get_cell_quality
    procedure :: get_controls => grid_get_controls
    procedure :: write => grid_write
    procedure :: set_side_from_file => grid_set_side_from_file
    procedure :: set_side_curve => grid_set_side_curve
    procedure :: set_airfoil => grid_set_airfoil
    procedure :: add_line_source => grid_add_line_source
    procedure :: add_point_source => grid_add_point_source
    procedure :: clear_sources => grid_clear_sources
    procedure :: set_source_arrays => grid_set_source_arrays
    procedure :: set_orthogonality => grid_set_orthogonality
    procedure :: set_wall_spacing => grid_set_wall_spacing
    procedure :: set_parameter_grid => grid_set_parameter_grid
    procedure :: set_weight => grid_set_weight
    procedure :: set_patch => grid_set_patch
    procedure :: clear_patches => grid_clear_patches
    procedure :: get_patch_count => grid_get_patch_count
    procedure :: get_patch => grid_get_patch
    final :: grid_final
  end type eg2d_grid_t

  ! A curve (eg2d_curve_*): made by one of polyline, spline, from_function,
  ! naca4, read_airfoil (each frees a curve held before); freed by destroy or
  ! its final procedure. Do not copy a made curve by assignment.
  type, public :: eg2d_curve_t
    type(c_ptr), private :: handle = c_null_ptr
    character(:), allocatable, private :: message
  contains
    procedure :: polyline => curve_polyline
    procedure :: spline => curve_spline
    procedure :: from_function => curve_from_function
    procedure :: naca4 => curve_naca4
    procedure :: read_airfoil => curve_read_airfoil
    procedure :: destroy => curve_destroy
    procedure :: c_handle => curve_c_handle
    procedure :: last_error => curve_last_error
    procedure :: get_length => curve_get_length
    procedure :: evaluate => curve_evaluate
    procedure :: points => curve_points
    final :: curve_final
  end type eg2d_curve_t

  public :: eg2d_c_string, eg2d_status_message, eg2d_solver_short_name, eg2d_version_string
  public :: eg2d_get_parameter_bounds, eg2d_live_grids
  public :: eg2d_read_plot3d_grid, eg2d_read_point_file
  public :: eg2d_get_distribution, eg2d_get_distribution_parameter, eg2d_get_first_cell_height
  public :: eg2d_get_clustering_map, eg2d_get_tensor_parameter_grid

  ! Grids created through eg2d_grid_t and not yet freed (to check finalisation).
  integer, save :: live_grids = 0

contains

  ! ---------------------------------------------------------------- strings
  ! A Fortran copy of a NUL-terminated C string; '' for NULL.
  function eg2d_c_string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer :: n, i
    if (.not. c_associated(p)) then
      s = ''
      return
    end if
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    allocate (character(n) :: s)
    do i = 1, n
      s(i:i) = chars(i)
    end do
  end function eg2d_c_string

  ! The English name of a status ("EG2D_ERR_BOUNDARY: inconsistent boundary").
  function eg2d_status_message(status) result(s)
    integer, intent(in) :: status
    character(:), allocatable :: s
    s = eg2d_c_string(eg2d_status_string(int(status, c_int)))
  end function eg2d_status_message

  ! A solver's short name ("psor"), or '' if this library has no such solver.
  function eg2d_solver_short_name(solver) result(s)
    integer, intent(in) :: solver
    character(:), allocatable :: s
    s = eg2d_c_string(eg2d_solver_name(int(solver, c_int)))
  end function eg2d_solver_short_name

  ! The run-time library version as "major.minor.patch".
  function eg2d_version_string() result(s)
    character(:), allocatable :: s
    integer(c_int) :: major, minor, patch
    character(32) :: buf
    call eg2d_version(major, minor, patch)
    write (buf, '(i0,".",i0,".",i0)') major, minor, patch
    s = trim(buf)
  end function eg2d_version_string

  ! Bounds and default of a generic parameter (EG2D_PARAM_*), without a grid.
  subroutine eg2d_get_parameter_bounds(param, lower, upper, default_value, status)
    integer, intent(in) :: param
    real(c_double), intent(out) :: lower, upper, default_value
    integer, intent(out), optional :: status
    integer(c_int) :: rc
    rc = eg2d_parameter_bounds(int(param, c_int), lower, upper, default_value)
    call settle(rc, eg2d_c_string(eg2d_last_error(c_null_ptr)), status)
  end subroutine eg2d_get_parameter_bounds

  integer function eg2d_live_grids()
    eg2d_live_grids = live_grids
  end function eg2d_live_grids

  ! ---------------------------------------------------------------- errors
  ! Hands rc to the caller's status, or stops the program with the message
  ! (which starts with the function's name: "eg2d_solve: ..." from the library,
  ! "set_side: ..." from a Fortran shape check).
  subroutine settle(rc, message, status)
    integer(c_int), intent(in) :: rc
    character(*), intent(in) :: message
    integer, intent(out), optional :: status
    if (present(status)) then
      status = int(rc)
    else if (rc /= EG2D_OK) then
      error stop 'eg2d: ' // message
    end if
  end subroutine settle

  ! After a C call on the grid: records the library's message on failure.
  subroutine finish(self, rc, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer(c_int), intent(in) :: rc
    integer, intent(out), optional :: status
    if (rc /= EG2D_OK) self%message = eg2d_c_string(eg2d_last_error(self%handle))
    if (.not. allocated(self%message)) self%message = ''
    call settle(rc, self%message, status)
  end subroutine finish

  ! A failure found by the Fortran layer (a shape check) before calling C.
  subroutine fail(self, rc, where, message, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer(c_int), intent(in) :: rc
    character(*), intent(in) :: where, message
    integer, intent(out), optional :: status
    self%message = where // ': ' // message
    call settle(rc, self%message, status)
  end subroutine fail

  ! Checks that x and y have the shape (m, n); false after recording a failure.
  logical function shape_ok(self, where, x, y, m, n, status)
    class(eg2d_grid_t), intent(inout) :: self
    character(*), intent(in) :: where
    real(c_double), intent(in) :: x(:, :), y(:, :)
    integer, intent(in) :: m, n
    integer, intent(out), optional :: status
    character(160) :: buf
    shape_ok = all(shape(x) == [m, n]) .and. all(shape(y) == [m, n])
    if (.not. shape_ok) then
      write (buf, '("x is (",i0,",",i0,"), y is (",i0,",",i0,"): both must be (ni,nj) = (",i0,",",i0,")")') &
           shape(x), shape(y), m, n
      call fail(self, EG2D_ERR_ARGUMENT, where, trim(buf), status)
    end if
  end function shape_ok

  ! The grid's size, or a recorded failure (not created).
  logical function size_of(self, ni, nj, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer(c_int), intent(out) :: ni, nj
    integer, intent(out), optional :: status
    integer(c_int) :: rc
    ni = 0
    nj = 0
    rc = eg2d_get_size(self%handle, ni, nj)
    size_of = rc == EG2D_OK
    if (.not. size_of) call finish(self, rc, status)
  end function size_of

  ! ---------------------------------------------------------------- lifetime
  ! Creates an ni x nj grid; an earlier grid held by self is freed first.
  subroutine grid_create(self, ni, nj, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: ni, nj
    integer, intent(out), optional :: status
    integer(c_int) :: rc
    call grid_destroy(self)
    rc = eg2d_create(int(ni, c_int), int(nj, c_int), self%handle)
    if (rc == EG2D_OK) live_grids = live_grids + 1
    call finish(self, rc, status)
  end subroutine grid_create

  ! Frees the grid; a grid never created (or already freed) is a no-op.
  subroutine grid_destroy(self)
    class(eg2d_grid_t), intent(inout) :: self
    if (c_associated(self%handle)) then
      call eg2d_destroy(self%handle)
      live_grids = live_grids - 1
    end if
    self%handle = c_null_ptr
  end subroutine grid_destroy

  subroutine grid_final(self)
    type(eg2d_grid_t), intent(inout) :: self
    call grid_destroy(self)
  end subroutine grid_final

  ! The raw handle, for the bind(C) functions (eg2d_solve(g%c_handle())).
  function grid_c_handle(self) result(p)
    class(eg2d_grid_t), intent(in) :: self
    type(c_ptr) :: p
    p = self%handle
  end function grid_c_handle

  ! The message of the last failed call through this object ('' if none).
  function grid_last_error(self) result(s)
    class(eg2d_grid_t), intent(in) :: self
    character(:), allocatable :: s
    if (allocated(self%message)) then
      s = self%message
    else
      s = ''
    end if
  end function grid_last_error

  ! ---------------------------------------------------------------- topology
  subroutine grid_set_topology(self, topology, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: topology
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_topology(self%handle, int(topology, c_int)), status)
  end subroutine grid_set_topology

  subroutine grid_get_topology(self, topology, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out) :: topology
    integer, intent(out), optional :: status
    integer(c_int) :: t
    t = -1
    call finish(self, eg2d_get_topology(self%handle, t), status)
    topology = int(t)
  end subroutine grid_get_topology

  ! C-grid: the trailing edge's index w on JMIN (nodes i and ni-1-i of JMIN
  ! are one point for i <= w); 0 on the other topologies.
  subroutine grid_get_cut(self, wake, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out) :: wake
    integer, intent(out), optional :: status
    integer(c_int) :: w
    w = -1
    call finish(self, eg2d_get_cut(self%handle, w), status)
    wake = int(w)
  end subroutine grid_get_cut

  ! ---------------------------------------------------------------- boundary
  ! One side from its points in increasing index: ni points for JMIN/JMAX,
  ! nj for IMIN/IMAX. An unknown side is left for the library to report.
  subroutine grid_set_side(self, side, x, y, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: side
    real(c_double), intent(in) :: x(:), y(:)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    integer :: need
    character(160) :: buf
    if (.not. size_of(self, ni, nj, status)) return
    need = -1
    if (side == EG2D_SIDE_JMIN .or. side == EG2D_SIDE_JMAX) need = ni
    if (side == EG2D_SIDE_IMIN .or. side == EG2D_SIDE_IMAX) need = nj
    write (buf, '("side ",i0,": ")') side
    if (.not. points_fit(self, need, x, y, 'set_side', trim(buf) // ' ', 'side', status)) return
    call finish(self, eg2d_set_side(self%handle, int(side, c_int), x, y), status)
  end subroutine grid_set_side

  ! True when x and y hold `need` points each (need < 0: the library judges);
  ! else fails `routine` with "PREFIXx has .. and y .. points; the WHAT has NEED".
  logical function points_fit(self, need, x, y, routine, prefix, what, status) result(ok)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: need
    real(c_double), intent(in) :: x(:), y(:)
    character(*), intent(in) :: routine, prefix, what
    integer, intent(out), optional :: status
    character(160) :: buf
    ok = need < 0 .or. (size(x) == need .and. size(y) == need)
    if (ok) return
    write (buf, '("x has ",i0," and y ",i0," points; the ",a," has ",i0)') size(x), size(y), what, need
    call fail(self, EG2D_ERR_ARGUMENT, routine, prefix // trim(buf), status)
  end function points_fit

  ! An interior line held by TFI and every solver: the column i = index
  ! (direction EG2D_XI, nj points) or the row j = index (EG2D_ETA, ni points).
  ! Indices are eg2d's, 0-based: the Fortran column x(index+1, :).
  subroutine grid_set_interior_line(self, direction, index, x, y, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: direction, index
    real(c_double), intent(in) :: x(:), y(:)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    integer :: need
    if (.not. size_of(self, ni, nj, status)) return
    need = -1
    if (direction == EG2D_XI) need = nj
    if (direction == EG2D_ETA) need = ni
    if (.not. points_fit(self, need, x, y, 'set_interior_line', '', 'line', status)) return
    call finish(self, eg2d_set_interior_line(self%handle, int(direction, c_int), int(index, c_int), x, y), status)
  end subroutine grid_set_interior_line

  subroutine grid_clear_interior_lines(self, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out), optional :: status
    call finish(self, eg2d_clear_interior_lines(self%handle), status)
  end subroutine grid_clear_interior_lines

  ! The boundary ring from whole x(ni,nj), y(ni,nj) arrays (only the boundary is read).
  subroutine grid_set_boundary(self, x, y, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in) :: x(:, :), y(:, :)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    if (.not. size_of(self, ni, nj, status)) return
    if (.not. shape_ok(self, 'set_boundary', x, y, ni, nj, status)) return
    call finish(self, eg2d_set_boundary(self%handle, x, y), status)
  end subroutine grid_set_boundary

  subroutine grid_initialize(self, method, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: method
    integer, intent(out), optional :: status
    call finish(self, eg2d_initialize(self%handle, int(method, c_int)), status)
  end subroutine grid_initialize

  ! A whole start grid x(ni,nj), y(ni,nj), boundary included.
  subroutine grid_set_coordinates(self, x, y, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in) :: x(:, :), y(:, :)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    if (.not. size_of(self, ni, nj, status)) return
    if (.not. shape_ok(self, 'set_coordinates', x, y, ni, nj, status)) return
    call finish(self, eg2d_set_coordinates(self%handle, x, y), status)
  end subroutine grid_set_coordinates

  ! ---------------------------------------------------------------- settings
  subroutine grid_set_system(self, system, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: system
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_system(self%handle, int(system, c_int)), status)
  end subroutine grid_set_system

  subroutine grid_set_solver(self, solver, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: solver
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_solver(self%handle, int(solver, c_int)), status)
  end subroutine grid_set_solver

  subroutine grid_get_solver(self, solver, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out) :: solver
    integer, intent(out), optional :: status
    integer(c_int) :: s
    s = -1
    call finish(self, eg2d_get_solver(self%handle, s), status)
    solver = int(s)
  end subroutine grid_get_solver

  subroutine grid_set_relaxation(self, omega, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in) :: omega
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_relaxation(self%handle, omega), status)
  end subroutine grid_set_relaxation

  subroutine grid_set_tolerance(self, tolerance, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in) :: tolerance
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_tolerance(self%handle, tolerance), status)
  end subroutine grid_set_tolerance

  subroutine grid_set_max_iterations(self, max_iterations, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: max_iterations
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_max_iterations(self%handle, int(max_iterations, c_int)), status)
  end subroutine grid_set_max_iterations

  subroutine grid_set_parameter(self, param, value, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: param
    real(c_double), intent(in) :: value
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_parameter(self%handle, int(param, c_int), value), status)
  end subroutine grid_set_parameter

  subroutine grid_get_parameter(self, param, value, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: param
    real(c_double), intent(out) :: value
    integer, intent(out), optional :: status
    value = 0
    call finish(self, eg2d_get_parameter(self%handle, int(param, c_int), value), status)
  end subroutine grid_get_parameter

  ! AF (seed 004): the pseudo-time-step cycle and the Warming-Beam time rule.
  subroutine grid_set_af_cycle(self, dtau_min, dtau_max, steps, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in) :: dtau_min, dtau_max
    integer, intent(in) :: steps
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_af_cycle(self%handle, dtau_min, dtau_max, int(steps, c_int)), status)
  end subroutine grid_set_af_cycle

  subroutine grid_set_af_time_rule(self, a, b, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in) :: a, b
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_af_time_rule(self%handle, a, b), status)
  end subroutine grid_set_af_time_rule

  ! ---------------------------------------------------------------- running
  ! fn: a bind(C) function with the interface eg2d_monitor_fn; absent removes
  ! the monitor. user is handed to fn unchanged (c_loc of your data).
  subroutine grid_set_monitor(self, fn, user, status)
    class(eg2d_grid_t), intent(inout) :: self
    procedure(eg2d_monitor_fn), optional :: fn
    type(c_ptr), intent(in), optional :: user
    integer, intent(out), optional :: status
    type(c_funptr) :: f
    type(c_ptr) :: u
    f = c_null_funptr
    u = c_null_ptr
    if (present(fn)) f = c_funloc(fn)
    if (present(user)) u = user
    call finish(self, eg2d_set_monitor(self%handle, f, u), status)
  end subroutine grid_set_monitor

  subroutine grid_iterate(self, iterations, residual, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: iterations
    real(c_double), intent(out), optional :: residual
    integer, intent(out), optional :: status
    call finish(self, eg2d_iterate(self%handle, int(iterations, c_int), residual), status)
  end subroutine grid_iterate

  subroutine grid_solve(self, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out), optional :: status
    call finish(self, eg2d_solve(self%handle), status)
  end subroutine grid_solve

  ! ---------------------------------------------------------------- queries
  subroutine grid_get_size(self, ni, nj, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out) :: ni, nj
    integer, intent(out), optional :: status
    integer(c_int) :: m, n
    m = 0
    n = 0
    call finish(self, eg2d_get_size(self%handle, m, n), status)
    ni = int(m)
    nj = int(n)
  end subroutine grid_get_size

  ! The node coordinates into x(ni,nj), y(ni,nj).
  subroutine grid_get_coordinates(self, x, y, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(inout) :: x(:, :), y(:, :)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    if (.not. size_of(self, ni, nj, status)) return
    if (.not. shape_ok(self, 'get_coordinates', x, y, ni, nj, status)) return
    call finish(self, eg2d_get_coordinates(self%handle, x, y), status)
  end subroutine grid_get_coordinates

  subroutine grid_get_residual(self, residual, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(out) :: residual
    integer, intent(out), optional :: status
    residual = 0
    call finish(self, eg2d_get_residual(self%handle, residual), status)
  end subroutine grid_get_residual

  subroutine grid_get_iterations(self, iterations, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out) :: iterations
    integer, intent(out), optional :: status
    integer(c_int) :: n
    n = 0
    call finish(self, eg2d_get_iterations(self%handle, n), status)
    iterations = int(n)
  end subroutine grid_get_iterations

  ! What the last iterate/solve ran: what = EG2D_RUN_SOLVER, _LEVELS, _LEVELS_BUILT, _EVENTS.
  subroutine grid_get_run_info(self, what, value, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: what
    integer, intent(out) :: value
    integer, intent(out), optional :: status
    integer(c_int) :: v
    v = 0
    call finish(self, eg2d_get_run_info(self%handle, int(what, c_int), v), status)
    value = int(v)
  end subroutine grid_get_run_info

  ! The k-th change of strategy of the last run (k from 0): its iteration and message.
  subroutine grid_get_run_event(self, index, iteration, message, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: index
    integer, intent(out) :: iteration
    character(len=*), intent(out) :: message
    integer, intent(out), optional :: status
    character(kind=c_char) :: buf(512)
    integer(c_int) :: it
    integer :: k
    it = 0
    buf = c_null_char
    call finish(self, eg2d_get_run_event(self%handle, int(index, c_int), it, buf, int(size(buf), c_int)), status)
    iteration = int(it)
    message = ''
    do k = 1, min(len(message), size(buf))
      if (buf(k) == c_null_char) exit
      message(k:k) = buf(k)
    end do
  end subroutine grid_get_run_event

  subroutine grid_get_quality(self, metric, value, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: metric
    real(c_double), intent(out) :: value
    integer, intent(out), optional :: status
    value = 0
    call finish(self, eg2d_get_quality(self%handle, int(metric, c_int), value), status)
  end subroutine grid_get_quality

  ! A figure of the wall layer at a side (EG2D_WALL_*): first cells, growth, angle.
  subroutine grid_get_wall_layer(self, side, what, value, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: side, what
    real(c_double), intent(out) :: value
    integer, intent(out), optional :: status
    value = 0
    call finish(self, eg2d_get_wall_layer(self%handle, int(side, c_int), int(what, c_int), value), status)
  end subroutine grid_get_wall_layer

  ! The per-cell values of a quality metric into values(ni-1, nj-1).
  subroutine grid_get_cell_quality(self, metric, values, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: metric
    real(c_double), intent(inout) :: values(:, :)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    character(160) :: buf
    if (.not. size_of(self, ni, nj, status)) return
    if (any(shape(values) /= [ni - 1, nj - 1])) then
      write (buf, '("values is (",i0,",",i0,"): must be (ni-1,nj-1) = (",i0,",",i0,")")') &
           shape(values), ni - 1, nj - 1
      call fail(self, EG2D_ERR_ARGUMENT, 'get_cell_quality', trim(buf), status)
      return
    end if
    call finish(self, eg2d_get_cell_quality(self%handle, int(metric, c_int), values), status)
  end subroutine grid_get_cell_quality

  ! The control terms as Thompson's P, Q per node into P(ni, nj), Q(ni, nj).
  subroutine grid_get_controls(self, P, Q, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(inout) :: P(:, :), Q(:, :)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    character(160) :: buf
    if (.not. size_of(self, ni, nj, status)) return
    if (any(shape(P) /= [ni, nj]) .or. any(shape(Q) /= [ni, nj])) then
      write (buf, '("P is (",i0,",",i0,"), Q (",i0,",",i0,"): both must be (ni,nj) = (",i0,",",i0,")")') &
           shape(P), shape(Q), ni, nj
      call fail(self, EG2D_ERR_ARGUMENT, 'get_controls', trim(buf), status)
      return
    end if
    call finish(self, eg2d_get_controls(self%handle, P, Q), status)
  end subroutine grid_get_controls

  ! ---------------------------------------------------------------- files
  ! Writes the grid to path in an EG2D_FORMAT_* (ior() with EG2D_PLOT3D_* flags).
  subroutine grid_write(self, path, format, status)
    class(eg2d_grid_t), intent(inout) :: self
    character(*), intent(in) :: path
    integer, intent(in) :: format
    integer, intent(out), optional :: status
    call finish(self, eg2d_write(self%handle, c_path(path), int(format, c_int)), status)
  end subroutine grid_write

  ! Sets a side from a point file ("x y" per line) of exactly ni or nj points.
  subroutine grid_set_side_from_file(self, side, path, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: side
    character(*), intent(in) :: path
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_side_from_file(self%handle, int(side, c_int), c_path(path)), status)
  end subroutine grid_set_side_from_file

  ! Reads grid `block` (default 0) of a Plot3D file into x, y allocated as
  ! (ni, nj); format (EG2D_FORMAT_* with its EG2D_PLOT3D_* flags) and the
  ! number of grids in the file on request.
  subroutine eg2d_read_plot3d_grid(path, x, y, block, format, nblocks, status)
    character(*), intent(in) :: path
    real(c_double), allocatable, intent(out) :: x(:, :), y(:, :)
    integer, intent(in), optional :: block
    integer, intent(out), optional :: format, nblocks, status
    integer(c_int) :: rc, b, f, nb, ni, nj
    b = 0
    if (present(block)) b = int(block, c_int)
    rc = eg2d_read_plot3d(c_path(path), b, f, nb, ni, nj)
    if (rc == EG2D_OK) then
      allocate (x(ni, nj), y(ni, nj))
      rc = eg2d_read_plot3d_into(c_path(path), b, ni * nj, x=x, y=y)
    end if
    if (present(format) .and. rc == EG2D_OK) format = int(f)
    if (present(nblocks) .and. rc == EG2D_OK) nblocks = int(nb)
    call settle(rc, eg2d_c_string(eg2d_last_error(c_null_ptr)), status)
  end subroutine eg2d_read_plot3d_grid

  ! Reads a point file into x, y allocated to its number of points.
  subroutine eg2d_read_point_file(path, x, y, status)
    character(*), intent(in) :: path
    real(c_double), allocatable, intent(out) :: x(:), y(:)
    integer, intent(out), optional :: status
    integer(c_int) :: rc, n
    rc = eg2d_read_points(c_path(path), 0_c_int, n)
    if (rc == EG2D_OK) then
      allocate (x(n), y(n))
      rc = eg2d_read_points(c_path(path), n, x=x, y=y)
    end if
    call settle(rc, eg2d_c_string(eg2d_last_error(c_null_ptr)), status)
  end subroutine eg2d_read_point_file

  ! The side's points on a curve with a distribution (EG2D_DIST_*, parameters
  ! p1, p2) and flags (EG2D_CURVE_*, default 0).
  subroutine grid_set_side_curve(self, side, curve, distribution, p1, p2, flags, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: side, distribution
    class(eg2d_curve_t), intent(in) :: curve
    real(c_double), intent(in) :: p1, p2
    integer, intent(in), optional :: flags
    integer, intent(out), optional :: status
    integer(c_int) :: f
    f = 0
    if (present(flags)) f = int(flags, c_int)
    call finish(self, eg2d_set_side_curve(self%handle, int(side, c_int), curve%handle, &
         int(distribution, c_int), p1, p2, f), status)
  end subroutine grid_set_side_curve

  ! Topology (EG2D_TOPO_O or EG2D_TOPO_C) and boundary of an airfoil grid round `section`.
  subroutine grid_set_airfoil(self, section, topology, status)
    class(eg2d_grid_t), intent(inout) :: self
    class(eg2d_curve_t), intent(in) :: section
    integer, intent(in) :: topology
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_airfoil(self%handle, section%handle, int(topology, c_int)), status)
  end subroutine grid_set_airfoil

  ! ---------------------------------------------------------------- control
  ! Thompson's attraction of the lines direction = EG2D_XI / EG2D_ETA to `line`.
  subroutine grid_add_line_source(self, direction, line, amplitude, decay, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: direction
    real(c_double), intent(in) :: line, amplitude, decay
    integer, intent(out), optional :: status
    call finish(self, eg2d_add_line_source(self%handle, int(direction, c_int), line, amplitude, decay), status)
  end subroutine grid_add_line_source

  subroutine grid_add_point_source(self, xi, eta, amplitude, decay, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in) :: xi, eta, amplitude, decay
    integer, intent(out), optional :: status
    call finish(self, eg2d_add_point_source(self%handle, xi, eta, amplitude, decay), status)
  end subroutine grid_add_point_source

  subroutine grid_clear_sources(self, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out), optional :: status
    call finish(self, eg2d_clear_sources(self%handle), status)
  end subroutine grid_clear_sources

  ! One array of shape (ni, nj), or a recorded failure (`name` names it).
  logical function field_ok(self, where, name, a, ni, nj, status)
    class(eg2d_grid_t), intent(inout) :: self
    character(*), intent(in) :: where, name
    real(c_double), intent(in) :: a(:, :)
    integer(c_int), intent(in) :: ni, nj
    integer, intent(out), optional :: status
    character(120) :: buf
    field_ok = all(shape(a) == [ni, nj])
    if (.not. field_ok) then
      write (buf, '(a," is (",i0,",",i0,"): must be (ni,nj) = (",i0,",",i0,")")') name, shape(a), ni, nj
      call fail(self, EG2D_ERR_ARGUMENT, where, trim(buf), status)
    end if
  end function field_ok

  ! The user's P(ni,nj), Q(ni,nj) (seed 000's p1, p2); an absent one is zero,
  ! both absent remove them.
  subroutine grid_set_source_arrays(self, P, Q, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in), optional :: P(:, :), Q(:, :)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    if (.not. size_of(self, ni, nj, status)) return
    if (present(P)) then
      if (.not. field_ok(self, 'set_source_arrays', 'P', P, ni, nj, status)) return
    end if
    if (present(Q)) then
      if (.not. field_ok(self, 'set_source_arrays', 'Q', Q, ni, nj, status)) return
    end if
    call finish(self, eg2d_set_source_arrays(self%handle, P, Q), status)
  end subroutine grid_set_source_arrays

  subroutine grid_set_orthogonality(self, method, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: method
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_orthogonality(self%handle, int(method, c_int)), status)
  end subroutine grid_set_orthogonality

  subroutine grid_set_wall_spacing(self, side, height, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: side
    real(c_double), intent(in) :: height
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_wall_spacing(self%handle, int(side, c_int), height), status)
  end subroutine grid_set_wall_spacing

  ! Seed 002's parameter-space grid s(ni,nj), t(ni,nj); both absent remove it.
  subroutine grid_set_parameter_grid(self, s, t, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in), optional :: s(:, :), t(:, :)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    if (.not. size_of(self, ni, nj, status)) return
    if (present(s)) then
      if (.not. field_ok(self, 'set_parameter_grid', 's', s, ni, nj, status)) return
    end if
    if (present(t)) then
      if (.not. field_ok(self, 'set_parameter_grid', 't', t, ni, nj, status)) return
    end if
    call finish(self, eg2d_set_parameter_grid(self%handle, s, t), status)
  end subroutine grid_set_parameter_grid

  ! Weight-function adaptivity, w(ni,nj) > 0; absent removes it.
  subroutine grid_set_weight(self, w, status)
    class(eg2d_grid_t), intent(inout) :: self
    real(c_double), intent(in), optional :: w(:, :)
    integer, intent(out), optional :: status
    integer(c_int) :: ni, nj
    if (.not. size_of(self, ni, nj, status)) return
    if (present(w)) then
      if (.not. field_ok(self, 'set_weight', 'w', w, ni, nj, status)) return
    end if
    call finish(self, eg2d_set_weight(self%handle, w), status)
  end subroutine grid_set_weight

  ! Names and types a stretch of a side for the solver-ready formats:
  ! nodes first..last (0-based) of side, type EG2D_PATCH_*.
  subroutine grid_set_patch(self, side, first, last, type, name, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: side, first, last, type
    character(*), intent(in) :: name
    integer, intent(out), optional :: status
    call finish(self, eg2d_set_patch(self%handle, int(side, c_int), int(first, c_int), int(last, c_int), &
         int(type, c_int), c_path(name)), status)
  end subroutine grid_set_patch

  ! Back to the topology's default patches.
  subroutine grid_clear_patches(self, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out), optional :: status
    call finish(self, eg2d_clear_patches(self%handle), status)
  end subroutine grid_clear_patches

  ! The number of stretches of the whole boundary as the writers see it.
  subroutine grid_get_patch_count(self, count, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(out) :: count
    integer, intent(out), optional :: status
    integer(c_int) :: n
    n = 0
    call finish(self, eg2d_get_patch_count(self%handle, n), status)
    count = int(n)
  end subroutine grid_get_patch_count

  ! The index-th stretch (from 0): side, nodes first..last, type and name.
  subroutine grid_get_patch(self, index, side, first, last, type, name, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: index
    integer, intent(out) :: side, first, last, type
    character(len=*), intent(out) :: name
    integer, intent(out), optional :: status
    character(kind=c_char) :: buf(64)
    integer(c_int) :: s, f, l, t
    integer :: k
    s = 0; f = 0; l = 0; t = 0
    buf = c_null_char
    call finish(self, eg2d_get_patch(self%handle, int(index, c_int), s, f, l, t, buf, int(size(buf), c_int)), status)
    side = int(s); first = int(f); last = int(l); type = int(t)
    name = ''
    do k = 1, min(len(name), size(buf))
      if (buf(k) == c_null_char) exit
      name(k:k) = buf(k)
    end do
  end subroutine grid_get_patch

  ! Seed 002's clustering map (EG2D_CLUSTER_*) sampled at size(u) points.
  subroutine eg2d_get_clustering_map(kind, a, b, strength, u, status)
    integer, intent(in) :: kind
    real(c_double), intent(in) :: a, b, strength
    real(c_double), intent(inout) :: u(:)
    integer, intent(out), optional :: status
    call settle(eg2d_clustering_map(int(kind, c_int), a, b, strength, int(size(u), c_int), u), &
         eg2d_c_string(eg2d_last_error(c_null_ptr)), status)
  end subroutine eg2d_get_clustering_map

  ! s(i,j) = u(i), t(i,j) = v(j): s, t must be (size(u), size(v)).
  subroutine eg2d_get_tensor_parameter_grid(u, v, s, t, status)
    real(c_double), intent(in) :: u(:), v(:)
    real(c_double), intent(inout) :: s(:, :), t(:, :)
    integer, intent(out), optional :: status
    character(160) :: buf
    if (any(shape(s) /= [size(u), size(v)]) .or. any(shape(t) /= [size(u), size(v)])) then
      write (buf, '("tensor_parameter_grid: s is (",i0,",",i0,"), t (",i0,",",i0,"): must be (",i0,",",i0,")")') &
           shape(s), shape(t), size(u), size(v)
      call settle(EG2D_ERR_ARGUMENT, trim(buf), status)
      return
    end if
    call settle(eg2d_tensor_parameter_grid(int(size(u), c_int), int(size(v), c_int), u, v, s, t), &
         eg2d_c_string(eg2d_last_error(c_null_ptr)), status)
  end subroutine eg2d_get_tensor_parameter_grid

  ! ---------------------------------------------------------------- curves
  ! After a curve call: the thread's message on failure (curves have no grid).
  subroutine curve_finish(self, rc, status)
    class(eg2d_curve_t), intent(inout) :: self
    integer(c_int), intent(in) :: rc
    integer, intent(out), optional :: status
    if (rc /= EG2D_OK) self%message = eg2d_c_string(eg2d_last_error(c_null_ptr))
    if (.not. allocated(self%message)) self%message = ''
    call settle(rc, self%message, status)
  end subroutine curve_finish

  ! x(:), y(:) of the same size, or a recorded failure.
  logical function points_ok(self, where, x, y, status)
    class(eg2d_curve_t), intent(inout) :: self
    character(*), intent(in) :: where
    real(c_double), intent(in) :: x(:), y(:)
    integer, intent(out), optional :: status
    character(120) :: buf
    points_ok = size(x) == size(y)
    if (.not. points_ok) then
      write (buf, '(a,": x has ",i0," points, y ",i0)') where, size(x), size(y)
      self%message = trim(buf)
      call settle(EG2D_ERR_ARGUMENT, self%message, status)
    end if
  end function points_ok

  ! Straight segments through the points (x(k), y(k)).
  subroutine curve_polyline(self, x, y, status)
    class(eg2d_curve_t), intent(inout) :: self
    real(c_double), intent(in) :: x(:), y(:)
    integer, intent(out), optional :: status
    call curve_destroy(self)
    if (.not. points_ok(self, 'polyline', x, y, status)) return
    call curve_finish(self, eg2d_curve_polyline(int(size(x), c_int), x, y, self%handle), status)
  end subroutine curve_polyline

  ! The cubic spline through the points (periodic when the last repeats the first).
  subroutine curve_spline(self, x, y, status)
    class(eg2d_curve_t), intent(inout) :: self
    real(c_double), intent(in) :: x(:), y(:)
    integer, intent(out), optional :: status
    call curve_destroy(self)
    if (.not. points_ok(self, 'spline', x, y, status)) return
    call curve_finish(self, eg2d_curve_spline(int(size(x), c_int), x, y, self%handle), status)
  end subroutine curve_spline

  ! A user curve: fn, a bind(C) subroutine with the interface eg2d_curve_fn.
  subroutine curve_from_function(self, fn, user, status)
    class(eg2d_curve_t), intent(inout) :: self
    procedure(eg2d_curve_fn) :: fn
    type(c_ptr), intent(in), optional :: user
    integer, intent(out), optional :: status
    type(c_ptr) :: u
    call curve_destroy(self)
    u = c_null_ptr
    if (present(user)) u = user
    call curve_finish(self, eg2d_curve_function(c_funloc(fn), u, self%handle), status)
  end subroutine curve_from_function

  ! A NACA 4-digit section ('0012'); flags EG2D_NACA_CLOSED_TE or 0 (default).
  subroutine curve_naca4(self, digits, flags, status)
    class(eg2d_curve_t), intent(inout) :: self
    character(*), intent(in) :: digits
    integer, intent(in), optional :: flags
    integer, intent(out), optional :: status
    integer(c_int) :: f
    call curve_destroy(self)
    f = 0
    if (present(flags)) f = int(flags, c_int)
    call curve_finish(self, eg2d_curve_naca4(c_path(digits), f, self%handle), status)
  end subroutine curve_naca4

  ! An airfoil from a Selig or Lednicer coordinate file.
  subroutine curve_read_airfoil(self, path, status)
    class(eg2d_curve_t), intent(inout) :: self
    character(*), intent(in) :: path
    integer, intent(out), optional :: status
    call curve_destroy(self)
    call curve_finish(self, eg2d_curve_read_airfoil(c_path(path), self%handle), status)
  end subroutine curve_read_airfoil

  subroutine curve_destroy(self)
    class(eg2d_curve_t), intent(inout) :: self
    if (c_associated(self%handle)) call eg2d_curve_destroy(self%handle)
    self%handle = c_null_ptr
  end subroutine curve_destroy

  subroutine curve_final(self)
    type(eg2d_curve_t), intent(inout) :: self
    call curve_destroy(self)
  end subroutine curve_final

  function curve_c_handle(self) result(p)
    class(eg2d_curve_t), intent(in) :: self
    type(c_ptr) :: p
    p = self%handle
  end function curve_c_handle

  function curve_last_error(self) result(s)
    class(eg2d_curve_t), intent(in) :: self
    character(:), allocatable :: s
    if (allocated(self%message)) then
      s = self%message
    else
      s = ''
    end if
  end function curve_last_error

  subroutine curve_get_length(self, length, status)
    class(eg2d_curve_t), intent(inout) :: self
    real(c_double), intent(out) :: length
    integer, intent(out), optional :: status
    length = 0
    call curve_finish(self, eg2d_curve_length(self%handle, length), status)
  end subroutine curve_get_length

  ! The point at normalized arc length s in [0, 1].
  subroutine curve_evaluate(self, s, x, y, status)
    class(eg2d_curve_t), intent(inout) :: self
    real(c_double), intent(in) :: s
    real(c_double), intent(out) :: x, y
    integer, intent(out), optional :: status
    x = 0
    y = 0
    call curve_finish(self, eg2d_curve_evaluate(self%handle, s, x, y), status)
  end subroutine curve_evaluate

  ! size(x) points of the curve at the normalized arc lengths of a distribution.
  subroutine curve_points(self, distribution, p1, p2, x, y, status)
    class(eg2d_curve_t), intent(inout) :: self
    integer, intent(in) :: distribution
    real(c_double), intent(in) :: p1, p2
    real(c_double), intent(inout) :: x(:), y(:)
    integer, intent(out), optional :: status
    if (.not. points_ok(self, 'points', x, y, status)) return
    call curve_finish(self, eg2d_curve_points(self%handle, int(size(x), c_int), int(distribution, c_int), &
         p1, p2, x, y), status)
  end subroutine curve_points

  ! size(s) values of a distribution of points on [0, 1].
  subroutine eg2d_get_distribution(distribution, p1, p2, s, status)
    integer, intent(in) :: distribution
    real(c_double), intent(in) :: p1, p2
    real(c_double), intent(inout) :: s(:)
    integer, intent(out), optional :: status
    call settle(eg2d_distribution(int(distribution, c_int), int(size(s), c_int), p1, p2, s), &
         eg2d_c_string(eg2d_last_error(c_null_ptr)), status)
  end subroutine eg2d_get_distribution

  ! The parameter p1 of a distribution whose first spacing (a fraction of 1) with n points is
  ! first_spacing (p2: TANH_TWO's c, VINOKUR's last spacing).
  subroutine eg2d_get_distribution_parameter(distribution, n, first_spacing, p2, p1, status)
    integer, intent(in) :: distribution, n
    real(c_double), intent(in) :: first_spacing, p2
    real(c_double), intent(inout) :: p1
    integer, intent(out), optional :: status
    call settle(eg2d_distribution_parameter(int(distribution, c_int), int(n, c_int), first_spacing, p2, p1), &
         eg2d_c_string(eg2d_last_error(c_null_ptr)), status)
  end subroutine eg2d_get_distribution_parameter

  ! The wall spacing for a target y+ at Reynolds number re on a body of this chord.
  subroutine eg2d_get_first_cell_height(yplus, re, chord, height, status)
    real(c_double), intent(in) :: yplus, re, chord
    real(c_double), intent(out) :: height
    integer, intent(out), optional :: status
    height = 0
    call settle(eg2d_first_cell_height(yplus, re, chord, height), &
         eg2d_c_string(eg2d_last_error(c_null_ptr)), status)
  end subroutine eg2d_get_first_cell_height

  ! A Fortran path as the C string the library reads.
  function c_path(path) result(p)
    character(*), intent(in) :: path
    character(kind=c_char, len=1) :: p(len_trim(path) + 1)
    integer :: i
    do i = 1, len_trim(path)
      p(i) = path(i:i)
    end do
    p(len_trim(path) + 1) = c_null_char
  end function c_path

end module eg2d
