! Hermite TFI at chosen sides and an interior line from Fortran, as
! tests/c/test_hermite_sides.c and test_interior_lines.c do in C: the
! annulus's first cells on the radial normals at the heights set, and a row
! of the unit square held on a bulging curve by TFI and by the solve.
program test_tfi2
  use eg2d
  use checks
  implicit none
  integer, parameter :: n = 33, row = 10
  real(eg2d_dp), parameter :: pi = 3.14159265358979323846d0, h0 = 0.02d0, h1 = 0.05d0
  real(eg2d_dp) :: t(n), s(n), cx(n), cy(n), x(n, n), y(n, n), x0(n, n), y0(n, n), folded
  integer :: i, st
  type(eg2d_grid_t) :: g

  ! Hermite at JMIN and JMAX of the annulus 1 <= r <= 3.
  t = [(2 * pi * (i - 1) / (n - 1), i = 1, n)]
  call g%create(n, n)
  call g%set_topology(EG2D_TOPO_O)
  cx = cos(t); cy = sin(t); cx(n) = cx(1); cy(n) = cy(1)
  call g%set_side(EG2D_SIDE_JMIN, cx, cy)
  call g%set_side(EG2D_SIDE_JMAX, 3 * cx, 3 * cy)
  call g%set_parameter(EG2D_PARAM_HERMITE_SIDES, real(ior(ishft(1, EG2D_SIDE_JMIN), ishft(1, EG2D_SIDE_JMAX)), eg2d_dp))
  call g%set_parameter(EG2D_PARAM_HERMITE_HEIGHT_JMIN, h0)
  call g%set_parameter(EG2D_PARAM_HERMITE_HEIGHT_JMAX, h1)
  call g%initialize(EG2D_INIT_HERMITE)
  call g%get_coordinates(x, y)
  call g%get_quality(EG2D_QUALITY_FOLDED_CELLS, folded)
  call check(folded == 0d0, 'Hermite annulus unfolded')
  call check(maxval(abs(hypot(x(:, 2), y(:, 2)) - (1 + h0))) < 1d-12, 'first cells at JMIN as set')
  call check(maxval(abs(hypot(x(:, n - 1), y(:, n - 1)) - (3 - h1))) < 1d-12, 'first cells at JMAX as set')
  call check(maxval(abs(x(:, 2) * y(:, 1) - y(:, 2) * x(:, 1))) < 1d-12, 'on the radial normals')
  call g%destroy()

  ! The unit square with the row j = 10 (Fortran column 11) on a bulging curve.
  s = [((i - 1) / real(n - 1, eg2d_dp), i = 1, n)]
  call g%create(n, n)
  call g%set_side(EG2D_SIDE_JMIN, s, 0 * s)
  call g%set_side(EG2D_SIDE_IMAX, 0 * s + 1, s)
  call g%set_side(EG2D_SIDE_JMAX, s, 0 * s + 1)
  call g%set_side(EG2D_SIDE_IMIN, 0 * s, s)
  cx = s
  cy = s(row + 1) + 0.1d0 * sin(pi * s)
  call g%set_interior_line(EG2D_ETA, row, cx, cy)
  call g%initialize(EG2D_INIT_TFI)
  call g%get_coordinates(x0, y0)
  call check(all(x0(:, row + 1) == cx) .and. all(y0(:, row + 1) == cy), 'TFI holds the line')
  call g%set_tolerance(1d-10)
  call g%solve()
  call g%get_coordinates(x, y)
  call check(all(x(:, row + 1) == cx) .and. all(y(:, row + 1) == cy), 'the solve holds the line')
  call g%clear_interior_lines()
  call g%set_coordinates(x0, y0)
  call g%solve()
  call g%get_coordinates(x, y)
  call check(maxval(abs(y(:, row + 1) - cy)) > 1d-2, 'without the line the solve moves it')
  call g%set_interior_line(EG2D_ETA, 0, cx, cy, status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'row 0 is no interior line')
  call g%set_interior_line(EG2D_ETA, row, cx(1:5), cy(1:5), status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'a line of the wrong length')
  call g%destroy()
  call checks_done('test_tfi2')
end program test_tfi2
