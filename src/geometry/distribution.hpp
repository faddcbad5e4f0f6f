// Point distributions on [0, 1] (seed 001 section 2.5): s_k = s(u_k),
// u_k = k/(n-1), with s(0) = 0, s(1) = 1 and s increasing.
#pragma once

namespace eg2d {

// Fills s[0..n-1] for the EG2D_DIST_* id with parameters p1, p2. `length` is
// the length of the curve the points go on: Vinokur's p1, p2 are spacings in
// its units (for the unit interval, length = 1). Throws Argument with the
// parameter's name and allowed range.
void distribute(int id, int n, double p1, double p2, double length, double *s);

}  // namespace eg2d
