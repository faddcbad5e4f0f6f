// The views of a grid: the whole domain, and for an airfoil grid the ones
// people look at, found from the grid itself so that any section, chord or
// position is framed alike: the section, 1.5 chords wide, and its leading
// and trailing edge, 0.05 chords wide. The section is the longest wall patch: its trailing
// edge the midpoint of the patch's two ends (one point on a C-grid or a
// sharp O-grid, the middle of a blunt base), its leading edge the wall
// node farthest from it, and the chord their distance.
#pragma once

#include <vector>

#include "view_lines.hpp"

namespace eg2dtool {

constexpr int kViewWidth = 800, kViewHeight = 600;  // the zoomed views' pictures

// The whole grid with a margin, kViewWidth pixels on its longer side.
View domain_view(const GridLines &g);

// domain, airfoil, le, te; Failure(EXIT_GEOMETRY) when the grid has no wall.
std::vector<View> airfoil_views(const GridLines &g);

}  // namespace eg2dtool
