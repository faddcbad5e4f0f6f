/* live_grids.c -- the count behind eg2d_live_grids() of module eg2d: grids
 * created through eg2d_grid_t and not yet freed (a test of finalisation).
 *
 * Grids are created and destroyed on several threads at once (eg2d.h,
 * "Threads": different handles from different threads), so the count is a
 * C11 atomic: a Fortran SAVE variable that create and destroy update would
 * be a data race. Standard Fortran has no atomic outside coarrays, and
 * OpenMP would be a dependency of every program using the module; a C11
 * atomic needs neither (the project builds C already). The module's only
 * shared state; hidden, not part of any ABI. */
#include <stdatomic.h>

static atomic_int live_grids;

#if defined(__GNUC__)
#  define HIDDEN __attribute__((visibility("hidden")))
#else
#  define HIDDEN
#endif

HIDDEN void eg2d_fortran_live_grids_add(int delta)
{
    atomic_fetch_add(&live_grids, delta);
}

HIDDEN int eg2d_fortran_live_grids(void)
{
    return atomic_load(&live_grids);
}
