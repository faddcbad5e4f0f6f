// Whether two walls bound a channel: both run from the inlet to the outlet,
// the upper on the left of the lower, and the boundary they make with the
// straight inlet and outlet (lower, outlet, upper backwards, inlet) is a
// simple closed curve: no wall crosses itself, the other wall, the inlet or
// the outlet.
#pragma once

#include "channel_walls.hpp"

namespace eg2dtool {

// Failure(EXIT_GEOMETRY) naming what is wrong and where, else nothing.
void check_channel_walls(const Walls &walls);

}  // namespace eg2dtool
