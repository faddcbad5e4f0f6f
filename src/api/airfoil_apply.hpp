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

// The run an airfoil grid wants, for every one of its parameters the caller
// has not set: the tolerance 1e-10 and, on a C-grid, multigrid's V(1,2)
// cycle. On the NACA 0012 C-grids 385x97 to 3585x1025, V(2,1) needed as
// many cycles as the default W(2,1) in 20-35% less time, and V(1,2) as many
// again; at 7169x2049 V(1,2) took 6 cycles where V(2,1) took 9.
void airfoil_run_defaults(eg2d_grid *grid, int topology);

// After settings `next` replace the grid's: the last airfoil made again
// with them if its boundary is still the grid's, then the settings set
// (both or neither).
void set_settings_remaking_airfoil(eg2d_grid *grid, const Settings &next);

}  // namespace api
}  // namespace eg2d
