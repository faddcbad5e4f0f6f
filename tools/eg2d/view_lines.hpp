// A view of a grid: a window of the plane drawn into width x height pixels,
// and the grid's lines cut to it. Only what the window shows is kept, so a
// zoomed view of a large grid stays small: segments outside are dropped,
// segments across the edge are clipped to it (Liang-Barsky), and a point
// is left out where the line drawn without it moves by less than a third of
// a pixel (most of a wall-resolved grid's nodes, seen from afar).
#pragma once

#include <string>
#include <vector>

#include "grid_lines.hpp"

namespace eg2dtool {

struct View {
    std::string name;                // what it shows, the file's suffix: domain, airfoil, le, te
    double xmin, ymin, xmax, ymax;   // the window, with the picture's aspect ratio
    int width, height;               // the picture, pixels
    double pixel() const { return (xmax - xmin) / width; }  // plane units per pixel
};

// A view of the window (x0, y0)-(x1, y1) grown to the aspect ratio of
// width x height about its centre.
View fitted_view(const std::string &name, double x0, double y0, double x1, double y1, int width, int height);

struct Polyline {
    LineKind kind;
    std::vector<double> xy;  // x0, y0, x1, y1, ... in the plane, inside the window
};

// The lines of `g` that `v` shows, in the order of g.lines.
std::vector<Polyline> view_lines(const GridLines &g, const View &v);

// How each kind of line is drawn, in pixels, so every zoom shows it alike.
struct LineStyle {
    const char *name;     // the SVG class
    unsigned char rgb[3];
    double width;         // pixels
};
const LineStyle &line_style(LineKind kind);

}  // namespace eg2dtool
