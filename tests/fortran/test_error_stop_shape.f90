! Without `status`, a failure found by the Fortran layer stops the program
! with the message (ctest matches it).
program test_error_stop_shape
  use eg2d
  implicit none
  type(eg2d_grid_t) :: g
  real(eg2d_dp) :: x(10) = 0, y(10) = 0
  call g%create(17, 9)
  call g%set_side(EG2D_SIDE_JMIN, x, y)
  print '(a)', 'not reached'
end program test_error_stop_shape
