// Boundary patches: names and types of the boundary's stretches for the
// solver-ready writers (base/patches.hpp).
#include <algorithm>
#include <cstring>

#include "api/handle.hpp"
#include "base/patches.hpp"

using namespace eg2d;
using namespace eg2d::api;

extern "C" {

EG2D_API int eg2d_set_patch(eg2d_grid *grid, int side, int first, int last, int type, const char *name) {
    return guard(grid, "eg2d_set_patch", [&] {
        require(side >= EG2D_SIDE_JMIN && side <= EG2D_SIDE_IMIN,
                format("side = %d: not one of EG2D_SIDE_JMIN (0), IMAX (1), JMAX (2), IMIN (3)", side));
        require_ptr(name, "name");
        const Grid &g = grid->gen.grid();
        grid->gen.set_patches(
            with_patch(g, g.patches, Patch{static_cast<Side>(side), first, last, static_cast<PatchType>(type), name}));
    });
}

EG2D_API int eg2d_clear_patches(eg2d_grid *grid) {
    return guard(grid, "eg2d_clear_patches", [&] { grid->gen.set_patches({}); });
}

EG2D_API int eg2d_get_patch_count(const eg2d_grid *grid, int *count) {
    return guard(grid, "eg2d_get_patch_count", [&] {
        const std::vector<Patch> all = resolve_patches(grid->gen.grid());
        if (count) *count = static_cast<int>(all.size());
    });
}

EG2D_API int eg2d_get_patch(const eg2d_grid *grid, int index, int *side, int *first, int *last, int *type, char *name,
                            int size) {
    return guard(grid, "eg2d_get_patch", [&] {
        require(size >= 0, format("size = %d: must be >= 0", size));
        require(name || size == 0, "name is NULL with size > 0");
        const std::vector<Patch> all = resolve_patches(grid->gen.grid());
        require(index >= 0 && static_cast<std::size_t>(index) < all.size(),
                format("index = %d: the grid has %zu patches (0..%zu)", index, all.size(), all.size() - 1));
        const Patch &p = all[static_cast<std::size_t>(index)];
        if (side) *side = static_cast<int>(p.side);
        if (first) *first = p.first;
        if (last) *last = p.last;
        if (type) *type = static_cast<int>(p.type);
        if (name && size > 0) {
            const std::size_t n = std::min(p.name.size(), static_cast<std::size_t>(size) - 1);
            std::memcpy(name, p.name.data(), n);
            name[n] = '\0';
        }
    });
}

}  // extern "C"
