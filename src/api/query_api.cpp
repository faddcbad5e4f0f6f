// Queries: size, coordinates, residual, iterations, quality.
#include <algorithm>
#include <vector>

#include "api/handle.hpp"
#include "quality/quality.hpp"
#include "quality/wall_layer_stats.hpp"

using namespace eg2d;
using namespace eg2d::api;

extern "C" {

EG2D_API int eg2d_get_size(const eg2d_grid *grid, int *ni, int *nj) {
    return guard(grid, "eg2d_get_size", [&] {
        require(ni || nj, "ni and nj are both NULL");
        if (ni) *ni = grid->gen.grid().ni();
        if (nj) *nj = grid->gen.grid().nj();
    });
}

EG2D_API int eg2d_get_coordinates(const eg2d_grid *grid, double *x, double *y) {
    return guard(grid, "eg2d_get_coordinates", [&] {
        require(x || y, "x and y are both NULL");
        grid->gen.require_initialized("coordinates");
        const Grid &g = grid->gen.grid();
        if (x) std::copy(g.x.begin(), g.x.end(), x);
        if (y) std::copy(g.y.begin(), g.y.end(), y);
    });
}

EG2D_API int eg2d_get_residual(const eg2d_grid *grid, double *residual) {
    return guard(grid, "eg2d_get_residual", [&] {
        require_ptr(residual, "residual");
        *residual = grid->gen.residual().value;
    });
}

EG2D_API int eg2d_get_iterations(const eg2d_grid *grid, int *iterations) {
    return guard(grid, "eg2d_get_iterations", [&] {
        require_ptr(iterations, "iterations");
        *iterations = grid->gen.iterations();
    });
}

EG2D_API int eg2d_get_run_info(const eg2d_grid *grid, int what, int *value) {
    return guard(grid, "eg2d_get_run_info", [&] {
        require_ptr(value, "value");
        const RunReport &r = grid->gen.report();
        switch (what) {
        case EG2D_RUN_SOLVER: *value = r.solver; break;
        case EG2D_RUN_LEVELS: *value = r.levels; break;
        case EG2D_RUN_LEVELS_BUILT: *value = r.levels_built; break;
        case EG2D_RUN_EVENTS: *value = static_cast<int>(r.events.size()); break;
        default: require(false, format("what = %d: not an EG2D_RUN_* id", what));
        }
    });
}

EG2D_API int eg2d_get_run_event(const eg2d_grid *grid, int index, int *iteration, char *message, int size) {
    return guard(grid, "eg2d_get_run_event", [&] {
        const RunReport &r = grid->gen.report();
        require(index >= 0 && static_cast<std::size_t>(index) < r.events.size(),
                format("index = %d: the last run has %zu event%s", index, r.events.size(),
                       r.events.size() == 1 ? "" : "s"));
        require(size >= 0, format("size = %d: must be >= 0", size));
        require(size == 0 || message != nullptr, format("message is NULL but size is %d", size));
        const RunEvent &e = r.events[static_cast<std::size_t>(index)];
        if (iteration) *iteration = e.iteration;
        if (size > 0) {
            const std::size_t n = std::min(static_cast<std::size_t>(size) - 1, e.message.size());
            std::copy(e.message.begin(), e.message.begin() + static_cast<std::ptrdiff_t>(n), message);
            message[n] = '\0';
        }
    });
}

EG2D_API int eg2d_get_quality(const eg2d_grid *grid, int metric, double *value) {
    return guard(grid, "eg2d_get_quality", [&] {
        require_ptr(value, "value");
        const QualityMetric *m = find_quality_metric(metric);
        require(m != nullptr, format("metric = %d: no such quality metric", metric));
        grid->gen.require_initialized("quality");
        *value = m->summary(grid->gen.grid());
    });
}

EG2D_API int eg2d_get_cell_quality(const eg2d_grid *grid, int metric, double *values) {
    return guard(grid, "eg2d_get_cell_quality", [&] {
        require_ptr(values, "values");
        const QualityMetric *m = find_quality_metric(metric);
        require(m != nullptr, format("metric = %d: no such quality metric", metric));
        require(m->cells != nullptr,
                format("metric = %d (%s): a boundary summary with no per-cell values", metric, m->name));
        grid->gen.require_initialized("quality");
        const Grid &g = grid->gen.grid();
        std::vector<double> v(static_cast<std::size_t>(g.ni() - 1) * static_cast<std::size_t>(g.nj() - 1));
        m->cells(g, v.data());
        std::copy(v.begin(), v.end(), values);
    });
}

EG2D_API int eg2d_get_wall_layer(const eg2d_grid *grid, int side, int what, double *value) {
    return guard(grid, "eg2d_get_wall_layer", [&] {
        require_ptr(value, "value");
        require(side >= 0 && side < 4, format("side = %d: not an EG2D_SIDE_* (0-3)", side));
        const Grid &g = grid->gen.grid();
        const Side s = static_cast<Side>(side);
        require(g.has_side(s), format("side %s: the topology has no such side", side_name(s)));
        require(what >= EG2D_WALL_FIRST_MIN && what <= EG2D_WALL_NODES_NEEDED,
                format("what = %d: not an EG2D_WALL_* (0-6)", what));
        grid->gen.require_initialized("wall layer");
        const WallLayerShape &layer = grid->gen.layer();
        if (what == EG2D_WALL_NODES_NEEDED) {
            *value = (s == Side::JMin || s == Side::JMax) ? layer.needed_nj : layer.needed_ni;
            return;
        }
        const WallLayerFigures f = wall_layer_figures(g, s, EG2D_WALL_ROWS);
        if (what == EG2D_WALL_NODES) {
            *value = f.nodes;
            return;
        }
        require(f.nodes > 0, format("side %s: no wall node to measure (a stretch's ends and corners are left out)",
                                    side_name(s)));
        const double figures[] = {f.first_min, f.first_median, f.first_max, f.growth, f.angle};
        *value = figures[what];
    });
}

}  // extern "C"
