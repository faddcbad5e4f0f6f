#include "wall_summary.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "side_spec.hpp"

namespace eg2dtool {

namespace {
std::string side_label(int topology, int side) {
    for (const auto &s : side_names(topology))
        if (s.second == side) return s.first;
    return "side " + std::to_string(side);
}
}  // namespace

bool print_wall_layer(const eg2d_grid *g, int side, const std::string &name, double height, double limit,
                      double first_off) {
    auto figure = [&](int what) {
        double v = 0;
        eg2d_get_wall_layer(g, side, what, &v);
        return v;
    };
    if (figure(EG2D_WALL_NODES) == 0) {
        std::printf("wall layer %s: no node to measure\n", name.c_str());
        return false;
    }
    const double growth = figure(EG2D_WALL_GROWTH), needed = figure(EG2D_WALL_NODES_NEEDED);
    std::printf("wall layer %s: first cell %.4e (median; %.4e to %.4e, asked %.4e), growth %.4f over %d cells, "
                "angle %.3f deg\n", name.c_str(), figure(EG2D_WALL_FIRST_MEDIAN), figure(EG2D_WALL_FIRST_MIN),
                figure(EG2D_WALL_FIRST_MAX), height, growth, EG2D_WALL_ROWS, figure(EG2D_WALL_ANGLE));
    const double median = figure(EG2D_WALL_FIRST_MEDIAN);
    if (first_off > 0.0 && !(std::max(median / height, height / median) <= first_off)) {
        std::fprintf(stderr, "eg2d: the wall layer at %s has a median first cell of %.4g where %.4g was asked (more "
                     "than %g times off; the files are written)\n", name.c_str(), median, height, first_off);
        return true;
    }
    if (growth <= limit) return false;
    const bool across_j = side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX;
    std::fprintf(stderr, "eg2d: the wall layer at %s grows by %.3f within %d cells, more than %g", name.c_str(), growth,
                 EG2D_WALL_ROWS, limit);
    if (needed > 0) std::fprintf(stderr, ": %s >= %.0f would meet it", across_j ? "nj" : "ni", needed);
    std::fprintf(stderr, " (the files are written)\n");
    return true;
}

bool print_wall_layers(const eg2d_grid *g, int topology, const std::vector<WallSpacing> &walls, double limit,
                       const std::string &prefix, double first_off) {
    bool short_layer = false;
    for (const WallSpacing &w : walls)
        if (w.height > 0 &&
            print_wall_layer(g, w.side, prefix + side_label(topology, w.side), w.height, limit, first_off))
            short_layer = true;
    return short_layer;
}

}  // namespace eg2dtool
