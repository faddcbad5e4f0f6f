// The C boundary. Each entry point checks its arguments, calls the core inside
// guard(), and guard() turns any exception into a status code and a message:
// nothing is thrown across the C interface, nothing aborts.
#pragma once
#include <array>
#include <cmath>
#include <memory>
#include <new>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "generator/generator.hpp"
#include "geometry/curve.hpp"
#include "eg2d.h"

struct eg2d_grid {
    explicit eg2d_grid(int ni, int nj) : gen(ni, nj) {}
    eg2d::Generator gen;
    mutable std::string last_error;
    // Wall sides for EG2D_ORTHO_WALL (height; < 0: not a wall), kept across
    // eg2d_set_orthogonality calls.
    std::array<double, 4> wall_height{{-1.0, -1.0, -1.0, -1.0}};
    // Wall-clock seconds of the last eg2d_iterate/eg2d_solve (for the report formats).
    double run_seconds = 0.0;
    // The last eg2d_set_airfoil: its section, topology and the boundary it
    // made. An EG2D_PARAM_AIRFOIL_* set afterwards makes it again while the
    // boundary is still that one (the settings act whatever their order).
    struct Airfoil {
        std::shared_ptr<const eg2d::ArcLength> section;
        int topology = 0;
        std::vector<double> x, y;
    } airfoil;
    // The EG2D_PARAM_* ids the caller has set: eg2d_set_airfoil's run
    // defaults (airfoil_apply.hpp) leave them as they are.
    std::set<int> set_by_caller;
    // The sets of blocks this grid is in (blocks_api.cpp): told when it is destroyed.
    std::vector<struct eg2d_blocks *> sets;
};

namespace eg2d {
namespace api {

int status_of(Failure f);
// The calling thread's last error, for calls that had no grid to record it in.
void set_thread_error(const std::string &message);

inline void require(bool ok, const std::string &message) {
    if (!ok) fail(Failure::Argument, message);
}
inline void require_ptr(const void *p, const char *name) {
    if (!p) fail(Failure::Argument, format("%s is NULL", name));
}
inline void require_finite(double v, const char *name) {
    if (!std::isfinite(v)) fail(Failure::Argument, format("%s = %g: must be finite", name, v));
}

// Runs body() and turns an exception into a status and a message.
template <class Body>
int capture(std::string &message, Body &&body) noexcept {
    try {
        body();
        return EG2D_OK;
    } catch (const Error &e) {
        message = e.what();
        return status_of(e.failure());
    } catch (const std::bad_alloc &) {
        message = "out of memory";
        return EG2D_ERR_MEMORY;
    } catch (const std::length_error &) {  // a container asked for more than it can hold
        message = "out of memory (a size beyond what can be allocated)";
        return EG2D_ERR_MEMORY;
    } catch (const std::exception &e) {
        message = std::string("internal error: ") + e.what();
    } catch (...) {
        message = "internal error: unknown exception";
    }
    // Not the caller's input: a caller can tell a defect from bad arguments.
    return EG2D_ERR_INTERNAL;
}

// Runs body(); records the message of a failure on the grid (or, for a NULL
// grid, on the thread) as "function: message" and returns its code.
template <class Body>
int guard(const eg2d_grid *grid, const char *function, Body &&body) noexcept {
    std::string message;
    const int status = capture(message, [&] {
        if (!grid) fail(Failure::Argument, "grid is NULL");
        body();
    });
    if (status == EG2D_OK) return status;
    try {
        const std::string text = std::string(function) + ": " + message;
        if (grid) grid->last_error = text;
        else set_thread_error(text);
    } catch (...) {
        // No memory for the message: the status code still says what happened.
    }
    return status;
}

// The same for a call that has no grid (file readers): the message goes to
// the thread, for eg2d_last_error(NULL).
template <class Body>
int guard_without_grid(const char *function, Body &&body) noexcept {
    std::string message;
    const int status = capture(message, body);
    if (status == EG2D_OK) return status;
    try {
        set_thread_error(std::string(function) + ": " + message);
    } catch (...) {
    }
    return status;
}

}  // namespace api
}  // namespace eg2d
