// The wall layer of each side a case gave a first-cell height, as the
// library measures it (eg2d_get_wall_layer), printed after the run; a layer
// that grows by more than the case's wall_growth_limit (1.2) within its first
// 30 cells, or that the library says needs more nodes, makes the command
// exit with EXIT_GEOMETRY, the files written, as `eg2d airfoil` does.
#pragma once
#include "case_file.hpp"
#include "eg2d.h"

namespace eg2dtool {

// Prints one line per wall side; true when some layer falls short.
bool print_wall_layers(const eg2d_grid *g, const Case &c);

}  // namespace eg2dtool
