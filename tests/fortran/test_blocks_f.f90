! A set of blocks from Fortran (eg2d_blocks_t), as tests/c/test_blocks.c
! does in C: the unit square with a bulging top as one block and as two
! blocks joined down its middle solve to the same grid; a join whose node
! counts differ is refused with the message naming both ranges; the blocks'
! names read and set, a name another block has refused.
program test_blocks_f
  use eg2d
  use checks
  implicit none
  integer, parameter :: ni = 17, nj = 9, mid = 8
  real(eg2d_dp) :: s(ni), t(nj), x(ni, nj), y(ni, nj), xl(mid + 1, nj), yl(mid + 1, nj)
  real(eg2d_dp) :: xr(ni - mid, nj), yr(ni - mid, nj), residual, at, near
  integer :: i, b0, b1, it, unknowns, st
  type(eg2d_grid_t) :: one, left, right
  type(eg2d_blocks_t) :: set

  s = [((i - 1) / real(ni - 1, eg2d_dp), i = 1, ni)]
  t = [((i - 1) / real(nj - 1, eg2d_dp), i = 1, nj)]
  call square(one, s, t)
  call one%set_tolerance(1d-13)
  call one%solve()
  call one%get_coordinates(x, y)

  call square(left, s(1:mid + 1), t)
  call square(right, s(mid + 1:ni), t)
  call set%create()
  call set%add(left, b0)
  call set%add(right, b1)
  call check(b0 == 0 .and. b1 == 1, 'blocks numbered 0 and 1')
  call set%join(b0, EG2D_SIDE_IMAX, 0, 1, b1, EG2D_SIDE_IMIN, 0, 2, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'node counts that differ refused')
  call check_contains(set%last_error(), 'block 0 side IMAX nodes 0..1 has 2 nodes, block 1 side IMIN nodes 0..2 has 3', &
                      'the message names both ranges')
  call set%join(b0, EG2D_SIDE_IMAX, 0, nj - 1, b1, EG2D_SIDE_IMIN, 0, nj - 1)
  ! names: block0, block1 until named; the library's rule refused by name
  call check(set%name(b0) == 'block0' .and. set%name(b1) == 'block1', 'blocks named block0 and block1 until named')
  call set%set_name(b1, 'right-half')
  call set%set_name(b0, 'right-half', st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'a name another block has refused')
  call check_contains(set%last_error(), 'name "right-half": block 1 has that name', 'the message names the other block')
  call check(set%name(b0) == 'block0' .and. set%name(b1) == 'right-half' .and. set%name(2) == '', &
             'names read back; none for a block the set has not')
  call left%set_tolerance(1d-13)
  call set%solve()
  call set%get_run(it, residual, unknowns)
  call check(unknowns == (ni - 2) * (nj - 2) .and. residual <= 1d-13, 'every interior node once, converged')
  ! The bulge is symmetric about the join, where its lines turn most: the
  ! turn there is the single block's own (the grids are equal, below).
  call set%get_kinks(at, near)
  call check(at > 0 .and. near > 0 .and. at < 2 * near, 'the turns at the join and one node in measured')
  call left%get_coordinates(xl, yl)
  call right%get_coordinates(xr, yr)
  call check(maxval(abs(xl - x(1:mid + 1, :))) < 1d-9 .and. maxval(abs(yl - y(1:mid + 1, :))) < 1d-9 .and. &
             maxval(abs(xr - x(mid + 1:ni, :))) < 1d-9 .and. maxval(abs(yr - y(mid + 1:ni, :))) < 1d-9, &
             'the set is the single block''s grid')
  call set%destroy()
  call checks_done('test_blocks_f')

contains

  ! The unit square over [s(1), s(end)] with the top bulging up: y = 1 + x (1 - x) / 4.
  subroutine square(g, s, t)
    type(eg2d_grid_t), intent(inout) :: g
    real(eg2d_dp), intent(in) :: s(:), t(:)
    call g%create(size(s), size(t))
    call g%set_side(EG2D_SIDE_JMIN, s, 0 * s)
    call g%set_side(EG2D_SIDE_IMAX, 0 * t + s(size(s)), t * (1 + s(size(s)) * (1 - s(size(s))) / 4))
    call g%set_side(EG2D_SIDE_JMAX, s, 1 + s * (1 - s) / 4)
    call g%set_side(EG2D_SIDE_IMIN, 0 * t + s(1), t * (1 + s(1) * (1 - s(1)) / 4))
  end subroutine square
end program test_blocks_f
