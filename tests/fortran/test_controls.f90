! The grid-control wrappers of module eg2d (sources, source arrays,
! orthogonality, walls, parameter grids, clustering maps, weights) on their
! good and bad paths, on the unit square (9 x 9) where the effect is plain.
program test_controls
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use eg2d
  use checks
  implicit none
  integer, parameter :: n = 9
  type(eg2d_grid_t) :: g
  real(eg2d_dp) :: x(n, n), y(n, n), x0(n, n), y0(n, n), f(n, n), u(n), s(n, n), t(n, n), bad(n, n - 1), wall_figure
  integer :: st, i

  call unit_square(g)
  call g%solve()
  call g%get_coordinates(x0, y0)

  ! line and point sources
  call g%add_line_source(5, 0d0, 100d0, 0.2d0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'line source in direction 5')
  call g%add_line_source(EG2D_ETA, 0d0, 1d0, 0.5d0, st)
  call check_status(st, EG2D_OK, 'line source at eta = 0')
  call g%solve()
  call g%get_coordinates(x, y)
  call check(y(5, 2) < y0(5, 2) - 1d-3, 'the eta-lines move toward eta = 0')
  call g%add_point_source(4d0, 4d0, 1d0, -1d0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'point source with decay -1')
  call g%add_point_source(4d0, 4d0, 1d0, 0.5d0, st)
  call check_status(st, EG2D_OK, 'point source at (4, 4)')
  call g%clear_sources(st)
  call check_status(st, EG2D_OK, 'clear_sources')
  call g%solve()
  call g%get_coordinates(x, y)
  call check(maxval(abs(y - y0)) < 1d-9, 'without sources the grid is the plain one again')

  ! source arrays
  f = 0.5d0
  call g%set_source_arrays(Q=bad, status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'Q of shape (9,8)')
  call check_contains(g%last_error(), 'Q is (9,8): must be (ni,nj) = (9,9)', 'its message')
  call g%set_source_arrays(Q=f, status=st)
  call check_status(st, EG2D_OK, 'set_source_arrays Q only')
  call g%solve()
  call g%get_coordinates(x, y)
  call check(y(5, 5) > y0(5, 5) + 1d-3, 'a positive Q pushes eta-lines toward larger eta')
  f(3, 3) = ieee_value(1d0, ieee_positive_inf)
  call g%set_source_arrays(P=f, status=st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'P with an infinity')
  call g%set_source_arrays(status=st)
  call check_status(st, EG2D_OK, 'remove the source arrays')

  ! orthogonality and walls
  call g%set_orthogonality(7, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'orthogonality 7')
  call g%set_wall_spacing(EG2D_SIDE_JMIN, 0.05d0, st)
  call check_status(st, EG2D_OK, 'wall spacing 0.05 at JMIN')
  call g%set_wall_spacing(9, 0.05d0, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'wall spacing at side 9')
  call g%set_orthogonality(EG2D_ORTHO_WALL, st)
  call check_status(st, EG2D_OK, 'orthogonality WALL')
  call g%set_max_iterations(20000)
  call g%solve(st)
  call g%get_coordinates(x, y)
  call check(st == EG2D_OK .and. abs(y(5, 2) - 0.05d0) < 1d-3, 'first cell height 0.05 at the wall')
  call g%get_wall_layer(EG2D_SIDE_JMIN, EG2D_WALL_FIRST_MEDIAN, wall_figure, st)
  call check(st == EG2D_OK .and. abs(wall_figure - 0.05d0) < 1d-3, 'get_wall_layer: the median first cell 0.05')
  call g%get_wall_layer(EG2D_SIDE_JMIN, 7, wall_figure, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_wall_layer of figure 7')
  call g%set_orthogonality(EG2D_ORTHO_NONE, st)
  call check_status(st, EG2D_OK, 'orthogonality NONE')

  ! clustering maps, tensor parameter grids, parameter-grid control
  call eg2d_get_clustering_map(EG2D_CLUSTER_LINE, 1.5d0, 0d0, 0d0, u, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'clustering map at a = 1.5')
  call eg2d_get_clustering_map(EG2D_CLUSTER_BOUNDARIES, 0.5d0, 0d0, 0d0, u, st)
  call check(st == EG2D_OK .and. u(1) == 0 .and. u(n) == 1 .and. all(u(2:) > u(:n - 1)), &
       'boundary clustering: increasing from 0 to 1')
  call check(u(2) - u(1) < 0.125d0 .and. u(5) - u(4) > 0.125d0, 'dense at the ends, sparse in the middle')
  call eg2d_get_tensor_parameter_grid(u, u, s, bad, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'tensor parameter grid into t(9,8)')
  call eg2d_get_tensor_parameter_grid([(real(i - 1, eg2d_dp) / (n - 1), i = 1, n)], u, s, t, st)
  call check(st == EG2D_OK .and. s(4, 7) == 3d0 / 8 .and. t(4, 7) == u(7), 'tensor parameter grid values')
  call g%set_parameter_grid(s, bad, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'parameter grid t of shape (9,8)')
  call g%set_parameter_grid(s, t, st)
  call check_status(st, EG2D_OK, 'set_parameter_grid')
  call g%solve()
  call g%get_coordinates(x, y)
  call check(y(5, 2) < y0(5, 2) - 1d-3 .and. y(5, 8) > y0(5, 8) + 1d-3, 'eta-lines dense at both walls')
  call g%set_parameter_grid(status=st)
  call check_status(st, EG2D_OK, 'remove the parameter grid')

  ! weights: w = 1 changes nothing; w > 0 is required
  f = 1
  call g%set_weight(f, st)
  call check_status(st, EG2D_OK, 'set_weight 1')
  call g%solve()
  call g%get_coordinates(x, y)
  call check(maxval(abs(x - x0)) + maxval(abs(y - y0)) < 1d-9, 'a uniform weight gives the plain grid')
  f(4, 4) = 0
  call g%set_weight(f, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'a zero weight')
  call g%set_weight(bad, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'weights of shape (9,8)')
  call g%set_weight(status=st)
  call check_status(st, EG2D_OK, 'remove the weights')
  call g%destroy()
  call checks_done('test_controls')

contains

  subroutine unit_square(g)
    type(eg2d_grid_t), intent(inout) :: g
    real(eg2d_dp) :: s(n)
    integer :: k
    s = [(real(k - 1, eg2d_dp) / (n - 1), k = 1, n)]
    call g%create(n, n)
    call g%set_side(EG2D_SIDE_JMIN, s, 0 * s)
    call g%set_side(EG2D_SIDE_IMAX, 1 + 0 * s, s)
    call g%set_side(EG2D_SIDE_JMAX, s, 1 + 0 * s)
    call g%set_side(EG2D_SIDE_IMIN, 0 * s, s)
    call g%set_tolerance(1d-12)
  end subroutine unit_square
end program test_controls
