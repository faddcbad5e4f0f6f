// The two walls of eg2d channel, as NI nodes each from the inlet to the
// outlet: from two curves (point files or expressions) or from a centreline
// and a width, the nodes along them by arc length (uniform, or clustered at
// the inlet and outlet). Each failure names the option it comes from.
#pragma once

#include <string>
#include <vector>

namespace eg2dtool {

struct WallOptions {
    std::string lower, upper;        // a point file, or "x(s);y(s)"
    std::string centreline, width;   // or a centreline curve and a width (a number or an expression in s)
    bool spline = false;             // a point file's points joined by a spline (else a polyline)
    double inlet_spacing = 0, outlet_spacing = 0;  // along the walls, in length units; 0: uniform
};

struct Walls {
    std::vector<double> lx, ly, ux, uy;  // NI nodes each, inlet first
};

// The walls' nodes. Failure: EXIT_CASE for a bad expression (naming the
// option), EXIT_IO for a point file that cannot be read, EXIT_GEOMETRY for
// spacings the walls cannot hold.
Walls channel_walls(const WallOptions &options, int ni);

// The arc length of the line midway between the walls' nodes (the
// centreline's nodes when the walls were made from one).
double centreline_length(const Walls &walls);

// The arc length of a polyline.
double polyline_length(const std::vector<double> &x, const std::vector<double> &y);

}  // namespace eg2dtool
