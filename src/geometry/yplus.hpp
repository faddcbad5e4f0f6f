// The wall spacing that gives a target y+ (see yplus.cpp for the formula).
#pragma once

namespace eg2d {

// Throws Argument for y+ <= 0, Re outside [1e3, 1e9], chord <= 0.
double first_cell_height(double yplus, double reynolds, double chord);

}  // namespace eg2d
