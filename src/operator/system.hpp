#pragma once

namespace eg2d {

// The elliptic systems of NUMERICS.md.
enum class System {
    Laplace = 0,  // Amsden-Hirt, seed 003 eq 4.1: linear
    Winslow = 1,  // Winslow / Thompson-Thames-Mastin with the control terms
};

const char *system_name(System s);

}  // namespace eg2d
