// Points along a polyline by arc length: the grid's rows and columns taken
// as lines, when nodes are moved along them (the wall layers re-space their
// columns and a C-grid's outflow and far-field sides).
#pragma once
#include <vector>

#include "base/block_tridiagonal.hpp"  // Vec2
#include "base/grid.hpp"

namespace eg2d {

// Cumulative arc length from the first point: s[0] = 0, s[k] = s[k-1] + |p[k] - p[k-1]|.
std::vector<double> arc_lengths(const std::vector<Vec2> &line);

// The points of `line` at arc lengths s (from its first point), each
// clamped to the line's ends; linear between its points.
std::vector<Vec2> points_along(const std::vector<Vec2> &line, const std::vector<double> &s);
// The same with the line's arc_lengths already at hand.
std::vector<Vec2> points_along(const std::vector<Vec2> &line, const std::vector<double> &cum, const std::vector<double> &s);

// Column i of a grid, rows 0..last; row j, columns 0..ni-1; one node.
std::vector<Vec2> grid_column(const Grid &g, int i, int last);
std::vector<Vec2> grid_row(const Grid &g, int j);
inline void set_node(Grid &g, int i, int j, Vec2 p) {
    g.x[node_index(g.ni(), i, j)] = p.x;
    g.y[node_index(g.ni(), i, j)] = p.y;
}

// A wall node whose path a -> b -> c (node indices into g.x, g.y) turns by
// more than 45 degrees is a corner (a blunt base's:
// 90 degrees; a sharp trailing edge's: nearly 180): the wall has no normal
// there, nor, by central differences, at the nodes beside it. The hybrid
// layer's first-cell figures and the grid report leave such nodes out alike.
bool wall_corner(const Grid &g, std::size_t a, std::size_t b, std::size_t c);

}  // namespace eg2d
