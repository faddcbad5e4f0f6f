// Files: writing a grid, reading Plot3D grids and point files.
#include <algorithm>

#include "api/handle.hpp"
#include "io/formats.hpp"
#include "io/plot3d_read.hpp"
#include "io/points.hpp"

using namespace eg2d;
using namespace eg2d::api;

extern "C" {

EG2D_API int eg2d_write(const eg2d_grid *grid, const char *path, int format) {
    return guard(grid, "eg2d_write", [&] {
        require_ptr(path, "path");
        grid->gen.require_initialized("write");
        const RunSummary run{grid->gen.solver_name(), grid->gen.iterations(), grid->gen.residual().value,
                             grid->run_seconds};
        write_grid(grid->gen.grid(), grid->gen.settings, path, format, &run);
    });
}

}  // extern "C"

namespace {

// Both read calls: capacity < 0 is the unchecked eg2d_read_plot3d.
void read_plot3d_block(const char *path, int block, long long capacity, int *format, int *nblocks, int *ni, int *nj,
                       double *x, double *y) {
    require_ptr(path, "path");
    require(block >= 0, eg2d::format("block = %d: must be >= 0", block));
    require((x == nullptr) == (y == nullptr), "x and y must both be given or both be NULL");
    const Plot3dFile file = read_plot3d(path, block);
    const Plot3dBlock &b = file.block;
    if (x) {
        require(capacity < 0 || b.x.size() <= static_cast<std::size_t>(capacity),
                eg2d::format("%s: grid %d has %d x %d = %zu nodes, more than capacity = %lld", path, block, b.ni, b.nj,
                             b.x.size(), capacity));
        std::copy(b.x.begin(), b.x.end(), x);
        std::copy(b.y.begin(), b.y.end(), y);
    }
    if (format) *format = file.format;
    if (nblocks) *nblocks = file.nblocks;
    if (ni) *ni = b.ni;
    if (nj) *nj = b.nj;
}

}  // namespace

extern "C" {

EG2D_API int eg2d_read_plot3d(const char *path, int block, int *format, int *nblocks, int *ni, int *nj, double *x,
                              double *y) {
    return guard_without_grid("eg2d_read_plot3d",
                              [&] { read_plot3d_block(path, block, -1, format, nblocks, ni, nj, x, y); });
}

EG2D_API int eg2d_read_plot3d_into(const char *path, int block, int capacity, int *format, int *nblocks, int *ni,
                                   int *nj, double *x, double *y) {
    return guard_without_grid("eg2d_read_plot3d_into", [&] {
        require(capacity >= 0, eg2d::format("capacity = %d: must be >= 0", capacity));
        read_plot3d_block(path, block, capacity, format, nblocks, ni, nj, x, y);
    });
}

EG2D_API int eg2d_read_points(const char *path, int capacity, int *n, double *x, double *y) {
    return guard_without_grid("eg2d_read_points", [&] {
        require_ptr(path, "path");
        require((x == nullptr) == (y == nullptr), "x and y must both be given or both be NULL");
        require(n || x, "n, x and y are all NULL");
        const Points p = read_points(path);
        if (x) {
            require(p.x.size() <= static_cast<std::size_t>(std::max(capacity, 0)),
                    format("%s holds %zu points, more than capacity = %d", path, p.x.size(), capacity));
            std::copy(p.x.begin(), p.x.end(), x);
            std::copy(p.y.begin(), p.y.end(), y);
        }
        if (n) *n = static_cast<int>(p.x.size());
    });
}

EG2D_API int eg2d_set_side_from_file(eg2d_grid *grid, int side, const char *path) {
    return guard(grid, "eg2d_set_side_from_file", [&] {
        require(side >= EG2D_SIDE_JMIN && side <= EG2D_SIDE_IMIN,
                format("side = %d: not one of EG2D_SIDE_JMIN (0), IMAX (1), JMAX (2), IMIN (3)", side));
        require_ptr(path, "path");
        const Side s = static_cast<Side>(side);
        if (!grid->gen.grid().has_side(s))
            fail(Failure::Argument, format("side %s: the %s topology has no such side", side_name(s),
                                           topology_name(grid->gen.grid().topology())));
        const Points p = read_points(path);
        const int want = grid->gen.grid().side_length(s);
        if (p.x.size() != static_cast<std::size_t>(want))
            fail(Failure::Boundary, format("%s holds %zu points; side %s has %d", path, p.x.size(), side_name(s), want));
        grid->gen.set_side(s, p.x.data(), p.y.data());
    });
}

}  // extern "C"
