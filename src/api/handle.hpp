// The C boundary. Each entry point checks its arguments, calls the core inside
// guard(), and guard() turns any exception into a status code and a message:
// nothing is thrown across the C interface, nothing aborts.
#pragma once
#include <array>
#include <cmath>
#include <new>
#include <string>

#include "core/error.hpp"
#include "core/generator.hpp"
#include "eg2d.h"

struct eg2d_grid {
    explicit eg2d_grid(int ni, int nj) : gen(ni, nj) {}
    eg2d::Generator gen;
    mutable std::string last_error;
    // Wall sides for EG2D_ORTHO_WALL (height; < 0: not a wall), kept across
    // eg2d_set_orthogonality calls.
    std::array<double, 4> wall_height{{-1.0, -1.0, -1.0, -1.0}};
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

// Runs body(); records the message of a failure on the grid (or, for a NULL
// grid, on the thread) as "function: message" and returns its code.
template <class Body>
int guard(const eg2d_grid *grid, const char *function, Body &&body) noexcept {
    std::string message;
    int status = EG2D_OK;
    try {
        if (!grid) fail(Failure::Argument, "grid is NULL");
        body();
        return EG2D_OK;
    } catch (const Error &e) {
        status = status_of(e.failure());
        message = e.what();
    } catch (const std::bad_alloc &) {
        status = EG2D_ERR_MEMORY;
        message = "out of memory";
    } catch (const std::exception &e) {
        status = EG2D_ERR_ARGUMENT;
        message = std::string("internal error: ") + e.what();
    } catch (...) {
        status = EG2D_ERR_ARGUMENT;
        message = "internal error: unknown exception";
    }
    try {
        const std::string text = std::string(function) + ": " + message;
        if (grid) grid->last_error = text;
        else set_thread_error(text);
    } catch (...) {
        // No memory for the message: the status code still says what happened.
    }
    return status;
}

}  // namespace api
}  // namespace eg2d
