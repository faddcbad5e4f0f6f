// Lednicer's layout of an airfoil file: a line "NU NL" (the point counts of
// the two surfaces), then the upper surface from the leading edge to the
// trailing edge, then the lower one likewise.
#pragma once
#include <cstddef>
#include <vector>

#include "geometry/airfoil_outline.hpp"

namespace eg2d {

// True when the first point is farther from all the others than half their
// bounding box's diagonal: not a point of the outline they draw.
bool first_off_outline(const std::vector<OutlinePoint> &pts);

// True when the first point is Lednicer's counts: whole numbers > 1, off the
// outline the others draw (a Selig file's first point lies on it, however
// far the file is shifted), which starts near its leftmost x.
bool lednicer_counts(const std::vector<OutlinePoint> &pts);

// The surfaces after the counts pts[0], as one outline in Selig's order
// (upper from the trailing edge, then lower). Counts that disagree with the
// file (their sum, or where the second surface visibly starts: x jumps back
// to the leading edge) are refused, naming both and the line (lines[k] is
// pts[k]'s line number).
std::vector<OutlinePoint> lednicer_outline(const std::vector<OutlinePoint> &pts, const std::vector<std::size_t> &lines,
                                           const char *path);

}  // namespace eg2d
