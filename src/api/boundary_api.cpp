// Boundary and initial grid.
#include "api/handle.hpp"

using namespace eg2d;
using namespace eg2d::api;

extern "C" {

EG2D_API int eg2d_set_side(eg2d_grid *grid, int side, const double *x, const double *y) {
    return guard(grid, "eg2d_set_side", [&] {
        require(side >= EG2D_SIDE_JMIN && side <= EG2D_SIDE_IMIN,
                format("side = %d: not one of EG2D_SIDE_JMIN (0), IMAX (1), JMAX (2), IMIN (3)", side));
        require_ptr(x, "x");
        require_ptr(y, "y");
        grid->gen.set_side(static_cast<Side>(side), x, y);
    });
}

EG2D_API int eg2d_set_boundary(eg2d_grid *grid, const double *x, const double *y) {
    return guard(grid, "eg2d_set_boundary", [&] {
        require_ptr(x, "x");
        require_ptr(y, "y");
        grid->gen.set_boundary(x, y);
    });
}

EG2D_API int eg2d_initialize(eg2d_grid *grid, int method) {
    return guard(grid, "eg2d_initialize", [&] { grid->gen.initialize(method); });
}

EG2D_API int eg2d_set_coordinates(eg2d_grid *grid, const double *x, const double *y) {
    return guard(grid, "eg2d_set_coordinates", [&] {
        require_ptr(x, "x");
        require_ptr(y, "y");
        grid->gen.set_coordinates(x, y);
    });
}

EG2D_API int eg2d_set_interior_line(eg2d_grid *grid, int direction, int index, const double *x, const double *y) {
    return guard(grid, "eg2d_set_interior_line", [&] {
        require(direction == EG2D_XI || direction == EG2D_ETA,
                format("direction = %d: not EG2D_XI (0, a column) or EG2D_ETA (1, a row)", direction));
        require_ptr(x, "x");
        require_ptr(y, "y");
        grid->gen.set_interior_line(direction == EG2D_XI, index, x, y);
    });
}

EG2D_API int eg2d_clear_interior_lines(eg2d_grid *grid) {
    return guard(grid, "eg2d_clear_interior_lines", [&] { grid->gen.clear_interior_lines(); });
}

}  // extern "C"
