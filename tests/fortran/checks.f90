! A minimal assertion module for the Fortran tests: every check prints a line,
! and checks_done() stops with a nonzero code if any failed.
module checks
  implicit none
  private
  public :: check, check_status, check_contains, checks_done
  integer, save :: failures = 0, passes = 0
contains
  subroutine check(ok, label)
    logical, intent(in) :: ok
    character(*), intent(in) :: label
    if (ok) then
      passes = passes + 1
    else
      failures = failures + 1
      print '("FAIL: ",a)', label
    end if
  end subroutine check

  subroutine check_status(got, want, label)
    integer, intent(in) :: got, want
    character(*), intent(in) :: label
    if (got /= want) print '("  status ",i0,", expected ",i0)', got, want
    call check(got == want, label)
  end subroutine check_status

  subroutine check_contains(text, part, label)
    character(*), intent(in) :: text, part
    character(*), intent(in) :: label
    if (index(text, part) == 0) print '("  message """,a,""" lacks """,a,"""")', text, part
    call check(index(text, part) > 0, label)
  end subroutine check_contains

  subroutine checks_done(name)
    character(*), intent(in) :: name
    print '(a,": ",i0," passed, ",i0," failed")', name, passes, failures
    if (failures > 0) error stop 1
  end subroutine checks_done
end module checks
