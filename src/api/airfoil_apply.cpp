#include "api/airfoil_apply.hpp"

#include "base/parameters.hpp"
#include "geometry/airfoil_boundary.hpp"

namespace eg2d {
namespace api {

void apply_airfoil(eg2d_grid *grid, std::shared_ptr<const ArcLength> section, int topology, const Settings &s) {
    AirfoilSpec spec;
    spec.topology = static_cast<Topology>(topology);
    spec.farfield = s.airfoil_farfield;
    spec.le_spacing = s.airfoil_le_spacing;
    spec.te_spacing = s.airfoil_te_spacing;
    spec.wake = static_cast<int>(s.airfoil_wake_nodes);
    spec.trailing_edge = static_cast<TrailingEdge>(static_cast<int>(s.airfoil_trailing_edge));
    spec.o_te_base = s.airfoil_o_te_base;
    const Grid &g = grid->gen.grid();
    std::vector<double> x, y;
    airfoil_boundary(*section, spec, g.ni(), g.nj(), x, y);
    Grid probe(g.ni(), g.nj());  // the ring's checks (crossings, the cut) before the handle changes
    probe.set_topology(spec.topology);
    probe.set_boundary(x.data(), y.data());
    eg2d_grid::Airfoil memory{std::move(section), topology, x, y};
    grid->gen.set_topology(spec.topology);
    grid->gen.set_boundary(x.data(), y.data());
    grid->airfoil = std::move(memory);
}

void airfoil_run_defaults(eg2d_grid *grid, int topology) {
    struct Default {
        int param;
        double value;
        bool c_grid_only;
    };
    static const Default kDefaults[] = {
        {EG2D_PARAM_TOLERANCE, 1e-10, false},
        {EG2D_PARAM_MG_CYCLE, 1, true},
        {EG2D_PARAM_MG_PRE_SMOOTH, 1, true},
        {EG2D_PARAM_MG_POST_SMOOTH, 2, true},
    };
    Settings &s = grid->gen.settings;
    for (const Default &d : kDefaults)
        if (!grid->set_by_caller.count(d.param) && (!d.c_grid_only || topology == EG2D_TOPO_C))
            s.*(find_parameter(d.param)->field) = d.value;
}

void set_settings_remaking_airfoil(eg2d_grid *grid, const Settings &next) {
    const eg2d_grid::Airfoil &a = grid->airfoil;
    const Settings &now = grid->gen.settings;
    const bool airfoil_changed = next.airfoil_farfield != now.airfoil_farfield ||
                                 next.airfoil_le_spacing != now.airfoil_le_spacing ||
                                 next.airfoil_te_spacing != now.airfoil_te_spacing ||
                                 next.airfoil_wake_nodes != now.airfoil_wake_nodes ||
                                 next.airfoil_trailing_edge != now.airfoil_trailing_edge ||
                                 next.airfoil_o_te_base != now.airfoil_o_te_base;
    if (airfoil_changed && a.section && grid->gen.grid().boundary_is(a.x.data(), a.y.data()))
        apply_airfoil(grid, a.section, a.topology, next);  // throws before anything changed
    grid->gen.settings = next;
}

}  // namespace api
}  // namespace eg2d
