! `eg2d airfoil`'s grid from a Fortran program: the NACA 0012 C-grid at y+ 1
! for a chord Reynolds number of 6e6, written as Plot3D, node for node the
! command's file (tests/examples_match_command.sh compares them):
!   eg2d airfoil 0012 --size NIxNJ --yplus 1 --reynolds 6e6 --format plot3d
! Usage: command_grid_fortran NI NJ FILE.xyz
program command_grid
  use, intrinsic :: iso_c_binding, only: c_double
  use eg2d
  implicit none
  type(eg2d_grid_t) :: g
  type(eg2d_curve_t) :: section
  character(len=256) :: arg, path
  integer :: ni, nj, cut
  real(c_double) :: re, cf, h
  call get_command_argument(1, arg); read (arg, *) ni
  call get_command_argument(2, arg); read (arg, *) nj
  call get_command_argument(3, path)
  ! the first cell from y+ by Cf = (2 log10(Re) - 0.65)^-2.3 (Schlichting 1979), as the command
  re = 6d6
  cf = (2 * log10(re) - 0.65d0)**(-2.3d0)
  h = 1 / (re * sqrt(cf / 2))
  call section%naca4('0012')
  call g%create(ni, nj)
  ! the section (with an airfoil grid's run: tolerance, cycle) and the wall's first cell, as the command
  call g%set_airfoil(section, EG2D_TOPO_C)
  call g%set_wall_spacing(EG2D_SIDE_JMIN, h)
  call g%solve()                        ! stops with the library's message on failure
  call g%write(trim(path), EG2D_FORMAT_PLOT3D)
  call g%get_cut(cut)
  print '(a,i0,a,i0,a,i0,a)', 'NACA 0012 C-grid ', ni, 'x', nj, ', ', cut, ' cut nodes a side, written'
end program command_grid
