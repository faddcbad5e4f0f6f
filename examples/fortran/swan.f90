! The swan of the elliptic-grid course notes from Fortran: build with
!   gfortran swan.f90 $(pkg-config --cflags --libs eg2d-fortran) -o swan_f
program swan
  use eg2d
  implicit none
  integer, parameter :: n = 65
  type(eg2d_grid_t) :: g
  real(eg2d_dp) :: s(n), x(n, n), y(n, n)
  integer :: i
  s = [(real(i, eg2d_dp) / (n - 1), i = 0, n - 1)]
  call g%create(n, n)
  call g%set_side(EG2D_SIDE_JMIN, s, 0 * s)                  ! bottom y = 0
  call g%set_side(EG2D_SIDE_IMAX, 1 + 2 * s - 2 * s**2, s)   ! right  x = 1+2y-2y^2
  call g%set_side(EG2D_SIDE_JMAX, s, 1 - 2 * s + 2 * s**2)   ! top    y = 1-2x+2x^2
  call g%set_side(EG2D_SIDE_IMIN, 0 * s, s)                  ! left   x = 0
  call g%set_tolerance(1d-10)
  call g%solve()                            ! stops with the library's message on failure
  call g%get_coordinates(x, y)
  print '("swan ",i0,"x",i0,": centre node (",f8.6,", ",f8.6,")")', n, n, x(n/2+1, n/2+1), y(n/2+1, n/2+1)
end program swan
