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
!
! Threads (eg2d.h, "Threads", holds for the module):
!  - different eg2d_grid_t / eg2d_curve_t objects may be used from different
!    threads at the same time (OpenMP, pthreads via bind(C)): the library has
!    no global mutable state, and the module none that a call writes (the
!    count of eg2d_live_grids is a C atomic, live_grids.c);
!  - one object, one call at a time: no call is locked inside, the queries
!    included (get_residual caches; every failure writes the handle's error
!    text and the object's message). Serialise a shared object yourself
!    (!$omp critical, a lock);
!  - an object may move between threads (no thread affinity) when the hand
!    over is synchronised (a barrier, a join, a lock);
!  - g%last_error() is the object's: read it before the next call on it;
!    eg2d_last_error(c_null_ptr) is per thread;
!  - the monitor runs on the thread of iterate/solve, inside the call: it
!    may query its own grid (eg2d_get_* on its handle), never change or
!    destroy it;
!  - eg2d_version_string, eg2d_status_message, eg2d_solver_short_name and
!    eg2d_get_parameter_bounds need no handle and are safe from any thread.
!
! Generated and hand-written: tools/gen_bindings.py writes the wrappers of the
! mechanical shapes from eg2d.h into eg2d_wrappers.inc (with their type-bound
! lines, eg2d_grid_procedures.inc and eg2d_curve_procedures.inc, and their
! public statement, eg2d_wrappers_public.inc); never edit those. Written here:
! the types, the helpers the generated wrappers call, and the wrappers of a
! shape of their own (the generator's table HAND_WRITTEN gives each reason).
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
    include 'eg2d_grid_procedures.inc'
    ! Hand-written (tools/gen_bindings.py, HAND_WRITTEN, says why):
    procedure :: set_side => grid_set_side
    procedure :: set_interior_line => grid_set_interior_line
    procedure :: set_monitor => grid_set_monitor
    procedure :: get_cell_quality => grid_get_cell_quality
    procedure :: get_controls => grid_get_controls
    final :: grid_final
  end type eg2d_grid_t

  ! A curve (eg2d_curve_*): made by one of polyline, spline, from_function,
  ! naca4, read_airfoil (each frees a curve held before); freed by destroy or
  ! its final procedure. Do not copy a made curve by assignment.
  type, public :: eg2d_curve_t
    type(c_ptr), private :: handle = c_null_ptr
    character(:), allocatable, private :: message
  contains
    include 'eg2d_curve_procedures.inc'
    procedure :: from_function => curve_from_function
    procedure :: destroy => curve_destroy
    procedure :: c_handle => curve_c_handle
    procedure :: last_error => curve_last_error
    final :: curve_final
  end type eg2d_curve_t

  ! A set of blocks (eg2d.h, "Sets of blocks"): made by create, freed by
  ! destroy or its final procedure; it refers to the grids added (it owns
  ! none): keep them alive while the set is used. Do not copy a created set
  ! by assignment. Hand-written (tools/gen_bindings.py, HAND_WRITTEN).
  type, public :: eg2d_blocks_t
    type(c_ptr), private :: handle = c_null_ptr
    character(:), allocatable, private :: message
  contains
    procedure :: create => blocks_create
    procedure :: destroy => blocks_destroy
    procedure :: c_handle => blocks_c_handle
    procedure :: last_error => blocks_last_error
    procedure :: add => blocks_add
    procedure :: set_name => blocks_set_name
    procedure :: name => blocks_name
    procedure :: join => blocks_join
    procedure :: hold_join => blocks_hold_join
    procedure :: check => blocks_check
    procedure :: solve => blocks_solve
    procedure :: get_run => blocks_get_run
    procedure :: get_kinks => blocks_get_kinks
    procedure :: write => blocks_write
    final :: blocks_final
  end type eg2d_blocks_t

  include 'eg2d_wrappers_public.inc'
  public :: eg2d_c_string, eg2d_version_string, eg2d_live_grids
  public :: eg2d_read_plot3d_grid, eg2d_read_point_file, eg2d_get_tensor_parameter_grid

  ! The number of grids created through eg2d_grid_t and not yet freed (to
  ! check finalisation): an atomic counter in C (live_grids.c), since grids
  ! are created and destroyed on several threads at once; the module has no
  ! SAVE variable that a call writes.
  interface
    subroutine live_grids_add(delta) bind(C, name='eg2d_fortran_live_grids_add')
      import :: c_int
      integer(c_int), value :: delta
    end subroutine live_grids_add
    function live_grids() bind(C, name='eg2d_fortran_live_grids') result(n)
      import :: c_int
      integer(c_int) :: n
    end function live_grids
  end interface

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

  ! The run-time library version as "major.minor.patch".
  ! Hand-written: eg2d_version's three numbers as one string.
  function eg2d_version_string() result(s)
    character(:), allocatable :: s
    integer(c_int) :: major, minor, patch
    character(32) :: buf
    call eg2d_version(major, minor, patch)
    write (buf, '(i0,".",i0,".",i0)') major, minor, patch
    s = trim(buf)
  end function eg2d_version_string

  ! Hand-written: no C function; the module's own count (live_grids.c).
  integer function eg2d_live_grids()
    eg2d_live_grids = int(live_grids())
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
  ! Hand-written: frees the grid held before, counts the live grid.
  subroutine grid_create(self, ni, nj, status)
    class(eg2d_grid_t), intent(inout) :: self
    integer, intent(in) :: ni, nj
    integer, intent(out), optional :: status
    integer(c_int) :: rc
    call grid_destroy(self)
    rc = eg2d_create(int(ni, c_int), int(nj, c_int), self%handle)
    if (rc == EG2D_OK) call live_grids_add(1_c_int)
    call finish(self, rc, status)
  end subroutine grid_create

  ! Frees the grid; a grid never created (or already freed) is a no-op.
  ! Hand-written: a no-op on a freed grid, counts the live grid; no status.
  subroutine grid_destroy(self)
    class(eg2d_grid_t), intent(inout) :: self
    if (c_associated(self%handle)) then
      call eg2d_destroy(self%handle)
      call live_grids_add(-1_c_int)
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
  ! Hand-written: the object's message, which has the Fortran layer's own checks too.
  function grid_last_error(self) result(s)
    class(eg2d_grid_t), intent(in) :: self
    character(:), allocatable :: s
    if (allocated(self%message)) then
      s = self%message
    else
      s = ''
    end if
  end function grid_last_error

  ! ---------------------------------------------------------------- boundary
  ! One side from its points in increasing index: ni points for JMIN/JMAX,
  ! nj for IMIN/IMAX. An unknown side is left for the library to report.
  ! Hand-written: the side decides the number of points (ni or nj).
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
  ! Hand-written: the direction decides the number of points (nj or ni).
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

  ! ---------------------------------------------------------------- running
  ! fn: a bind(C) function with the interface eg2d_monitor_fn; absent removes
  ! the monitor. user is handed to fn unchanged (c_loc of your data).
  ! Hand-written: a callback (c_funloc of an optional procedure) and its user pointer.
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

  ! ---------------------------------------------------------------- queries

  ! The per-cell values of a quality metric into values(ni-1, nj-1).
  ! Hand-written: an array of the cells, (ni-1, nj-1).
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
  ! Hand-written: P and Q checked together, with a message of their own.
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

  ! Reads grid `block` (default 0) of a Plot3D file into x, y allocated as
  ! (ni, nj); format (EG2D_FORMAT_* with its EG2D_PLOT3D_* flags) and the
  ! number of grids in the file on request.
  ! Hand-written: two C calls (eg2d_read_plot3d sizes, eg2d_read_plot3d_into reads) around an allocation.
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
  ! Hand-written: two calls of eg2d_read_points (count, read) around an allocation.
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

  ! ---------------------------------------------------------------- control

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

  ! s(i,j) = u(i), t(i,j) = v(j): s, t must be (size(u), size(v)).
  ! Hand-written: two 2-D arrays sized by two 1-D ones.
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

  ! A user curve: fn, a bind(C) subroutine with the interface eg2d_curve_fn.
  ! Hand-written: a callback (c_funloc) and its optional user pointer.
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

  ! Hand-written: a no-op on a freed curve; no status.
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

  ! A C buffer's text (up to its NUL) into s, cut to len(s), blank-padded.
  subroutine c_buffer_copy(buf, s)
    character(kind=c_char), intent(in) :: buf(:)
    character(len=*), intent(out) :: s
    integer :: k
    s = ''
    do k = 1, min(len(s), size(buf))
      if (buf(k) == c_null_char) exit
      s(k:k) = buf(k)
    end do
  end subroutine c_buffer_copy

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

  ! ---------------------------------------------------------------- sets of blocks
  ! After a C call on the set: records the library's message on failure.
  subroutine blocks_finish(self, rc, status)
    class(eg2d_blocks_t), intent(inout) :: self
    integer(c_int), intent(in) :: rc
    integer, intent(out), optional :: status
    if (rc /= EG2D_OK) self%message = eg2d_c_string(eg2d_blocks_last_error(self%handle))
    if (.not. allocated(self%message)) self%message = ''
    call settle(rc, self%message, status)
  end subroutine blocks_finish

  ! A new, empty set; a set held by self is freed first.
  subroutine blocks_create(self, status)
    class(eg2d_blocks_t), intent(inout) :: self
    integer, intent(out), optional :: status
    integer(c_int) :: rc
    call blocks_destroy(self)
    rc = eg2d_blocks_create(self%handle)
    if (rc /= EG2D_OK) self%message = eg2d_c_string(eg2d_last_error(c_null_ptr))
    if (.not. allocated(self%message)) self%message = ''
    call settle(rc, self%message, status)
  end subroutine blocks_create

  ! Frees the set (not its grids); a set never created or already freed is a no-op.
  subroutine blocks_destroy(self)
    class(eg2d_blocks_t), intent(inout) :: self
    if (c_associated(self%handle)) call eg2d_blocks_destroy(self%handle)
    self%handle = c_null_ptr
  end subroutine blocks_destroy

  subroutine blocks_final(self)
    type(eg2d_blocks_t), intent(inout) :: self
    call blocks_destroy(self)
  end subroutine blocks_final

  function blocks_c_handle(self) result(p)
    class(eg2d_blocks_t), intent(in) :: self
    type(c_ptr) :: p
    p = self%handle
  end function blocks_c_handle

  function blocks_last_error(self) result(s)
    class(eg2d_blocks_t), intent(in) :: self
    character(:), allocatable :: s
    if (allocated(self%message)) then
      s = self%message
    else
      s = ''
    end if
  end function blocks_last_error

  ! Adds the grid as the set's next block; block receives its index (0, 1, ...).
  subroutine blocks_add(self, grid, block, status)
    class(eg2d_blocks_t), intent(inout) :: self
    class(eg2d_grid_t), intent(in) :: grid
    integer, intent(out) :: block
    integer, intent(out), optional :: status
    integer(c_int) :: b
    b = -1
    call blocks_finish(self, eg2d_blocks_add(self%handle, grid%handle, b), status)
    block = int(b)
  end subroutine blocks_add

  ! Names block `block` (0, 1, ...) in the files that hold a zone a block.
  subroutine blocks_set_name(self, block, name, status)
    class(eg2d_blocks_t), intent(inout) :: self
    integer, intent(in) :: block
    character(*), intent(in) :: name
    integer, intent(out), optional :: status
    call blocks_finish(self, eg2d_blocks_set_name(self%handle, int(block, c_int), c_path(name)), status)
  end subroutine blocks_set_name

  ! Block `block`'s name ("block0", ... until named); '' for a block the set has not.
  function blocks_name(self, block) result(s)
    class(eg2d_blocks_t), intent(in) :: self
    integer, intent(in) :: block
    character(:), allocatable :: s
    s = eg2d_c_string(eg2d_blocks_name(self%handle, int(block, c_int)))
  end function blocks_name

  subroutine blocks_join(self, block_a, side_a, first_a, last_a, block_b, side_b, first_b, last_b, status)
    class(eg2d_blocks_t), intent(inout) :: self
    integer, intent(in) :: block_a, side_a, first_a, last_a, block_b, side_b, first_b, last_b
    integer, intent(out), optional :: status
    call blocks_finish(self, eg2d_blocks_join(self%handle, int(block_a, c_int), int(side_a, c_int), &
         int(first_a, c_int), int(last_a, c_int), int(block_b, c_int), int(side_b, c_int), int(first_b, c_int), &
         int(last_b, c_int)), status)
  end subroutine blocks_join

  ! held: .true. holds join `join` (0 for the first join, ...) where the sides put it
  subroutine blocks_hold_join(self, join, held, status)
    class(eg2d_blocks_t), intent(inout) :: self
    integer, intent(in) :: join
    logical, intent(in) :: held
    integer, intent(out), optional :: status
    call blocks_finish(self, eg2d_blocks_hold_join(self%handle, int(join, c_int), merge(1_c_int, 0_c_int, held)), &
         status)
  end subroutine blocks_hold_join

  subroutine blocks_check(self, status)
    class(eg2d_blocks_t), intent(inout) :: self
    integer, intent(out), optional :: status
    call blocks_finish(self, eg2d_blocks_check(self%handle), status)
  end subroutine blocks_check

  subroutine blocks_solve(self, status)
    class(eg2d_blocks_t), intent(inout) :: self
    integer, intent(out), optional :: status
    call blocks_finish(self, eg2d_blocks_solve(self%handle), status)
  end subroutine blocks_solve

  subroutine blocks_get_run(self, iterations, residual, unknowns, status)
    class(eg2d_blocks_t), intent(inout) :: self
    integer, intent(out) :: iterations, unknowns
    real(c_double), intent(out) :: residual
    integer, intent(out), optional :: status
    integer(c_int) :: it, n
    it = 0
    n = 0
    residual = 0
    call blocks_finish(self, eg2d_blocks_get_run(self%handle, it, residual, n), status)
    iterations = int(it)
    unknowns = int(n)
  end subroutine blocks_get_run

  subroutine blocks_get_kinks(self, at_joins, nearby, status)
    class(eg2d_blocks_t), intent(inout) :: self
    real(c_double), intent(out) :: at_joins, nearby
    integer, intent(out), optional :: status
    at_joins = 0
    nearby = 0
    call blocks_finish(self, eg2d_blocks_get_kinks(self%handle, at_joins, nearby), status)
  end subroutine blocks_get_kinks

  subroutine blocks_write(self, path, format, status)
    class(eg2d_blocks_t), intent(inout) :: self
    character(*), intent(in) :: path
    integer, intent(in) :: format
    integer, intent(out), optional :: status
    call blocks_finish(self, eg2d_blocks_write(self%handle, c_path(path), int(format, c_int)), status)
  end subroutine blocks_write

  ! ---------------------------------------------------------------- generated
  ! The wrappers of the mechanical shapes, generated from eg2d.h by
  ! tools/gen_bindings.py; each is documented at its C function in eg2d.h.
  include 'eg2d_wrappers.inc'

end module eg2d
