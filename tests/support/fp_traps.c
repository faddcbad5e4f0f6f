/* Linked into every C test program: invalid, divide-by-zero and overflow
 * traps on from the start, so any library call that raises one of these
 * flags on valid input dies with SIGFPE where it happens (as
 * Fortran hosts built with -ffpe-trap do). Inexact and underflow stay
 * off: they are raised by ordinary rounding. */
#define _GNU_SOURCE
#include "fp_traps.h"

#include <fenv.h>

__attribute__((constructor)) static void eg2d_test_fp_traps(void) {
    feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
}

int fp_traps_pause(void) { return fedisableexcept(FE_ALL_EXCEPT); }

void fp_traps_resume(int paused) {
    feclearexcept(FE_ALL_EXCEPT);
    if (paused != -1) feenableexcept(paused);
}
