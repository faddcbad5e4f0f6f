! Writes Plot3D grid files the way Fortran flow solvers and grid tools do,
! with the compiler's own unformatted and formatted I/O (not eg2d's), for
! read_foreign.c to read with eg2d_read_plot3d. Node (i, j) of the grid is
! at x = i + 0.25 j, y = 0.5 j + 0.01 i**2 (1-based i, j).
! Usage: plot3d_fortran DIR
program plot3d_fortran
  implicit none
  integer, parameter :: ni = 7, nj = 5
  double precision :: x(ni, nj), y(ni, nj), z(ni, nj)
  real :: xs(ni, nj), ys(ni, nj)
  character(len=1024) :: dir
  integer :: i, j
  call get_command_argument(1, dir)
  do j = 1, nj
    do i = 1, ni
      x(i, j) = i + 0.25d0 * j
      y(i, j) = 0.5d0 * j + 0.01d0 * i**2
    end do
  end do
  z = 0
  xs = real(x)
  ys = real(y)
  ! 2D, single grid, unformatted, double (as Construct2D's binary output)
  open(10, file=trim(dir)//'/f_2d.x', form='unformatted', access='sequential', status='replace')
  write(10) ni, nj
  write(10) ((x(i, j), i = 1, ni), j = 1, nj), ((y(i, j), i = 1, ni), j = 1, nj)
  close(10)
  ! 3D with one k-plane, multi-grid header, unformatted, double (Pointwise's default)
  open(10, file=trim(dir)//'/f_3d_multi.x', form='unformatted', access='sequential', status='replace')
  write(10) 1
  write(10) ni, nj, 1
  write(10) ((x(i, j), i = 1, ni), j = 1, nj), ((y(i, j), i = 1, ni), j = 1, nj), ((z(i, j), i = 1, ni), j = 1, nj)
  close(10)
  ! 2D, single precision
  open(10, file=trim(dir)//'/f_2d_single.x', form='unformatted', access='sequential', status='replace')
  write(10) ni, nj
  write(10) ((xs(i, j), i = 1, ni), j = 1, nj), ((ys(i, j), i = 1, ni), j = 1, nj)
  close(10)
  ! 3D formatted (list-directed), single grid
  open(10, file=trim(dir)//'/f_3d_ascii.x', form='formatted', status='replace')
  write(10, *) ni, nj, 1
  write(10, *) ((x(i, j), i = 1, ni), j = 1, nj)
  write(10, *) ((y(i, j), i = 1, ni), j = 1, nj)
  write(10, *) ((z(i, j), i = 1, ni), j = 1, nj)
  close(10)
  ! 3D, stream access (no record markers; a C-style "binary" file)
  open(10, file=trim(dir)//'/f_3d_stream.x', form='unformatted', access='stream', status='replace')
  write(10) ni, nj, 1
  write(10) ((x(i, j), i = 1, ni), j = 1, nj), ((y(i, j), i = 1, ni), j = 1, nj), ((z(i, j), i = 1, ni), j = 1, nj)
  close(10)
end program plot3d_fortran
