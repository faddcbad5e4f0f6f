#pragma once

namespace eg2d {

// The systems of NUMERICS.md: the equations the solvers drive to zero.
enum class System {
    Laplace = 0,      // Amsden-Hirt, the elliptic-grid course notes eq 4.1: linear
    Winslow = 1,      // Winslow / Thompson-Thames-Mastin with the control terms
    Variational = 2,  // the Euler-Lagrange equations of V = aA + bS + cO (variational.hpp)
};

const char *system_name(System s);

}  // namespace eg2d
