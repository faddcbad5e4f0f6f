// Status strings, last-error text and the version.
#include <string>

#include "api/handle.hpp"

namespace eg2d {
namespace api {

namespace {
thread_local std::string thread_error;
}

void set_thread_error(const std::string &message) { thread_error = message; }

int status_of(Failure f) {
    switch (f) {
    case Failure::Argument: return EG2D_ERR_ARGUMENT;
    case Failure::Memory: return EG2D_ERR_MEMORY;
    case Failure::Boundary: return EG2D_ERR_BOUNDARY;
    case Failure::State: return EG2D_ERR_STATE;
    case Failure::NotConverged: return EG2D_ERR_NOT_CONVERGED;
    case Failure::Diverged: return EG2D_ERR_DIVERGED;
    case Failure::Folded: return EG2D_ERR_FOLDED;
    case Failure::Io: return EG2D_ERR_IO;
    case Failure::Unsupported: return EG2D_ERR_UNSUPPORTED;
    case Failure::Interrupted: return EG2D_ERR_INTERRUPTED;
    }
    return EG2D_ERR_ARGUMENT;
}

}  // namespace api
}  // namespace eg2d

extern "C" {

EG2D_API const char *eg2d_status_string(int status) {
    switch (status) {
    case EG2D_OK: return "EG2D_OK: success";
    case EG2D_ERR_ARGUMENT: return "EG2D_ERR_ARGUMENT: invalid argument";
    case EG2D_ERR_MEMORY: return "EG2D_ERR_MEMORY: out of memory";
    case EG2D_ERR_BOUNDARY: return "EG2D_ERR_BOUNDARY: inconsistent boundary";
    case EG2D_ERR_STATE: return "EG2D_ERR_STATE: call out of order";
    case EG2D_ERR_NOT_CONVERGED: return "EG2D_ERR_NOT_CONVERGED: iteration limit reached or no progress";
    case EG2D_ERR_DIVERGED: return "EG2D_ERR_DIVERGED: iteration diverged, grid restored";
    case EG2D_ERR_FOLDED: return "EG2D_ERR_FOLDED: grid has folded cells";
    case EG2D_ERR_IO: return "EG2D_ERR_IO: file error";
    case EG2D_ERR_UNSUPPORTED: return "EG2D_ERR_UNSUPPORTED: not built into this library";
    case EG2D_ERR_INTERRUPTED: return "EG2D_ERR_INTERRUPTED: stopped by the monitor";
    case EG2D_ERR_INTERNAL: return "EG2D_ERR_INTERNAL: internal error in eg2d";
    default: return "unknown eg2d status";
    }
}

EG2D_API const char *eg2d_last_error(const eg2d_grid *grid) {
    return grid ? grid->last_error.c_str() : eg2d::api::thread_error.c_str();
}

EG2D_API void eg2d_version(int *major, int *minor, int *patch) {
    if (major) *major = EG2D_VERSION_MAJOR;
    if (minor) *minor = EG2D_VERSION_MINOR;
    if (patch) *patch = EG2D_VERSION_PATCH;
}

}  // extern "C"
