! Without `status`, a failure reported by the library stops the program with
! eg2d_last_error's message (ctest matches it).
program test_error_stop_library
  use eg2d
  implicit none
  type(eg2d_grid_t) :: g
  call g%create(17, 9)
  call g%solve()
  print '(a)', 'not reached'
end program test_error_stop_library
