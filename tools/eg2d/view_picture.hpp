// A view of a grid as the bytes of a picture file: SVG, written here, and
// PNG, drawn by cairo, an optional dependency of the command (never of the
// library): without it at configure time png_available() is false and
// view_png throws Failure(EXIT_UNSUPPORTED).
#pragma once

#include <string>
#include <vector>

#include "view_lines.hpp"

namespace eg2dtool {

// The viewBox is the view's window in the plane's units, y negated (SVG's y
// points down), so a reader finds the window from the file alone; stroke
// widths are the styles' pixels in those units.
std::string view_svg(const View &v, const std::vector<Polyline> &lines, const std::string &title);

bool png_available();
std::string view_png(const View &v, const std::vector<Polyline> &lines);

}  // namespace eg2dtool
