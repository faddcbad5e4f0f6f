// The set-of-blocks handle (eg2d_blocks): the core's BlockSet over the
// grids' generators, the grids themselves (to tell them when the set goes)
// and the set's own last error.
#pragma once
#include <string>
#include <vector>

#include "api/handle.hpp"
#include "blocks/block_set.hpp"
#include "blocks/set_solve.hpp"

struct eg2d_blocks {
    eg2d::BlockSet set;
    std::vector<eg2d_grid *> grids;  // nullptr: destroyed
    mutable std::string last_error;
    bool ran = false;
    eg2d::SetRun run;
};

namespace eg2d {
namespace api {

// eg2d_destroy: the grid leaves every set it is in (they refuse to run).
void forget_in_sets(eg2d_grid *grid) noexcept;

// guard() for a set: the message goes to the set (or the thread for NULL).
template <class Body>
int guard_set(const eg2d_blocks *set, const char *function, Body &&body) noexcept {
    std::string message;
    const int status = capture(message, [&] {
        if (!set) fail(Failure::Argument, "set is NULL");
        body();
    });
    if (status == EG2D_OK) return status;
    try {
        const std::string text = std::string(function) + ": " + message;
        if (set) set->last_error = text;
        else set_thread_error(text);
    } catch (...) {
    }
    return status;
}

}  // namespace api
}  // namespace eg2d
