// An airfoil's points as a file gives them (any direction, any start) put in
// the one order the library's sections have (make_naca4): from the trailing
// edge along the lower surface to the leading edge and back along the upper,
// clockwise, a sharp trailing edge's point first and last.
#pragma once
#include <cstddef>
#include <vector>

namespace eg2d {

struct OutlinePoint { double x, y; };

struct Outline {
    std::vector<double> x, y;   // the normalised points
    std::size_t duplicates = 0; // repeated consecutive points dropped (a closing point doubled)
};

// Throws Argument (naming `path`) for fewer than 4 distinct points or an
// outline that encloses no area.
Outline normalise_outline(std::vector<OutlinePoint> pts, const char *path);

}  // namespace eg2d
