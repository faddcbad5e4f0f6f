! The hyperbolic march from Fortran: an O-grid around the unit circle marched
! with EG2D_INIT_HYPERBOLIC (first cell, growth, far field, no folds), and an
! unreachable schedule reported as EG2D_ERR_ARGUMENT; and the wall control's
! hybrid layer, which uses the march: in an annulus, and by default on a
! NACA 0012 C-grid at y+ 1.
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
  call c_grid_by_default()
  call checks_done('test_march')

contains

  ! A NACA 0012 C-grid 385x97, far field 100 chords, with only the first
  ! cell set (y+ 1 at Re 6e6): the default makes the hybrid layer; the first
  ! cell as asked on the body, growth at most 1.2 over 30 cells, no folds,
  ! the cut's first cells growing downstream, a few cycles.
  subroutine c_grid_by_default()
    integer, parameter :: ci = 385, cj = 97, wake = 80, na = ci - 2 * wake
    real(eg2d_dp), parameter :: radius = 100, te = 2d-3
    type(eg2d_grid_t) :: c
    type(eg2d_curve_t) :: foil
    real(eg2d_dp) :: cx(ci), cy(ci), s(na), yo(cj), xs(ci, cj), ys(ci, cj), wall, hgt(ci, cj - 1), rr, lo, hi, cell, a
    integer :: k, j
    call eg2d_get_first_cell_height(1d0, 6d6, 1d0, wall, st)
    call foil%naca4('0012', EG2D_NACA_CLOSED_TE, st)
    call foil%points(EG2D_DIST_VINOKUR, te, te, cx(wake + 1:wake + na), cy(wake + 1:wake + na), st)
    call check_status(st, EG2D_OK, 'the section by Vinokur')
    call foil%destroy()
    lo = 1
    hi = 2
    do k = 1, 200  ! the cut's ratio: wake cells from te adding up to the radius
      rr = (lo + hi) / 2
      if (te * (rr**wake - 1) / (rr - 1) < radius) then
        lo = rr
      else
        hi = rr
      end if
    end do
    cell = te
    cx(wake) = 1 + te
    do k = wake, 1, -1
      if (k < wake) cx(k) = cx(k + 1) + cell
      cell = cell * rr
    end do
    cx(1) = 1 + radius
    cy(1:wake) = 0
    cx(ci - wake + 1:ci) = cx(wake:1:-1)
    cy(ci - wake + 1:ci) = 0
    call c%create(ci, cj, st)
    call c%set_topology(EG2D_TOPO_C, st)
    call c%set_side(EG2D_SIDE_JMIN, cx, cy, st)
    call check_status(st, EG2D_OK, 'the C-grid cut and section')
    call eg2d_get_distribution(EG2D_DIST_VINOKUR, te / (pi * radius), te / (pi * radius), s, st)
    do k = 1, na
      a = -pi / 2 - pi * s(k)
      cx(wake + k) = 1 + radius * cos(a)
      cy(wake + k) = radius * sin(a)
    end do
    cy(1:wake) = -radius
    cy(ci - wake + 1:ci) = radius
    call c%set_side(EG2D_SIDE_JMAX, cx, cy, st)
    call check_status(st, EG2D_OK, 'the far field')
    yo = [(-radius * (j - 1) / (cj - 1), j = 1, cj)]
    call c%set_side(EG2D_SIDE_IMIN, [(1 + radius, j = 1, cj)], yo, st)
    call c%set_side(EG2D_SIDE_IMAX, [(1 + radius, j = 1, cj)], -yo, st)
    call check_status(st, EG2D_OK, 'the outflow sides')
    call c%set_wall_spacing(EG2D_SIDE_JMIN, wall, st)
    call c%set_orthogonality(EG2D_ORTHO_WALL, st)
    call c%set_tolerance(1d-10, st)
    call c%solve(st)
    call check_status(st, EG2D_OK, 'solve the C-grid by default')
    call c%get_iterations(it, st)
    call check(it <= 10, 'C-grid: a few multigrid cycles')
    call c%get_run_event(0, at, message, st)
    call check_contains(message, 'wall layer (hybrid): 64 rows of the hyperbolic march held', 'C-grid: the run says so')
    call c%get_coordinates(xs, ys, st)
    hgt = hypot(xs(:, 2:cj) - xs(:, 1:cj - 1), ys(:, 2:cj) - ys(:, 1:cj - 1))
    call check(maxval(abs(hgt(wake + 1:ci - wake, 1) / wall - 1)) < 1d-3, 'C-grid: first cell on the body')
    call check(maxval(hgt(wake + 1:ci - wake, 2:30) / hgt(wake + 1:ci - wake, 1:29)) <= 1.2d0, 'C-grid: growth <= 1.2')
    call check(minval(hgt(wake + 1:ci - wake, 2:30) / hgt(wake + 1:ci - wake, 1:29)) >= 1d0, 'C-grid: growth >= 1')
    ! the cut's first cells grow downstream, then stay level in the far wake
    ! (within 1%, the layer's thickness there)
    call check(all(hgt(2:wake - 1, 1) >= hgt(3:wake, 1) * (1 - 1d-2)) .and. hgt(2, 1) > 10 * wall, &
               'C-grid: the cut grows downstream')
    call c%get_quality(EG2D_QUALITY_FOLDED_CELLS, folded, st)
    call check(folded == 0, 'C-grid: no folded cells')
    call c%destroy()
  end subroutine c_grid_by_default
end program test_march
