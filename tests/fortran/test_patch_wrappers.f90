! The boundary-patch wrappers of module eg2d (set_patch, clear_patches,
! get_patch_count, get_patch) on a 9 x 7 single block, good and bad paths.
program test_patch_wrappers
  use eg2d
  use checks
  implicit none
  type(eg2d_grid_t) :: g
  integer :: st, n, side, first, last, type
  character(len=40) :: name

  call g%create(9, 7)
  call g%get_patch_count(n)
  call check(n == 4, 'a single block has one default patch per side')
  call g%get_patch(3, side, first, last, type, name)
  call check(side == EG2D_SIDE_IMIN .and. first == 0 .and. last == 6 .and. type == EG2D_PATCH_WALL &
       .and. name == 'imin', 'the fourth is IMIN 0..6, a wall named imin')
  call g%set_patch(EG2D_SIDE_JMIN, 2, 5, EG2D_PATCH_SYMMETRY, 'axis', st)
  call check_status(st, EG2D_OK, 'set_patch JMIN 2..5 symmetry "axis"')
  call g%set_patch(EG2D_SIDE_JMIN, 4, 8, EG2D_PATCH_WALL, 'plate', st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'an overlapping patch')
  call check_contains(g%last_error(), 'overlap patch "axis" [2, 5]', 'its message')
  call g%get_patch_count(n)
  call check(n == 6, 'JMIN is jmin, axis, jmin: 6 stretches')
  call g%get_patch(1, side, first, last, type, name)
  call check(side == EG2D_SIDE_JMIN .and. first == 2 .and. last == 5 .and. type == EG2D_PATCH_SYMMETRY &
       .and. name == 'axis', 'the second stretch is the user''s')
  call g%get_patch(6, side, first, last, type, name, st)
  call check_status(st, EG2D_ERR_ARGUMENT, 'get_patch beyond the last')
  call g%clear_patches()
  call g%get_patch_count(n)
  call check(n == 4, 'clear_patches: the defaults again')
  call g%destroy()
  call checks_done('test_patch_wrappers')
end program test_patch_wrappers
