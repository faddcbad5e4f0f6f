// Initial-grid methods, selected by their EG2D_INIT_* id. Adding one is adding
// a file with its function and a line in initializers.cpp.
#pragma once
#include "base/settings.hpp"
#include "base/grid.hpp"
#include "base/table.hpp"

namespace eg2d {

struct InitMethod {
    int id;             // EG2D_INIT_*
    const char *name;
    // Fills the interior (and the O-grid cut) of a grid whose boundary is
    // complete. May throw; callers run it on a copy.
    void (*fill)(Grid &grid, const Settings &settings);
    // A marching method needs only JMIN and writes every other node, its
    // sides included: the grid it makes becomes the boundary.
    bool marches = false;
};

Table<InitMethod> init_method_table();
// nullptr if no method has that id.
const InitMethod *find_init_method(int id);

void tfi_linear(Grid &grid, const Settings &settings);   // tfi.cpp
void tfi_hermite(Grid &grid, const Settings &settings);  // tfi_hermite.cpp
// At the sides settings.hermite_sides chooses (tfi_hermite_sides.cpp);
// tfi_hermite hands over to it when the mask is not 0.
void tfi_hermite_sides(Grid &grid, const Settings &settings);
void hyperbolic_march(Grid &grid, const Settings &settings);  // hyperbolic.cpp

// A filling method through the grid's fixed interior lines: each sub-block
// between them filled as a grid of its own (tfi_blocks.cpp); without lines,
// fill itself.
void fill_blocks(Grid &grid, const Settings &settings, void (*fill)(Grid &, const Settings &));

}  // namespace eg2d
