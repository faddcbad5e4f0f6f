#include "grid_lines.hpp"

#include <eg2d.h>

#include <algorithm>
#include <string>

#include "failure.hpp"

namespace eg2dtool {

namespace {

void check(const eg2d_grid *g, int status, const char *what) {
    if (status != EG2D_OK) throw Failure(exit_code_for_status(status), std::string(what) + ": " + eg2d_last_error(g));
}

LineKind kind_of(int patch_type) {
    if (patch_type == EG2D_PATCH_WALL) return kWallLine;
    return patch_type == EG2D_PATCH_CUT ? kGridLine : kBoundaryLine;
}

}  // namespace

GridLines grid_lines(const eg2d_grid *grid) {
    GridLines g;
    check(grid, eg2d_get_size(grid, &g.ni, &g.nj), "the grid's size");
    const std::size_t ni = static_cast<std::size_t>(g.ni);
    g.x.resize(ni * g.nj);
    g.y.resize(g.x.size());
    check(grid, eg2d_get_coordinates(grid, g.x.data(), g.y.data()), "the grid's coordinates");
    // Interior lines; the sides are drawn as their patches (an O-grid's
    // i = 0 line is its cut, and i = ni-1 the same nodes again).
    for (int j = 1; j < g.nj - 1; ++j) g.lines.push_back({kGridLine, ni * j, 1, g.ni});
    for (int i = 1; i < g.ni - 1; ++i) g.lines.push_back({kGridLine, static_cast<std::size_t>(i), ni, g.nj});
    int count = 0;
    check(grid, eg2d_get_patch_count(grid, &count), "the grid's patches");
    std::vector<LineRef> sides;
    for (int k = 0; k < count; ++k) {
        int side = 0, first = 0, last = 0, type = 0;
        check(grid, eg2d_get_patch(grid, k, &side, &first, &last, &type, nullptr, 0), "the grid's patches");
        const std::size_t f = static_cast<std::size_t>(first);
        const int n = last - first + 1;
        if (side == EG2D_SIDE_JMIN) sides.push_back({kind_of(type), f, 1, n});
        else if (side == EG2D_SIDE_JMAX) sides.push_back({kind_of(type), ni * (g.nj - 1) + f, 1, n});
        else if (side == EG2D_SIDE_IMIN) sides.push_back({kind_of(type), ni * f, ni, n});
        else sides.push_back({kind_of(type), ni * f + ni - 1, ni, n});
    }
    std::stable_sort(sides.begin(), sides.end(), [](const LineRef &a, const LineRef &b) { return a.kind < b.kind; });
    g.lines.insert(g.lines.end(), sides.begin(), sides.end());
    return g;
}

}  // namespace eg2dtool
