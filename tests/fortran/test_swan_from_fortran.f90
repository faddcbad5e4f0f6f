! The swan grid generated through module eg2d (boundary computed in Fortran)
! equals the one swan_write_c generated from C (tests/support/domains.c), node
! by node to round-off. Usage: test_swan_from_fortran FILE_WRITTEN_BY_C
program test_swan_from_fortran
  use eg2d
  use checks
  use swan_boundary
  implicit none
  type(eg2d_grid_t) :: g
  real(eg2d_dp), allocatable :: x(:, :), y(:, :), xc(:, :), yc(:, :)
  character(512) :: path
  integer :: ni, nj, i, j, u, st
  real(eg2d_dp) :: diff

  call get_command_argument(1, path)
  open (newunit=u, file=trim(path), status='old', action='read')
  read (u, *) ni, nj
  allocate (x(ni, nj), y(ni, nj), xc(ni, nj), yc(ni, nj))
  do j = 1, nj
    do i = 1, ni
      read (u, *) xc(i, j), yc(i, j)
    end do
  end do
  close (u)

  call g%create(ni, nj)
  call set_swan(g, ni, nj, st)
  call check_status(st, EG2D_OK, 'swan boundary from Fortran')
  call g%set_system(EG2D_SYSTEM_WINSLOW)
  call g%set_solver(EG2D_SOLVER_PSOR)
  call g%set_tolerance(1d-12)
  call g%solve()
  call g%get_coordinates(x, y)

  diff = max(maxval(abs(x - xc)), maxval(abs(y - yc)))
  print '("swan ",i0,"x",i0,": max |Fortran - C| = ",es9.2)', ni, nj, diff
  call check(diff <= 1d-14, 'Fortran and C swan grids agree to round-off')
  call check(maxval(abs(xc)) > 1.2d0 .and. maxval(abs(yc)) > 0.99d0, 'the C file holds the swan')
  ! The main program's allocatables are not freed at its end: valgrind (tests/memcheck.sh) counts them lost.
  deallocate (x, y, xc, yc)
  call checks_done('test_swan_from_fortran')
end program test_swan_from_fortran
