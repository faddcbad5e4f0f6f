! Every Fortran-friendly wrapper of module eg2d on its good and its bad path:
! statuses, the messages (from the library or from the shape checks), and
! that a failed call leaves the grid usable. The stop-on-error path (no
! `status`) is tested by test_error_stop_*.
module monitors
  use, intrinsic :: iso_c_binding
  implicit none
contains
  ! Stops the run at iteration 3.
  integer(c_int) function stop_at_3(user, iteration, residual) bind(C)
    type(c_ptr), value :: user
    integer(c_int), value :: iteration
    real(c_double), value :: residual
    integer(c_int), pointer :: calls
    call c_f_pointer(user, calls)
    calls = calls + 1
    stop_at_3 = merge(1, 0, iteration >= 3 .or. residual < 0)
  end function stop_at_3
end module monitors

program test_wrappers
  use, intrinsic :: iso_c_binding, only: c_loc, c_int
  use eg2d
  use checks
  use monitors
  use swan_boundary
  implicit none
  integer, parameter :: ni = 17, nj = 13
  type(eg2d_grid_t) :: g, none
  type(eg2d_grid_t), allocatable :: h
  real(eg2d_dp) :: x(ni, nj), y(ni, nj), xs(ni, nj - 1), lo, hi, def, r, v
  real(eg2d_dp) :: cells(ni - 1, nj - 1)
  real(eg2d_dp), allocatable :: xr(:, :), yr(:, :), px(:), py(:)
  integer :: st, m, n, k, it, u, fmt, nb
  integer(c_int), target :: calls
  character(len=200) :: g_msg
  character(:), allocatable :: unit_s, summary_s, name_s

  ! ---- free functions
  call check(eg2d_version_string() == '1.0.0', 'version string')
  call check(index(eg2d_status_message(EG2D_ERR_BOUNDARY), 'EG2D_ERR_BOUNDARY:') == 1, 'status message')
  ! the library's lists (eg2d.h section 2)
  call eg2d_list_lookup(EG2D_LIST_SOLVERS, 'multigrid', k)
  call check(k == EG2D_SOLVER_MULTIGRID, 'list lookup')
  call eg2d_list_lookup(EG2D_LIST_SOLVERS, 'Multigrid', k, st)
  call check(st == EG2D_ERR_ARGUMENT, 'list lookup of a name not listed')
  call check(eg2d_list_id_name(EG2D_LIST_SYSTEMS, EG2D_SYSTEM_WINSLOW) == 'winslow', 'list id name')
  call eg2d_list_size(EG2D_LIST_PARAMETERS, n)
  call eg2d_list_item(EG2D_LIST_PARAMETERS, n - 1, k, name_s)
  call check(n >= 48 .and. k == EG2D_PARAM_AIRFOIL_O_TE_BASE .and. name_s == 'airfoil_o_te_base', 'list item')
  call eg2d_parameter_description(EG2D_PARAM_MG_FMG, k, unit_s, summary_s)
  call check(k == EG2D_VALUE_FLAG + EG2D_VALUE_INTEGER .and. unit_s == '1' .and. len(summary_s) > 8, &
       'parameter description')
  call eg2d_format_description(EG2D_FORMAT_OPENFOAM, k, name_s)
  call check(k == EG2D_WRITES_DIRECTORY .and. name_s == '_foam', 'format description')
  call check(eg2d_quality_field_name(EG2D_QUALITY_MAX_AREA) == 'area', 'quality field name')
  deallocate (unit_s, summary_s, name_s)  ! the main program's locals are not freed at its end (memcheck)
  call check(eg2d_status_message(999) == 'unknown eg2d status', 'status message of an unknown code')
  call check(eg2d_solver_short_name(EG2D_SOLVER_PSOR) == 'psor', 'solver name')
  call check(eg2d_solver_short_name(99) == '', 'solver name of an unknown id')
  call eg2d_get_parameter_bounds(EG2D_PARAM_TOLERANCE, lo, hi, def, st)
  call check_status(st, EG2D_OK, 'parameter bounds')
  call check(lo == 0 .and. hi == 1 .and. def == 1d-8, 'tolerance bounds (0, 1), default 1e-8')
  call eg2d_get_parameter_bounds(999, lo, hi, def, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'bounds of an unknown parameter')
  call check_contains(eg2d_c_string(eg2d_last_error(none%c_handle())), 'parameter 999', 'its message')

  ! ---- a grid never created: every call reports it, nothing crashes
  call none%solve(st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'solve on a grid never created')
  call check_contains(none%last_error(), 'grid is NULL', 'its message')
  call none%get_size(m, n, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_size on a grid never created')
  call none%set_side(EG2D_SIDE_JMIN, x(:, 1), y(:, 1), st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_side on a grid never created')
  call none%get_coordinates(x, y, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_coordinates on a grid never created')
  call none%iterate(1, status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'iterate on a grid never created')
  call none%destroy()

  ! ---- create
  call g%create(2, nj, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'create 2 x 13')
  call check_contains(g%last_error(), 'eg2d_create', 'its message names eg2d_create')
  call check(eg2d_live_grids() == 0, 'no grid after a failed create')
  call g%create(ni, nj, st)
  call check_status(st, EG2D_OK, 'create 17 x 13')
  call check(eg2d_live_grids() == 1, 'one live grid')
  call g%get_size(m, n, st)
  call check(st == EG2D_OK .and. m == ni .and. n == nj, 'get_size')

  ! ---- topology
  call g%set_topology(7, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_topology 7')
  call check_contains(g%last_error(), 'topology = 7', 'its message')
  call g%set_topology(EG2D_TOPO_O, st)
  call g%get_topology(k, st)
  call check(st == EG2D_OK .and. k == EG2D_TOPO_O, 'set/get topology O')
  call g%set_topology(EG2D_TOPO_SINGLE, st)
  call check_status(st, EG2D_OK, 'set_topology single')

  ! ---- set_side: Fortran shape check, the library's corner check, good path
  call g%set_side(EG2D_SIDE_JMIN, x(1:10, 1), y(1:10, 1), st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_side with 10 points')
  call check_contains(g%last_error(), 'x has 10 and y 10 points; the side has 17', 'its message')
  call g%set_side(7, x(:, 1), y(:, 1), st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_side of side 7')
  call check_contains(g%last_error(), 'eg2d_set_side', 'its message comes from the library')
  call g%initialize(EG2D_INIT_TFI, st)
  call check_status(st, EG2D_ERR_STATE, 'initialize without a boundary')
  call set_swan(g, ni, nj, st)
  call check_status(st, EG2D_OK, 'set the swan sides')
  x(:, 1) = 5
  call g%set_side(EG2D_SIDE_JMIN, x(:, 1), x(:, 1), st)
  call check_status(st, EG2D_ERR_BOUNDARY, 'set_side with corners off')

  ! ---- initialize, get_coordinates, set_coordinates, set_boundary
  call g%initialize(5, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'initialize with method 5')
  call g%get_coordinates(x, y, st)
  call check_status(st, EG2D_ERR_STATE, 'get_coordinates before initialize')
  call g%initialize(EG2D_INIT_TFI, st)
  call check_status(st, EG2D_OK, 'initialize TFI')
  call g%get_coordinates(xs, xs, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_coordinates into (17,12) arrays')
  call check_contains(g%last_error(), 'x is (17,12), y is (17,12): both must be (ni,nj) = (17,13)', &
       'its message')
  call g%get_coordinates(x, y, st)
  call check_status(st, EG2D_OK, 'get_coordinates')
  call check(x(ni, 1) == 1 .and. y(1, nj) == 1 .and. abs(x(ni, nj) - 1) < 1d-15, 'swan corners')
  call check(abs(x(9, 1) - 0.5d0) < 1d-15 .and. y(9, 1) == 0, 'bottom midpoint')
  call g%set_coordinates(xs, xs, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_coordinates with (17,12) arrays')
  call g%set_coordinates(x, y, st)
  call check_status(st, EG2D_OK, 'set_coordinates')
  call g%set_boundary(xs, xs, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_boundary with (17,12) arrays')
  call g%set_boundary(x, y, st)
  call check_status(st, EG2D_OK, 'set_boundary')

  ! ---- settings
  call g%set_system(9, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_system 9')
  call g%set_system(EG2D_SYSTEM_WINSLOW, st)
  call check_status(st, EG2D_OK, 'set_system Winslow')
  call g%set_solver(-1, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_solver -1')
  call g%set_solver(EG2D_SOLVER_PSOR, st)
  call g%get_solver(k, st)
  call check(st == EG2D_OK .and. k == EG2D_SOLVER_PSOR, 'set/get solver')
  call g%set_relaxation(2.5d0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_relaxation 2.5')
  call g%set_relaxation(0d0, st)
  call check_status(st, EG2D_OK, 'set_relaxation automatic')
  call g%set_tolerance(0d0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_tolerance 0')
  call g%set_tolerance(1d-11, st)
  call check_status(st, EG2D_OK, 'set_tolerance 1e-11')
  call g%set_max_iterations(0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_max_iterations 0')
  call g%set_max_iterations(5000, st)
  call check_status(st, EG2D_OK, 'set_max_iterations 5000')
  call g%set_parameter(999, 1d0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_parameter 999')
  call g%get_parameter(EG2D_PARAM_MAX_ITERATIONS, v, st)
  call check(st == EG2D_OK .and. v == 5000, 'get_parameter max iterations = 5000')
  call g%get_parameter(999, v, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_parameter 999')

  ! ---- running: the monitor stops at iteration 3, then a full solve
  calls = 0
  call g%set_monitor(stop_at_3, c_loc(calls), st)
  call check_status(st, EG2D_OK, 'set_monitor')
  call g%solve(st)
  call check_status(st, EG2D_ERR_INTERRUPTED, 'solve stopped by the monitor')
  call g%get_iterations(it, st)
  call check(it == 3 .and. calls == 3, 'three iterations, three monitor calls')
  call g%set_monitor(status=st)
  call check_status(st, EG2D_OK, 'remove the monitor')
  call g%iterate(-1, status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'iterate -1')
  call g%iterate(2, r, st)
  call check(st == EG2D_OK .and. r > 0, 'iterate 2 with the residual')
  call g%iterate(1, status=st)
  call check_status(st, EG2D_OK, 'iterate 1 without the residual')
  ! ---- what the run ran
  call g%get_run_info(EG2D_RUN_SOLVER, m, st)
  call check(st == EG2D_OK .and. m == EG2D_SOLVER_PSOR, 'run info: point SOR ran')
  call g%get_run_info(EG2D_RUN_LEVELS, m, st)
  call check(st == EG2D_OK .and. m == 1, 'run info: point SOR runs on the fine grid alone')
  call g%get_run_info(EG2D_RUN_EVENTS, n, st)
  call check(st == EG2D_OK .and. n == 0, 'run info: no change of strategy')
  call g%get_run_info(99, n, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'run info 99')
  call check_contains(g%last_error(), 'not an EG2D_RUN_* id', 'its message')
  call g%get_run_event(0, it, g_msg, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'run event 0 of none')
  call check_contains(g%last_error(), 'the last run has 0 events', 'its message')
  call g%solve(st)
  call check_status(st, EG2D_OK, 'solve')
  call g%get_residual(r, st)
  call check(st == EG2D_OK .and. r <= 1d-11, 'residual <= tolerance')
  call g%get_quality(EG2D_QUALITY_FOLDED_CELLS, v, st)
  call check(st == EG2D_OK .and. v == 0, 'no folded cells')
  call g%get_quality(EG2D_QUALITY_MIN_AREA, v, st)
  call check(st == EG2D_OK .and. v > 0, 'positive smallest area')
  call g%get_quality(99, v, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_quality 99')
  call g%set_max_iterations(1, st)
  call g%set_tolerance(1d-14, st)
  call g%set_coordinates(x, y, st)   ! back to TFI: one iteration cannot converge
  call g%solve(st)
  call check_status(st, EG2D_ERR_NOT_CONVERGED, 'solve with one iteration')
  call check_contains(g%last_error(), 'eg2d_solve', 'its message')

  ! ---- AF settings
  call g%set_af_cycle(2d0, 1d0, 0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_af_cycle with dtau_min > dtau_max')
  call g%set_af_cycle(0.5d0, 0d0, 0, st)
  call check_status(st, EG2D_OK, 'set_af_cycle automatic')
  call g%set_af_time_rule(0d0, 0d0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_af_time_rule explicit (b = 0)')
  call g%set_af_time_rule(0.5d0, 1d0, st)
  call g%get_parameter(EG2D_PARAM_AF_A, v, st)
  call check(st == EG2D_OK .and. v == 0.5d0, 'set_af_time_rule three-point backward')

  ! ---- per-cell quality
  call g%get_cell_quality(EG2D_QUALITY_MIN_AREA, cells, st)
  call check(st == EG2D_OK .and. minval(cells) > 0, 'per-cell areas')
  call check(abs(sum(cells) - 1) < 1d-2, 'the cell areas add up to the swan area 1 (to the polygon error)')
  call g%get_cell_quality(EG2D_QUALITY_MIN_AREA, xs, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_cell_quality into (17,12)')
  call check_contains(g%last_error(), 'must be (ni-1,nj-1) = (16,12)', 'its message')
  call g%get_cell_quality(EG2D_QUALITY_ORTHO_MAX_JMIN, cells, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_cell_quality of a boundary summary')

  ! ---- files: write, read back, point files
  call g%get_coordinates(x, y)
  call g%write('fortran_wrappers.x', EG2D_FORMAT_PLOT3D, st)
  call check_status(st, EG2D_OK, 'write Plot3D')
  call g%write('no-such-dir/grid.x', EG2D_FORMAT_PLOT3D, st)
  call check_status(st, EG2D_ERR_IO, 'write into a missing directory')
  call check_contains(g%last_error(), 'no-such-dir/grid.x', 'its message names the path')
  call eg2d_read_plot3d_grid('fortran_wrappers.x', xr, yr, format=fmt, nblocks=nb, status=st)
  call check(st == EG2D_OK .and. fmt == EG2D_FORMAT_PLOT3D .and. nb == 1, 'read the Plot3D file back')
  call check(all(shape(xr) == [ni, nj]) .and. all(xr == x) .and. all(yr == y), &
       'the read grid equals the written one')
  call eg2d_read_plot3d_grid('fortran_wrappers.x', xr, yr, block=1, status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'read block 1 of a one-grid file')
  call eg2d_read_plot3d_grid('no-such-file.x', xr, yr, status=st)
  call check_status(st, EG2D_ERR_IO, 'read a missing Plot3D file')
  call check_contains(eg2d_c_string(eg2d_last_error(none%c_handle())), 'no-such-file.x', 'its message')
  open (newunit=u, file='fortran_wrappers_jmin.txt', status='replace', action='write')
  write (u, '(a)') '# the bottom of the swan, 17 points'
  do k = 0, ni - 1
    write (u, '(es24.16,1x,es24.16)') real(k, eg2d_dp) / (ni - 1), 0d0
  end do
  close (u)
  call eg2d_read_point_file('fortran_wrappers_jmin.txt', px, py, st)
  call check(st == EG2D_OK .and. size(px) == ni .and. px(ni) == 1 .and. all(py == 0), 'read a point file')
  call eg2d_read_point_file('no-such-file.txt', px, py, st)
  call check_status(st, EG2D_ERR_IO, 'read a missing point file')
  call g%set_side_from_file(EG2D_SIDE_JMIN, 'fortran_wrappers_jmin.txt', st)
  call check_status(st, EG2D_OK, 'set_side_from_file JMIN')
  call g%set_side_from_file(EG2D_SIDE_IMIN, 'fortran_wrappers_jmin.txt', st)
  call check_status(st, EG2D_ERR_BOUNDARY, 'set_side_from_file with 17 points for a 13-point side')
  call check_contains(g%last_error(), 'holds 17 points', 'its message')

  ! ---- the bind(C) layer is usable on the same handle
  call check(eg2d_get_size(g%c_handle(), m, n) == EG2D_OK .and. m == ni, 'C layer on the handle')
  call check(eg2d_set_tolerance(g%c_handle(), -1d0) == EG2D_ERR_ARGUMENT, 'C layer error status')
  call check_contains(eg2d_c_string(eg2d_last_error(g%c_handle())), 'tolerance', 'C layer message')

  ! ---- lifetime: create again frees the old grid; deallocation finalises
  call g%create(ni, nj, st)
  call check(eg2d_live_grids() == 1, 'create again frees the old grid')
  allocate (h)
  call h%create(5, 5)
  call check(eg2d_live_grids() == 2, 'two live grids')
  deallocate (h)
  call check(eg2d_live_grids() == 1, 'deallocate finalises (frees) the grid')
  call g%destroy()
  call g%destroy()
  call check(eg2d_live_grids() == 0, 'destroy, twice, frees once')
  call checks_done('test_wrappers')
end program test_wrappers
