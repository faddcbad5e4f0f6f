! The swan domain of the elliptic-grid course notes (A4) as the Fortran tests build it: the same
! formulas as tests/support/domains.c, points uniform in s = (i-1)/(n-1).
module swan_boundary
  use eg2d
  implicit none
  private
  public :: set_swan
contains
  subroutine set_swan(g, ni, nj, status)
    type(eg2d_grid_t), intent(inout) :: g
    integer, intent(in) :: ni, nj
    integer, intent(out) :: status
    real(eg2d_dp) :: s(max(ni, nj)), x(max(ni, nj)), y(max(ni, nj))
    integer :: i
    do i = 1, max(ni, nj)
      s(i) = real(i - 1, eg2d_dp)
    end do
    s(1:ni) = s(1:ni) / (ni - 1)
    x(1:ni) = s(1:ni); y(1:ni) = 0                                ! bottom y = 0
    call g%set_side(EG2D_SIDE_JMIN, x(1:ni), y(1:ni), status)
    if (status /= EG2D_OK) return
    y(1:ni) = 1 - 2 * s(1:ni) + 2 * s(1:ni) * s(1:ni)              ! top y = 1-2x+2x^2
    call g%set_side(EG2D_SIDE_JMAX, x(1:ni), y(1:ni), status)
    if (status /= EG2D_OK) return
    do i = 1, nj
      s(i) = real(i - 1, eg2d_dp) / (nj - 1)
    end do
    x(1:nj) = 1 + 2 * s(1:nj) - 2 * s(1:nj) * s(1:nj); y(1:nj) = s(1:nj)  ! right x = 1+2y-2y^2
    call g%set_side(EG2D_SIDE_IMAX, x(1:nj), y(1:nj), status)
    if (status /= EG2D_OK) return
    x(1:nj) = 0                                                   ! left x = 0
    call g%set_side(EG2D_SIDE_IMIN, x(1:nj), y(1:nj), status)
  end subroutine set_swan
end module swan_boundary
