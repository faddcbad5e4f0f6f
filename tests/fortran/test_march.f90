! The hyperbolic march from Fortran: an O-grid around the unit circle marched
! with EG2D_INIT_HYPERBOLIC (first cell, growth, far field, no folds), and an
! unreachable schedule reported as EG2D_ERR_ARGUMENT; and the wall control's
! hybrid layer, which uses the march.
program test_march
  use eg2d
  use checks
  implicit none
  integer, parameter :: ni = 65, nj = 33
  real(eg2d_dp), parameter :: pi = acos(-1d0)
  type(eg2d_grid_t) :: g
  real(eg2d_dp) :: bx(ni), by(ni), x(ni, nj), y(ni, nj), r(ni, nj), folded, h(nj - 1)
  integer :: i, st, it, at
  character(len=256) :: message

  do i = 1, ni
    bx(i) = cos(2 * pi * (i - 1) / (ni - 1))
    by(i) = sin(2 * pi * (i - 1) / (ni - 1))
  end do
  bx(ni) = bx(1)
  by(ni) = by(1)
  call g%create(ni, nj, st)
  call check_status(st, EG2D_OK, 'create')
  call g%set_topology(EG2D_TOPO_O, st)
  call g%set_side(EG2D_SIDE_JMIN, bx, by, st)
  call check_status(st, EG2D_OK, 'set_side JMIN')
  call g%set_parameter(EG2D_PARAM_MARCH_DISTANCE, 10d0, st)
  call g%set_parameter(EG2D_PARAM_MARCH_FIRST_HEIGHT, 0.01d0, st)
  call g%set_parameter(EG2D_PARAM_MARCH_GROWTH, 1.3d0, st)
  call check_status(st, EG2D_OK, 'set_parameter')
  call g%initialize(EG2D_INIT_HYPERBOLIC, st)
  call check_status(st, EG2D_OK, 'initialize hyperbolic')
  call g%get_coordinates(x, y, st)
  r = hypot(x, y)
  call check(abs(r(1, 2) - 1.01d0) < 1d-5, 'first cell 0.01')
  h = r(1, 2:nj) - r(1, 1:nj - 1)
  call check(maxval(h(2:) / h(:nj - 2)) <= 1.3d0 + 1d-9, 'growth within 1.3')
  call check(minval(r(:, nj)) - 1 >= 0.95d0 * 10, 'far field at 95% of the distance')
  call g%get_quality(EG2D_QUALITY_FOLDED_CELLS, folded, st)
  call check(folded == 0, 'no folded cells')

  call g%set_parameter(EG2D_PARAM_MARCH_DISTANCE, 1d4, st)
  call g%initialize(EG2D_INIT_HYPERBOLIC, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'unreachable distance')
  call check_contains(g%last_error(), 'reach only', 'its message')
  call g%destroy()

  ! The wall control's hybrid layer (EG2D_PARAM_WALL_LAYER 2) in the annulus
  ! 1..10: the first cell as asked, no folds, a few multigrid cycles, and the
  ! run says what it held.
  call g%create(ni, nj, st)
  call g%set_topology(EG2D_TOPO_O, st)
  call g%set_side(EG2D_SIDE_JMIN, bx, by, st)
  call g%set_side(EG2D_SIDE_JMAX, 10 * bx, 10 * by, st)
  call check_status(st, EG2D_OK, 'set_side JMAX')
  call g%set_wall_spacing(EG2D_SIDE_JMIN, 1d-3, st)
  call g%set_orthogonality(EG2D_ORTHO_WALL, st)
  call g%set_parameter(EG2D_PARAM_WALL_LAYER, 2d0, st)
  call g%set_tolerance(1d-10, st)
  call g%solve(st)
  call check_status(st, EG2D_OK, 'solve with the hybrid layer')
  call g%get_iterations(it, st)
  call check(it <= 10, 'a few multigrid cycles')
  call g%get_run_event(0, at, message, st)
  call check_contains(message, 'wall layer (hybrid): 21 rows of the hyperbolic march held', 'the run says so')
  call g%get_coordinates(x, y, st)
  r = hypot(x, y)
  call check(maxval(abs(r(:, 2) - 1.001d0)) < 1d-6, 'first cell 1e-3')
  call g%get_quality(EG2D_QUALITY_FOLDED_CELLS, folded, st)
  call check(folded == 0, 'no folded cells with the hybrid layer')
  call g%destroy()
  call checks_done('test_march')
end program test_march
