! EG2D_SYSTEM_VARIATIONAL from Fortran: the weights as parameters, the swan
! at a = 10, b = 1, c = 1 converged and unfolded with more even cells than
! Winslow's, and a line solver refused (EG2D_ERR_STATE).
program test_variational_f
  use eg2d
  use checks
  use swan_boundary
  implicit none
  integer, parameter :: n = 33
  real(eg2d_dp) :: ratio(2), amin, amax, folded, residual, w
  integer :: k, st
  type(eg2d_grid_t) :: g

  do k = 1, 2
    call g%create(n, n)
    call set_swan(g, n, n, st)
    call check_status(st, EG2D_OK, 'swan boundary')
    if (k == 2) then
      call g%set_system(EG2D_SYSTEM_VARIATIONAL)
      call g%set_parameter(EG2D_PARAM_VARIATIONAL_AREA, 10d0)
      call g%set_parameter(EG2D_PARAM_VARIATIONAL_ORTHOGONALITY, 1d0)
      call g%get_parameter(EG2D_PARAM_VARIATIONAL_SPACING, w)
      call check(w == 1d0, 'spacing weight b: default 1')
    end if
    call g%solve(st)
    call check_status(st, EG2D_OK, 'solved')
    call g%get_residual(residual)
    call g%get_quality(EG2D_QUALITY_FOLDED_CELLS, folded)
    call g%get_quality(EG2D_QUALITY_MIN_AREA, amin)
    call g%get_quality(EG2D_QUALITY_MAX_AREA, amax)
    call check(residual <= 1d-8 .and. folded == 0d0, 'converged, unfolded')
    ratio(k) = amax / amin
    if (k == 2) then
      call g%set_solver(EG2D_SOLVER_LSOR)
      call g%iterate(1, status=st)
      call check_status(st, EG2D_ERR_STATE, 'a line solver refuses the variational system')
    end if
    call g%destroy()
  end do
  print '("swan ",i0,"x",i0,": largest/smallest cell area, Winslow ",f7.3,", variational ",f7.3)', n, n, ratio
  call check(ratio(2) < ratio(1), 'the area weight evens the cells')
  call checks_done('test_variational_f')
end program test_variational_f
