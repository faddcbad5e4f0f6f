// The wall layer of each side a case gave a first-cell height, as the
// library measures it (eg2d_get_wall_layer), printed after the run; a layer
// that grows by more than the case's wall_growth_limit (1.2) within its first
// 30 cells, or that the library says needs more nodes, makes the command
// exit with EXIT_GEOMETRY, the files written, as `eg2d airfoil` does.
#pragma once
#include <string>
#include <vector>

#include "case_file.hpp"
#include "eg2d.h"

namespace eg2dtool {

// Prints the line of one wall side, named `name`, asked a first cell `height`;
// true when its layer grows by more than `limit` (then the node count the
// library says would do goes to stderr, "nj >= N" or "ni >= N"), or, with
// `first_off` > 0, when its median first cell is more than that factor off
// the height (a set's layer that could not be made: its run notes say why).
// Heights node by node: `height` the least and `most` the largest asked.
bool print_wall_layer(const eg2d_grid *g, int side, const std::string &name, double height, double limit,
                      double first_off = 0.0, double most = 0.0);

// Prints one line per wall side of `walls` (a case's, or a block's of a
// set: its name in `prefix`); true when some layer falls short.
bool print_wall_layers(const eg2d_grid *g, int topology, const std::vector<WallSpacing> &walls, double limit,
                       const std::string &prefix = "", double first_off = 0.0);

}  // namespace eg2dtool
