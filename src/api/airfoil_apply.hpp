// eg2d_set_airfoil's work, shared with eg2d_set_parameter: an AIRFOIL_*
// parameter set after it makes the airfoil's boundary again.
#pragma once
#include <memory>

#include "api/handle.hpp"

namespace eg2d {
namespace api {

// Makes the boundary of an airfoil grid round `section` with settings s
// and records it in grid->airfoil. Strong guarantee.
void apply_airfoil(eg2d_grid *grid, std::shared_ptr<const ArcLength> section, int topology, const Settings &s);

// After settings `next` replace the grid's: the last airfoil made again
// with them if its boundary is still the grid's, then the settings set
// (both or neither).
void set_settings_remaking_airfoil(eg2d_grid *grid, const Settings &next);

}  // namespace api
}  // namespace eg2d
