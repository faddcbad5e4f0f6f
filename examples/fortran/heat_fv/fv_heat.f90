! A cell-centred finite-volume solver for steady heat conduction
!     -div(k grad T) = f   on the cells of a structured curvilinear grid,
! written the way a line-by-line FV code (Phoenix, for which Petrilli's (1989)
! generator was made) is written: node arrays x(ni,nj), y(ni,nj) from the
! grid generator, cell values with a halo T(0:ncx+1, 0:ncy+1) that holds the
! Dirichlet values at boundary-face midpoints (or, across a periodic cut, the
! cells on the other side), face coefficients, and line-TDMA sweeps.
!
! Face flux with non-orthogonal correction. For a face with end nodes a, b
! (t = r_b - r_a), its normal S (|S| = |t|) pointing from the cell centre
! (or halo point) r_m to r_p, and d = r_p - r_m, split S = c d + B t:
!     c = |S|^2 / (S.d),   B = -c (d.t) / |t|^2,
!     grad T . S = c (T_p - T_m) + B (T_b - T_a).
! This is exact for linear T, whatever the skewness (d not parallel to S)
! and the offset of the face centre. c (T_p - T_m) is implicit (the usual
! five-point coefficients, symmetric); the cross-diffusion B (T_b - T_a) uses
! node values interpolated from the four cells around each node by a
! least-squares plane (exact for linear T), and is deferred: it is
! recomputed from the current T before every sweep (deferred correction).
! Boundary nodes take the Dirichlet values. Sources: f(centroid) * area.

module fv_heat
  use tdma
  use mms
  implicit none
  private
  integer, parameter :: dp = kind(1d0)
  public :: heat_solve, heat_cross_diffusion

  ! .false. drops the non-orthogonal correction (the B terms): only to show
  ! that without it the scheme is not even exact for linear T on skewed cells.
  logical, save :: cross_diffusion = .true.

  real(dp), parameter :: relax = 1.6_dp   ! over-relaxation of the line sweeps

