// The table of orthogonality methods (registry.cpp), as solvers/registry.cpp
// is for solvers: the API looks methods up here and has no list of its own.
#pragma once
#include <array>
#include <memory>
#include <string>

#include "base/table.hpp"
#include "controls/control.hpp"

namespace eg2d {

struct OrthogonalityMethod {
    int id;                // EG2D_ORTHO_*
    const char *name;      // list name: "middlecoff-thomas"
    const char *constant;  // its name in eg2d.h, for messages
    // The control for the wall heights of eg2d_set_wall_spacing (per side,
    // < 0: not a wall); nullptr: no orthogonality control (remove it).
    std::unique_ptr<Control> (*make)(const std::array<double, 4> &wall_height);
};

Table<OrthogonalityMethod> orthogonality_table();
const OrthogonalityMethod *find_orthogonality(int id);  // nullptr: no such id
// "EG2D_ORTHO_NONE (0), ... or EG2D_ORTHO_WALL (2)": the valid ids, for messages.
std::string orthogonality_ids();

}  // namespace eg2d
