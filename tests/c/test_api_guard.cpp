// The C boundary's translation of exceptions (src/api/handle.hpp): the
// caller's bad input is EG2D_ERR_ARGUMENT, memory is EG2D_ERR_MEMORY, and a
// defect inside eg2d (any other exception) is EG2D_ERR_INTERNAL with an
// "internal error" message naming the call, never ARGUMENT or MEMORY.
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "api/handle.hpp"
#include "eg2d.h"

using namespace eg2d;

static int failures = 0, passes = 0;
static void check(bool ok, const char *what) {
    if (ok) {
        ++passes;
    } else {
        std::printf("FAILED: %s (last error \"%s\")\n", what, eg2d_last_error(nullptr));
        ++failures;
    }
}

template <class Body>
static void expect(Body &&body, int status, const char *message, const char *what) {
    const int got = api::guard_without_grid("eg2d_probe", body);
    check(got == status && std::strcmp(eg2d_last_error(nullptr), message) == 0, what);
}

int main() {
    expect([] { fail(Failure::Argument, "n = -1: must be >= 0"); }, EG2D_ERR_ARGUMENT,
           "eg2d_probe: n = -1: must be >= 0", "the caller's bad input");
    expect([] { throw std::bad_alloc(); }, EG2D_ERR_MEMORY, "eg2d_probe: out of memory", "bad_alloc");
    expect([] { throw std::length_error("vector::_M_default_append"); }, EG2D_ERR_MEMORY,
           "eg2d_probe: out of memory (a size beyond what can be allocated)", "length_error");
    expect([] { throw std::logic_error("a broken invariant"); }, EG2D_ERR_INTERNAL,
           "eg2d_probe: internal error: a broken invariant", "logic_error");
    expect([] { throw 42; }, EG2D_ERR_INTERNAL, "eg2d_probe: internal error: unknown exception", "not an exception");
    check(std::string(eg2d_status_string(EG2D_ERR_INTERNAL)).find("EG2D_ERR_INTERNAL") == 0, "its status string");
    // The grid-less helpers share the guard: an argument error there stays ARGUMENT.
    double u[4];
    check(eg2d_clustering_map(99, 0.5, 0.0, 1.0, 4, u) == EG2D_ERR_ARGUMENT, "eg2d_clustering_map's bad kind");
    std::printf("test_api_guard: %d passed, %d failed\n", passes, failures);
    return failures == 0 ? 0 : 1;
}
