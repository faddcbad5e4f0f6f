// Monitor, iterate, solve.
#include "api/handle.hpp"

using namespace eg2d;
using namespace eg2d::api;

extern "C" {

EG2D_API int eg2d_set_monitor(eg2d_grid *grid, eg2d_monitor_fn fn, void *user) {
    return guard(grid, "eg2d_set_monitor", [&] {
        if (!fn) {
            grid->gen.monitor = nullptr;
            return;
        }
        grid->gen.monitor = [fn, user](int iteration, double residual) { return fn(user, iteration, residual) != 0; };
    });
}

EG2D_API int eg2d_iterate(eg2d_grid *grid, int iterations, double *residual) {
    return guard(grid, "eg2d_iterate", [&] {
        require(iterations >= 0, format("iterations = %d: must be >= 0", iterations));
        grid->gen.iterate(iterations);
        if (residual) *residual = grid->gen.residual().value;
    });
}

EG2D_API int eg2d_solve(eg2d_grid *grid) {
    return guard(grid, "eg2d_solve", [&] { grid->gen.solve(); });
}

}  // extern "C"
