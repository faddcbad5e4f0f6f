! Line solvers of the heat_fv demo: the tridiagonal (Thomas) algorithm and its
! cyclic form for periodic lines (Sherman-Morrison), as used by
! line-by-line finite-volume codes.
!   -a(k) u(k-1) + b(k) u(k) - c(k) u(k+1) = d(k),   k = 1..n
! (tdma: a(1) and c(n) are ignored; cyclic_tdma: u(0) = u(n), u(n+1) = u(1)).
module tdma
  implicit none
  private
  integer, parameter :: dp = kind(1d0)
  public :: tdma_solve, cyclic_tdma_solve
contains
  subroutine tdma_solve(n, a, b, c, d, u)
    integer, intent(in) :: n
    real(dp), intent(in) :: a(n), b(n), c(n), d(n)
    real(dp), intent(out) :: u(n)
    real(dp) :: p(n), q(n), den
    integer :: k
    p(1) = c(1) / b(1)
    q(1) = d(1) / b(1)
    do k = 2, n
      den = b(k) - a(k) * p(k - 1)
      p(k) = c(k) / den
      q(k) = (d(k) + a(k) * q(k - 1)) / den
    end do
    u(n) = q(n)
    do k = n - 1, 1, -1
      u(k) = p(k) * u(k + 1) + q(k)
    end do
  end subroutine tdma_solve

  ! Sherman-Morrison: the cyclic matrix is T + w v^T with T tridiagonal.
  subroutine cyclic_tdma_solve(n, a, b, c, d, u)
    integer, intent(in) :: n
    real(dp), intent(in) :: a(n), b(n), c(n), d(n)
    real(dp), intent(out) :: u(n)
    real(dp) :: bb(n), w(n), z(n), gam, fact
    gam = b(1)
    bb = b
    bb(1) = b(1) + gam                 ! T(1,1) = b(1) - (-gam) ...
    bb(n) = b(n) + a(1) * c(n) / gam   ! ... so that T + w v^T has -a(1), -c(n) in the corners
    call tdma_solve(n, a, bb, c, d, u)
    w = 0
    w(1) = -gam
    w(n) = -c(n)
    call tdma_solve(n, a, bb, c, w, z)
    ! v = (1, 0, ..., 0, a(1)/gam)
    fact = (u(1) + a(1) * u(n) / gam) / (1 + z(1) + a(1) * z(n) / gam)
    u = u - fact * z
  end subroutine cyclic_tdma_solve
end module tdma
