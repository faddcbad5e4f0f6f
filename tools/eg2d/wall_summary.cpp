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
                      double first_off, double most) {
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
    char asked[64], said[64];  // the line's figures and the message's
    if (most > height) {
        std::snprintf(asked, sizeof asked, "%.4e to %.4e", height, most);
        std::snprintf(said, sizeof said, "%.4g to %.4g", height, most);
    } else {
        std::snprintf(asked, sizeof asked, "%.4e", height);
        std::snprintf(said, sizeof said, "%.4g", height);
    }
    std::printf("wall layer %s: first cell %.4e (median; %.4e to %.4e, asked %s), growth %.4f over %d cells, "
                "angle %.3f deg\n", name.c_str(), figure(EG2D_WALL_FIRST_MEDIAN), figure(EG2D_WALL_FIRST_MIN),
                figure(EG2D_WALL_FIRST_MAX), asked, growth, EG2D_WALL_ROWS, figure(EG2D_WALL_ANGLE));
    // Heights node by node: the median against the range asked.
    const double median = figure(EG2D_WALL_FIRST_MEDIAN), low = height, high = std::max(height, most);
    if (first_off > 0.0 && !(median * first_off >= low && median <= high * first_off)) {
        std::fprintf(stderr, "eg2d: the wall layer at %s has a median first cell of %.4g where %s was asked (more "
                     "than %g times off; the files are written)\n", name.c_str(), median, said, first_off);
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
            print_wall_layer(g, w.side, prefix + side_label(topology, w.side), w.height, limit, first_off,
                             w.nodes.empty() ? 0.0 : *std::max_element(w.nodes.begin(), w.nodes.end())))
            short_layer = true;
    return short_layer;
}

}  // namespace eg2dtool