contains

  subroutine heat_cross_diffusion(on)
    logical, intent(in) :: on
    cross_diffusion = on
  end subroutine heat_cross_diffusion

  ! Solves on the grid of nodes x(ni,nj), y(ni,nj): Dirichlet T = t_exact on
  ! the boundary, or periodic in i (an O-grid: node column ni is column 1).
  ! Out: cell values t(ncx,ncy), centroids xc, yc, areas, and the number of
  ! sweeps that brought the residual below tol times its start value.
  subroutine heat_solve(x, y, periodic, tol, t, xc, yc, area, sweeps)
    real(dp), intent(in) :: x(:, :), y(:, :), tol
    logical, intent(in) :: periodic
    real(dp), intent(out) :: t(:, :), xc(:, :), yc(:, :), area(:, :)
    integer, intent(out) :: sweeps
    integer :: ni, nj, ncx, ncy, i, j
    real(dp), allocatable :: px(:, :), py(:, :), tc(:, :), tn(:, :), w(:, :, :)
    real(dp), allocatable :: ci(:, :), bi(:, :), cj(:, :), bj(:, :), fa(:, :), su(:, :)
    real(dp) :: r0, r

    ni = size(x, 1); nj = size(x, 2); ncx = ni - 1; ncy = nj - 1
    allocate (px(0:ncx + 1, 0:ncy + 1), py(0:ncx + 1, 0:ncy + 1), tc(0:ncx + 1, 0:ncy + 1))
    allocate (tn(ni, nj), w(4, ni, nj), fa(ncx, ncy), su(ncx, ncy))
    allocate (ci(ncx + 1, ncy), bi(ncx + 1, ncy), cj(ncx, ncy + 1), bj(ncx, ncy + 1))

    call cell_geometry(x, y, xc, yc, area)
    call halo_points(x, y, xc, yc, periodic, px, py)
    call face_coefficients(x, y, px, py, ci, bi, cj, bj)
    if (.not. cross_diffusion) then
      bi = 0
      bj = 0
    end if
    call node_weights(x, y, px, py, periodic, w)

    tc = 0
    do j = 0, ncy + 1       ! Dirichlet values in the halo (corners unused)
      do i = 0, ncx + 1
        if (i == 0 .or. j == 0 .or. i == ncx + 1 .or. j == ncy + 1) tc(i, j) = t_exact(px(i, j), py(i, j))
      end do
    end do
    do j = 1, ncy
      do i = 1, ncx
        fa(i, j) = f_of(xc(i, j), yc(i, j)) * area(i, j)
      end do
    end do

    r0 = -1
    do sweeps = 1, 200000
      if (periodic) call wrap(tc)
      call node_values(x, y, tc, w, periodic, tn)
      call sources(fa, tn, bi, bj, su)
      r = residual_norm(tc, su, ci, cj)
      if (r0 < 0) r0 = max(r, tiny(1d0))
      if (r <= tol * r0) exit
      call sweep_i_lines(tc, su, ci, cj, periodic)
      if (periodic) call wrap(tc)
      call sweep_j_lines(tc, su, ci, cj)
    end do
    t = tc(1:ncx, 1:ncy)
  end subroutine heat_solve

  ! Areas (positive) and centroids of the quadrilateral cells.
  subroutine cell_geometry(x, y, xc, yc, area)
    real(dp), intent(in) :: x(:, :), y(:, :)
    real(dp), intent(out) :: xc(:, :), yc(:, :), area(:, :)
    real(dp) :: qx(5), qy(5), cr, a, sx, sy
    integer :: i, j, k
    do j = 1, size(x, 2) - 1
      do i = 1, size(x, 1) - 1
        qx = [x(i, j), x(i + 1, j), x(i + 1, j + 1), x(i, j + 1), x(i, j)]
        qy = [y(i, j), y(i + 1, j), y(i + 1, j + 1), y(i, j + 1), y(i, j)]
        a = 0; sx = 0; sy = 0
        do k = 1, 4
          cr = qx(k) * qy(k + 1) - qx(k + 1) * qy(k)
          a = a + cr / 2
          sx = sx + (qx(k) + qx(k + 1)) * cr
          sy = sy + (qy(k) + qy(k + 1)) * cr
        end do
        area(i, j) = abs(a)
        xc(i, j) = sx / (6 * a)
        yc(i, j) = sy / (6 * a)
      end do
    end do
  end subroutine cell_geometry

  ! Cell points with halo: centroids inside; boundary-face midpoints in the
  ! halo, or across a periodic cut the centroids of the cells on the other side.
  subroutine halo_points(x, y, xc, yc, periodic, px, py)
    real(dp), intent(in) :: x(:, :), y(:, :), xc(:, :), yc(:, :)
    logical, intent(in) :: periodic
    real(dp), intent(out) :: px(0:, 0:), py(0:, 0:)
    integer :: ni, nj, ncx, ncy
    ni = size(x, 1); nj = size(x, 2); ncx = ni - 1; ncy = nj - 1
    px = 0; py = 0
    px(1:ncx, 1:ncy) = xc; py(1:ncx, 1:ncy) = yc
    px(1:ncx, 0) = (x(1:ncx, 1) + x(2:ni, 1)) / 2
    py(1:ncx, 0) = (y(1:ncx, 1) + y(2:ni, 1)) / 2
    px(1:ncx, ncy + 1) = (x(1:ncx, nj) + x(2:ni, nj)) / 2
    py(1:ncx, ncy + 1) = (y(1:ncx, nj) + y(2:ni, nj)) / 2
    if (periodic) then
      px(0, 1:ncy) = xc(ncx, :); py(0, 1:ncy) = yc(ncx, :)
      px(ncx + 1, 1:ncy) = xc(1, :); py(ncx + 1, 1:ncy) = yc(1, :)
    else
      px(0, 1:ncy) = (x(1, 1:ncy) + x(1, 2:nj)) / 2
      py(0, 1:ncy) = (y(1, 1:ncy) + y(1, 2:nj)) / 2
      px(ncx + 1, 1:ncy) = (x(ni, 1:ncy) + x(ni, 2:nj)) / 2
      py(ncx + 1, 1:ncy) = (y(ni, 1:ncy) + y(ni, 2:nj)) / 2
    end if
  end subroutine halo_points

  ! k c and k B of every face (see the header): i-faces ci(i,j) between
  ! cells (i-1,j) and (i,j), with nodes (i,j), (i,j+1); j-faces cj(i,j)
  ! between (i,j-1) and (i,j), with nodes (i,j), (i+1,j).
  subroutine face_coefficients(x, y, px, py, ci, bi, cj, bj)
    real(dp), intent(in) :: x(:, :), y(:, :), px(0:, 0:), py(0:, 0:)
    real(dp), intent(out) :: ci(:, :), bi(:, :), cj(:, :), bj(:, :)
    integer :: i, j
    do j = 1, size(ci, 2)
      do i = 1, size(ci, 1)
        call face(x(i, j), y(i, j), x(i, j + 1), y(i, j + 1), px(i - 1, j), py(i - 1, j), &
                  px(i, j), py(i, j), ci(i, j), bi(i, j))
      end do
    end do
    do j = 1, size(cj, 2)
      do i = 1, size(cj, 1)
        call face(x(i, j), y(i, j), x(i + 1, j), y(i + 1, j), px(i, j - 1), py(i, j - 1), &
                  px(i, j), py(i, j), cj(i, j), bj(i, j))
      end do
    end do
  end subroutine face_coefficients

  subroutine face(xa, ya, xb, yb, xm, ym, xp, yp, coef, cross)
    real(dp), intent(in) :: xa, ya, xb, yb, xm, ym, xp, yp
    real(dp), intent(out) :: coef, cross
    real(dp) :: tx, ty, sx, sy, dx, dy, c, kf
    tx = xb - xa; ty = yb - ya
    sx = ty; sy = -tx
    dx = xp - xm; dy = yp - ym
    if (sx * dx + sy * dy < 0) then
      sx = -sx; sy = -sy
    end if
    c = (sx * sx + sy * sy) / (sx * dx + sy * dy)
    kf = k_of((xa + xb) / 2, (ya + yb) / 2)
    coef = kf * c
    cross = -kf * c * (dx * tx + dy * ty) / (tx * tx + ty * ty)
  end subroutine face

  ! Least-squares-plane weights of the four cells around each interior node:
  ! T_node = sum w(k) T(cell k), cells (i-1,j-1), (i,j-1), (i-1,j), (i,j).
  subroutine node_weights(x, y, px, py, periodic, w)
    real(dp), intent(in) :: x(:, :), y(:, :), px(0:, 0:), py(0:, 0:)
    logical, intent(in) :: periodic
    real(dp), intent(out) :: w(:, :, :)
    real(dp) :: dx(4), dy(4), m(3, 3), z(3), det
    integer :: i, j, k, ci(4), cj(4)
    w = 0
    do j = 2, size(x, 2) - 1
      do i = 1, size(x, 1)
        if (.not. periodic .and. (i == 1 .or. i == size(x, 1))) cycle
        ci = [i - 1, i, i - 1, i]; cj = [j - 1, j - 1, j, j]
        do k = 1, 4
          dx(k) = px(ci(k), cj(k)) - x(i, j)
          dy(k) = py(ci(k), cj(k)) - y(i, j)
        end do
        m(1, :) = [4.0_dp, sum(dx), sum(dy)]
        m(2, :) = [sum(dx), sum(dx * dx), sum(dx * dy)]
        m(3, :) = [sum(dy), sum(dx * dy), sum(dy * dy)]
        ! z = first column of m^-1 (m is symmetric): cofactors of row 1.
        det = m(1, 1) * (m(2, 2) * m(3, 3) - m(2, 3) * m(3, 2)) &
            - m(1, 2) * (m(2, 1) * m(3, 3) - m(2, 3) * m(3, 1)) &
            + m(1, 3) * (m(2, 1) * m(3, 2) - m(2, 2) * m(3, 1))
        z(1) = (m(2, 2) * m(3, 3) - m(2, 3) * m(3, 2)) / det
        z(2) = -(m(2, 1) * m(3, 3) - m(2, 3) * m(3, 1)) / det
        z(3) = (m(2, 1) * m(3, 2) - m(2, 2) * m(3, 1)) / det
        w(:, i, j) = z(1) + z(2) * dx + z(3) * dy
      end do
    end do
  end subroutine node_weights

  ! Node values: the Dirichlet values on the boundary, planes inside.
  subroutine node_values(x, y, tc, w, periodic, tn)
    real(dp), intent(in) :: x(:, :), y(:, :), tc(0:, 0:), w(:, :, :)
    logical, intent(in) :: periodic
    real(dp), intent(out) :: tn(:, :)
    integer :: i, j, ni, nj
    ni = size(x, 1); nj = size(x, 2)
    do j = 1, nj
      do i = 1, ni
        if (j == 1 .or. j == nj .or. (.not. periodic .and. (i == 1 .or. i == ni))) then
          tn(i, j) = t_exact(x(i, j), y(i, j))
        else
          tn(i, j) = w(1, i, j) * tc(i - 1, j - 1) + w(2, i, j) * tc(i, j - 1) &
                   + w(3, i, j) * tc(i - 1, j) + w(4, i, j) * tc(i, j)
        end if
      end do
    end do
  end subroutine node_values

  ! su = f A minus the net deferred cross-diffusion flux out of the cell.
  subroutine sources(fa, tn, bi, bj, su)
    real(dp), intent(in) :: fa(:, :), tn(:, :), bi(:, :), bj(:, :)
    real(dp), intent(out) :: su(:, :)
    integer :: i, j
    do j = 1, size(su, 2)
      do i = 1, size(su, 1)
        su(i, j) = fa(i, j) &
             + bi(i + 1, j) * (tn(i + 1, j + 1) - tn(i + 1, j)) - bi(i, j) * (tn(i, j + 1) - tn(i, j)) &
             + bj(i, j + 1) * (tn(i + 1, j + 1) - tn(i, j + 1)) - bj(i, j) * (tn(i + 1, j) - tn(i, j))
      end do
    end do
  end subroutine sources

  ! || su - (aP T_P - sum a_nb T_nb) ||_2 with the current cross terms.
  real(dp) function residual_norm(tc, su, ci, cj) result(r)
    real(dp), intent(in) :: tc(0:, 0:), su(:, :), ci(:, :), cj(:, :)
    integer :: i, j
    real(dp) :: res
    r = 0
    do j = 1, size(su, 2)
      do i = 1, size(su, 1)
        res = su(i, j) - (ci(i, j) + ci(i + 1, j) + cj(i, j) + cj(i, j + 1)) * tc(i, j) &
             + ci(i, j) * tc(i - 1, j) + ci(i + 1, j) * tc(i + 1, j) &
             + cj(i, j) * tc(i, j - 1) + cj(i, j + 1) * tc(i, j + 1)
        r = r + res * res
      end do
    end do
    r = sqrt(r)
  end function residual_norm

  subroutine wrap(tc)
    real(dp), intent(inout) :: tc(0:, 0:)
    integer :: ncx
    ncx = size(tc, 1) - 2
    tc(0, :) = tc(ncx, :)
    tc(ncx + 1, :) = tc(1, :)
  end subroutine wrap

  ! Lines of constant j, solved for T(1:ncx, j) (cyclic when periodic).
  subroutine sweep_i_lines(tc, su, ci, cj, periodic)
    real(dp), intent(inout) :: tc(0:, 0:)
    real(dp), intent(in) :: su(:, :), ci(:, :), cj(:, :)
    logical, intent(in) :: periodic
    real(dp) :: a(size(su, 1)), b(size(su, 1)), c(size(su, 1)), d(size(su, 1)), u(size(su, 1))
    integer :: j, n
    n = size(su, 1)
    do j = 1, size(su, 2)
      a = ci(1:n, j); c = ci(2:n + 1, j)
      b = a + c + cj(:, j) + cj(:, j + 1)
      d = su(:, j) + cj(:, j) * tc(1:n, j - 1) + cj(:, j + 1) * tc(1:n, j + 1)
      if (periodic) then
        call cyclic_tdma_solve(n, a, b, c, d, u)
      else
        d(1) = d(1) + a(1) * tc(0, j)
        d(n) = d(n) + c(n) * tc(n + 1, j)
        call tdma_solve(n, a, b, c, d, u)
      end if
      tc(1:n, j) = tc(1:n, j) + relax * (u - tc(1:n, j))
    end do
  end subroutine sweep_i_lines

  ! Lines of constant i, solved for T(i, 1:ncy).
  subroutine sweep_j_lines(tc, su, ci, cj)
    real(dp), intent(inout) :: tc(0:, 0:)
    real(dp), intent(in) :: su(:, :), ci(:, :), cj(:, :)
    real(dp) :: a(size(su, 2)), b(size(su, 2)), c(size(su, 2)), d(size(su, 2)), u(size(su, 2))
    integer :: i, n
    n = size(su, 2)
    do i = 1, size(su, 1)
      a = cj(i, 1:n); c = cj(i, 2:n + 1)
      b = a + c + ci(i, :) + ci(i + 1, :)
      d = su(i, :) + ci(i, :) * tc(i - 1, 1:n) + ci(i + 1, :) * tc(i + 1, 1:n)
      d(1) = d(1) + a(1) * tc(i, 0)
      d(n) = d(n) + c(n) * tc(i, n + 1)
      call tdma_solve(n, a, b, c, d, u)
      tc(i, 1:n) = tc(i, 1:n) + relax * (u - tc(i, 1:n))
    end do
  end subroutine sweep_j_lines
end module fv_heat
