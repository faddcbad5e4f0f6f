! The curve wrappers of module eg2d (eg2d_curve_t, distributions, y+ height,
! set_side_curve) on their good and bad paths.
module quarter_circle
  use, intrinsic :: iso_c_binding
  implicit none
contains
  ! r(t) = (cos(pi t / 2), sin(pi t / 2)), scaled by the radius user points to.
  subroutine arc(user, t, x, y) bind(C)
    type(c_ptr), value :: user
    real(c_double), value :: t
    real(c_double), intent(out) :: x, y
    real(c_double), pointer :: radius
    call c_f_pointer(user, radius)
    x = radius * cos(acos(-1d0) * t / 2)
    y = radius * sin(acos(-1d0) * t / 2)
  end subroutine arc
end module quarter_circle

program test_curves
  use, intrinsic :: iso_c_binding, only: c_loc
  use eg2d
  use checks
  use quarter_circle
  implicit none
  real(eg2d_dp), parameter :: pi = acos(-1d0)
  type(eg2d_curve_t) :: c
  type(eg2d_grid_t) :: g
  real(eg2d_dp), target :: radius
  real(eg2d_dp) :: len, x, y, s(5), px(5), py(5), cx(65), cy(65), h, cf
  integer :: st, k

  ! polyline: (0,0) -> (1,0) -> (1,1), length 2
  call c%polyline([0d0, 1d0, 1d0], [0d0, 0d0, 1d0], st)
  call check_status(st, EG2D_OK, 'polyline')
  call c%get_length(len, st)
  call check(st == EG2D_OK .and. abs(len - 2) < 1d-14, 'polyline length 2')
  call c%evaluate(0.75d0, x, y, st)
  call check(st == EG2D_OK .and. abs(x - 1) < 1d-12 .and. abs(y - 0.5d0) < 1d-12, 'evaluate at s = 3/4')
  call c%evaluate(1.5d0, x, y, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'evaluate at s = 1.5')
  call check_contains(c%last_error(), 's = 1.5', 'its message')
  call c%points(EG2D_DIST_UNIFORM, 0d0, 0d0, px, py, st)
  call check(st == EG2D_OK .and. maxval(abs(px - [0d0, 0.5d0, 1d0, 1d0, 1d0])) < 1d-12 .and. &
       maxval(abs(py - [0d0, 0d0, 0d0, 0.5d0, 1d0])) < 1d-12, 'five uniform points')
  call c%points(EG2D_DIST_UNIFORM, 0d0, 0d0, px, py(1:4), st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'points into x(5), y(4)')
  call check_contains(c%last_error(), 'x has 5 points, y 4', 'its message')
  call c%polyline([0d0, 1d0], [0d0], st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'polyline with x(2), y(1)')
  call c%polyline([0d0], [0d0], st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'polyline through one point')
  call check_contains(c%last_error(), 'eg2d_curve_polyline', 'its message comes from the library')
  call c%get_length(len, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'length of no curve')

  ! spline: a periodic circle of radius 2 through 65 points
  do k = 1, 65
    cx(k) = 2 * cos(2 * pi * (k - 1) / 64)
    cy(k) = 2 * sin(2 * pi * (k - 1) / 64)
  end do
  cx(65) = cx(1); cy(65) = cy(1)
  call c%spline(cx, cy, st)
  call c%get_length(len, st)
  call check(st == EG2D_OK .and. abs(len - 4 * pi) < 1d-5, 'periodic spline circle length 4 pi')

  ! a user curve: the quarter circle of radius 3, length 3 pi / 2
  radius = 3
  call c%from_function(arc, c_loc(radius), st)
  call check_status(st, EG2D_OK, 'from_function')
  call c%get_length(len, st)
  call check(st == EG2D_OK .and. abs(len - 1.5d0 * pi) < 1d-10, 'quarter circle length 3 pi / 2')
  call c%evaluate(0.5d0, x, y, st)
  call check(abs(x - 3 / sqrt(2d0)) < 1d-10 .and. abs(y - 3 / sqrt(2d0)) < 1d-10, 'its midpoint at 45 degrees')

  ! NACA and airfoil files
  call c%naca4('0012', EG2D_NACA_CLOSED_TE, st)
  call check_status(st, EG2D_OK, 'naca4 0012 closed')
  call c%evaluate(0d0, x, y, st)
  call check(abs(x - 1) < 1d-12 .and. abs(y) < 1d-12, 'NACA 0012 starts at the trailing edge (1, 0)')
  call c%naca4('12', status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'naca4 "12"')
  call c%read_airfoil('no-such-airfoil.dat', st)
  call check_status(st, EG2D_ERR_IO, 'read_airfoil of a missing file')
  call check_contains(c%last_error(), 'no-such-airfoil.dat', 'its message names the file')

  ! distributions and the y+ height
  call eg2d_get_distribution(EG2D_DIST_UNIFORM, 0d0, 0d0, s, st)
  call check(st == EG2D_OK .and. maxval(abs(s - [0d0, 0.25d0, 0.5d0, 0.75d0, 1d0])) < 1d-15, 'uniform distribution')
  call eg2d_get_distribution(EG2D_DIST_EXPONENTIAL, 2d0, 0d0, s, st)
  call check(st == EG2D_OK .and. abs(s(2) - (exp(0.5d0) - 1) / (exp(2d0) - 1)) < 1d-14, &
       'exponential distribution, beta = 2 (the grid-generation lecture notes)')
  call eg2d_get_distribution(EG2D_DIST_EXPONENTIAL, 0d0, 0d0, s, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'exponential with beta = 0')
  call eg2d_get_first_cell_height(1d0, 1d6, 1d0, h, st)
  cf = (2 * log10(1d6) - 0.65d0)**(-2.3d0)
  call check(st == EG2D_OK .and. abs(h - 1 / (1d6 * sqrt(cf / 2))) < 1d-12 * h, 'y+ = 1 height (Schlichting)')
  call eg2d_get_first_cell_height(-1d0, 1d6, 1d0, h, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'y+ = -1')

  ! set_side_curve: the bottom of a 17 x 13 grid on the polyline's first leg
  call c%polyline([0d0, 1d0], [0d0, 0d0])
  call g%create(17, 13)
  call g%set_side_curve(EG2D_SIDE_JMIN, c, EG2D_DIST_UNIFORM, 0d0, 0d0, status=st)
  call check_status(st, EG2D_OK, 'set_side_curve JMIN')
  call g%set_side_curve(9, c, EG2D_DIST_UNIFORM, 0d0, 0d0, status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'set_side_curve of side 9')
  call g%set_side(EG2D_SIDE_IMIN, [(0d0, k = 1, 13)], [(real(k - 1, eg2d_dp) / 12, k = 1, 13)])
  call g%set_side_curve(EG2D_SIDE_JMIN, c, EG2D_DIST_UNIFORM, 0d0, 0d0, EG2D_CURVE_REVERSE, st)
  call check_status(st, EG2D_ERR_BOUNDARY, 'set_side_curve reversed, against the side IMIN')
  call check_contains(g%last_error(), 'eg2d_set_side_curve', 'its message')
  call c%destroy()
  call checks_done('test_curves')
end program test_curves
