// Queries: size, coordinates, residual, iterations, quality.
#include <algorithm>
#include <vector>

#include "api/handle.hpp"
#include "quality/quality.hpp"

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

}  // extern "C"
