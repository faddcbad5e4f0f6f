// One side of the domain as the case file gives it: one piece or a chain of pieces,
// each a formula in s, inline points or a point file; and the nodes it puts on the side.
#pragma once

#include <string>
#include <vector>

#include "formula.hpp"
#include "location.hpp"

namespace toml {
inline namespace v3 {
class node;
}
}  // namespace toml

namespace eg2dtool {

// How nodes are placed along a curve (the library's EG2D_DIST_*, by arc length).
struct Distribution {
    bool given = false;  // absent: formula nodes at equal steps of s; points are the nodes
    int kind = 0;
    double p1 = 0, p2 = 0;
    Location where;
    // first_spacing = ... in place of p1 (exponential, tanh, tanh2): the first
    // spacing in the curve's length units; p1 is solved for when the number of
    // nodes is known (eg2d_distribution_parameter). 0: p1 is given.
    double first_spacing = 0;
    Location first_spacing_at;
};

struct SidePiece {
    Location where;
    std::string x, y;                  // formulas in s (both or neither)
    Location x_at, y_at;
    std::vector<double> px, py;        // points (inline or from a file)
    Location points_at;
    std::string curve;                 // for points: "" (the nodes), "polyline" or "spline"
    std::string naca;                  // NACA 4-digit section, e.g. "0012"
    bool closed_te = true;             // NACA: the closed (sharp) trailing edge
    std::string airfoil;               // path of a Selig/Lednicer airfoil file
    Distribution distribution;
    bool reverse = false;              // run the piece from its end to its start
    bool sliding = false;              // nodes slide along the curve (a side of one piece)
    double share = -1;                 // fraction of the side's intervals; < 0: by length
};

struct SideSpec {
    int side = 0;      // EG2D_SIDE_*
    std::string name;  // as written ("bottom", "inner", ...)
    Location where;
    std::vector<SidePiece> pieces;
};

// The side names of a topology, in EG2D_SIDE_* order (e.g. bottom right top left).
const std::vector<std::pair<std::string, int>> &side_names(int topology);

// Parses `sides.NAME` (a table or an array of tables). `dir` resolves point files;
// numbers (points, share) may be formulas of the constants.
SideSpec parse_side(const toml::node &node, int side, const std::string &name, const Location &where,
                    const std::string &dir, const Constants &constants);

// The points of a point file through the library's reader (eg2d_read_points:
// "x y" per line); Failure naming `where` (EXIT_IO when it cannot be read,
// EXIT_CASE for fewer than 2 points).
void read_point_file(const std::string &path, const Location &where, std::vector<double> &px,
                     std::vector<double> &py);

// The n nodes of a side. closed: the side is a closed curve (O-grid), so the last
// node is snapped onto the first when they agree to roundoff.
void side_nodes(const SideSpec &spec, int n, bool closed, const Constants &constants, std::vector<double> &x,
                std::vector<double> &y);

}  // namespace eg2dtool
