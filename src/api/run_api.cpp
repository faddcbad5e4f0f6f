// Monitor, iterate, solve.
#include <chrono>

#include "api/handle.hpp"

using namespace eg2d;
using namespace eg2d::api;

namespace {
// Times a run into the handle on every way out: a run that ends in
// NOT_CONVERGED or DIVERGED has still taken its time.
class RunClock {
public:
    explicit RunClock(eg2d_grid *grid) : grid_(grid), start_(std::chrono::steady_clock::now()) {}
    ~RunClock() { grid_->run_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    RunClock(const RunClock &) = delete;
    RunClock &operator=(const RunClock &) = delete;

private:
    eg2d_grid *grid_;
    std::chrono::steady_clock::time_point start_;
};
}  // namespace

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
        const RunClock clock(grid);
        grid->gen.iterate(iterations);
        if (residual) *residual = grid->gen.residual().value;
    });
}

EG2D_API int eg2d_solve(eg2d_grid *grid) {
    return guard(grid, "eg2d_solve", [&] {
        const RunClock clock(grid);
        grid->gen.solve();
    });
}

}  // extern "C"
