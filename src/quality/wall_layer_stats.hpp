// The wall layer as a flow solver sees it: at each node of a wall stretch
// (but its two ends, and its corners with the nodes beside them: a trailing
// edge, a blunt base's corners, where the wall has no tangent) the first-cell
// height normal to the wall, the deviation of the line leaving it from the
// wall normal, and the largest ratio of consecutive cells along that line
// over its first `rows` cells. The grid report (io/report.cpp) and
// eg2d_get_wall_layer read it.
#pragma once
#include <vector>

#include "base/grid.hpp"

namespace eg2d {

struct WallNodeStats {
    double height, angle, growth;  // growth: the largest cell over the one below it; 0 if rows < 2
};

// The measured nodes of nodes first..last of side s, in order.
std::vector<WallNodeStats> wall_stretch_stats(const Grid &g, Side s, int first, int last, int rows);

// One side's figures over its wall stretches (all of it when it has none),
// `rows` cells deep (eg2d_get_wall_layer). nodes 0: nothing measured.
struct WallLayerFigures {
    int nodes = 0;
    double first_min = 0, first_median = 0, first_max = 0, growth = 0, angle = 0;
};
WallLayerFigures wall_layer_figures(const Grid &g, Side s, int rows);

}  // namespace eg2d
