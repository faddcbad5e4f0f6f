#pragma once
#include "base/table.hpp"

namespace eg2d {

// The systems of NUMERICS.md: the equations the solvers drive to zero.
enum class System {
    Laplace = 0,      // Amsden-Hirt, the elliptic-grid course notes eq 4.1: linear
    Winslow = 1,      // Winslow / Thompson-Thames-Mastin with the control terms
    Variational = 2,  // the Euler-Lagrange equations of V = aA + bS + cO (variational.hpp)
};

const char *system_name(System s);  // for messages: "Winslow"
Table<NamedId> system_table();      // EG2D_SYSTEM_*, by list name: "winslow"

}  // namespace eg2d
