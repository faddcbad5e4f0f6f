// Point distributions on [0, 1] (the grid-generation lecture notes section 2.5): s_k = s(u_k),
// u_k = k/(n-1), with s(0) = 0, s(1) = 1 and s increasing.
#pragma once
#include "base/table.hpp"

namespace eg2d {

// EG2D_DIST_*, by list name ("tanh2") and title ("two-sided tanh").
Table<NamedId> distribution_table();

// Fills s[0..n-1] for the EG2D_DIST_* id with parameters p1, p2. `length` is
// the length of the curve the points go on: Vinokur's p1, p2 are spacings in
// its units (for the unit interval, length = 1). Throws Argument with the
// parameter's name and allowed range.
void distribute(int id, int n, double p1, double p2, double length, double *s);

// The parameter p1 of EXPONENTIAL, TANH_ONE or TANH_TWO (with p2 = c) whose
// n points have s[1] - s[0] = first (a fraction of 1), to 1e-12 relative;
// VINOKUR's p1 is the spacing itself (checked with p2 as the last one).
// Throws Argument naming first_spacing and the reachable range when no
// parameter within its bound gives it.
double distribution_parameter(int id, int n, double first, double p2);

}  // namespace eg2d
