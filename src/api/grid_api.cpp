// Creating and destroying grids, topology.
#include "api/blocks_handle.hpp"
#include "api/handle.hpp"

using namespace eg2d;
using namespace eg2d::api;

extern "C" {

EG2D_API int eg2d_create(int ni, int nj, eg2d_grid **grid) {
    if (grid) *grid = nullptr;
    return guard_without_grid("eg2d_create", [&] {
        require_ptr(grid, "grid");
        *grid = new eg2d_grid(ni, nj);
    });
}

EG2D_API void eg2d_destroy(eg2d_grid *grid) {
    if (grid) forget_in_sets(grid);
    delete grid;
}

EG2D_API int eg2d_set_topology(eg2d_grid *grid, int topology) {
    return guard(grid, "eg2d_set_topology", [&] {
        require(topology == EG2D_TOPO_SINGLE || topology == EG2D_TOPO_O || topology == EG2D_TOPO_C,
                format("topology = %d: not one of EG2D_TOPO_SINGLE, EG2D_TOPO_O, EG2D_TOPO_C", topology));
        grid->gen.set_topology(static_cast<Topology>(topology));
    });
}

EG2D_API int eg2d_get_topology(const eg2d_grid *grid, int *topology) {
    return guard(grid, "eg2d_get_topology", [&] {
        require_ptr(topology, "topology");
        *topology = static_cast<int>(grid->gen.grid().topology());
    });
}

EG2D_API int eg2d_get_cut(const eg2d_grid *grid, int *wake) {
    return guard(grid, "eg2d_get_cut", [&] {
        require_ptr(wake, "wake");
        *wake = grid->gen.grid().cut_wake();
    });
}

}  // extern "C"
