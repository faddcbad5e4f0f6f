// Points of a curve on a grid side, in the direction the grid needs (the grid-generation lecture notes
// figure 1.13: opposite sides must run the same way).
#pragma once
#include <vector>

#include "generator/generator.hpp"
#include "geometry/curve.hpp"

namespace eg2d {

// n points at the normalized arc lengths of a distribution (distribution.hpp).
void curve_points(const ArcLength &curve, int n, int distribution, double p1, double p2, double *x, double *y);

enum SideCurveFlags { kCurveReverse = 1, kCurveOrient = 2, kCurveSliding = 4 };  // EG2D_CURVE_*

// Sets the side from the curve. Throws Boundary when the curve runs against
// the grid and flags do not allow reversing it; strong guarantee.
void set_side_curve(Generator &gen, Side side, const ArcLength &curve, int distribution, double p1, double p2,
                    int flags);

}  // namespace eg2d
