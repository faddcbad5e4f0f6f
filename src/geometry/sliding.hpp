// Sliding boundary points (Overture's slip-orthogonal condition): the nodes
// of a side move along its curve, keeping their order, to the foot of the
// perpendicular from their neighbour on the first interior line, so grid
// lines meet the side at right angles; the corners stay fixed.
#pragma once
#include <memory>

#include "geometry/curve.hpp"
#include "grid/boundary_motion.hpp"

namespace eg2d {

// The side's current points must be the curve's (eg2d_set_side_curve puts
// them there). Single-block sides only (throws Unsupported otherwise).
std::shared_ptr<const BoundaryMotion> make_sliding(const Grid &grid, Side side, const ArcLength &curve);

}  // namespace eg2d
