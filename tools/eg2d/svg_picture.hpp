// A minimal SVG picture of the grid lines, used only until the library has
// eg2d_write(..., EG2D_FORMAT_SVG); then this file goes (one SVG writer, not two).
#pragma once

#include <string>
#include <vector>

namespace eg2dtool {

// Writes to path + ".tmp" and renames, so no half-written file ever has the name.
// Returns an empty string, or the system's reason for failing.
std::string write_svg_picture(const std::string &path, int ni, int nj, const std::vector<double> &x,
                              const std::vector<double> &y);

}  // namespace eg2dtool
