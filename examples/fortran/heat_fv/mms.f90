! The manufactured problem of the heat_fv demo: a smooth temperature T, a
! variable conductivity k > 0, and the heat source f = -div(k grad T) that
! makes T the exact solution of -div(k grad T) = f.
!   T = exp(x/2) sin(2y + 1) + x y,      k = 3/2 + sin(x) cos(y)
! (case 'linear': T = 1 + 2x - 3y, k = 1, f = 0, which a consistent scheme
! reproduces to round-off on any grid: the patch test.)
module mms
  implicit none
  private
  integer, parameter :: dp = kind(1d0)
  public :: mms_case, t_exact, k_of, f_of
  logical, save :: linear = .false.
contains
  subroutine mms_case(name)
    character(*), intent(in) :: name
    linear = name == 'linear'
  end subroutine mms_case

  real(dp) function t_exact(x, y)
    real(dp), intent(in) :: x, y
    if (linear) then
      t_exact = 1 + 2 * x - 3 * y
    else
      t_exact = exp(x / 2) * sin(2 * y + 1) + x * y
    end if
  end function t_exact

  real(dp) function k_of(x, y)
    real(dp), intent(in) :: x, y
    if (linear) then
      k_of = 1
    else
      k_of = 1.5_dp + sin(x) * cos(y)
    end if
  end function k_of

  ! f = -(k_x T_x + k_y T_y + k (T_xx + T_yy))
  real(dp) function f_of(x, y)
    real(dp), intent(in) :: x, y
    real(dp) :: tx, ty, lap, kx, ky
    if (linear) then
      f_of = 0
      return
    end if
    tx = exp(x / 2) * sin(2 * y + 1) / 2 + y
    ty = 2 * exp(x / 2) * cos(2 * y + 1) + x
    lap = (0.25_dp - 4) * exp(x / 2) * sin(2 * y + 1)
    kx = cos(x) * cos(y)
    ky = -sin(x) * sin(y)
    f_of = -(kx * tx + ky * ty + k_of(x, y) * lap)
  end function f_of
end module mms
