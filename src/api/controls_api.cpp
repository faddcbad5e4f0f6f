// Grid control: attraction sources, user arrays, orthogonality (Middlecoff-
// Thomas, wall), parameter grid, weight; and Khattri's (2006) clustering helpers.
// Each call checks everything, builds the new ControlSet on a copy and only
// then replaces the grid's (a failed call changes nothing).
#include <algorithm>
#include <cmath>
#include <vector>

#include "api/handle.hpp"
#include "controls/controls.hpp"
#include "controls/registry.hpp"

using namespace eg2d;
using namespace eg2d::api;

namespace {

// Copies n values after checking each is finite (and > 0 when asked).
std::vector<double> take_array(const double *v, std::size_t n, const char *name, bool positive = false) {
    for (std::size_t k = 0; k < n; ++k) {
        if (!std::isfinite(v[k])) fail(Failure::Argument, format("%s[%zu] = %g: must be finite", name, k, v[k]));
        if (positive && !(v[k] > 0.0)) fail(Failure::Argument, format("%s[%zu] = %g: must be > 0", name, k, v[k]));
    }
    return std::vector<double>(v, v + n);
}

template <class Edit>
void edit_controls(eg2d_grid *grid, Edit &&edit) {
    ControlSet next = grid->gen.controls();
    edit(next);
    grid->gen.controls() = std::move(next);
    grid->gen.changed_controls();
}

std::array<double, 4> wall_sides(std::array<double, 4> h) {
    bool any = false;
    for (double v : h) any = any || v >= 0.0;
    if (!any) h = {0.0, 0.0, 0.0, 0.0};  // no side chosen: every side, orthogonality only
    return h;
}

}  // namespace

extern "C" {

EG2D_API int eg2d_add_line_source(eg2d_grid *grid, int direction, double line, double amplitude, double decay) {
    return guard(grid, "eg2d_add_line_source", [&] {
        require(direction == EG2D_XI || direction == EG2D_ETA,
                format("direction = %d: not EG2D_XI (0) or EG2D_ETA (1)", direction));
        require_finite(line, "line");
        require_finite(amplitude, "amplitude");
        require_finite(decay, "decay");
        const int last = (direction == EG2D_XI ? grid->gen.grid().ni() : grid->gen.grid().nj()) - 1;
        require(line >= 0.0 && line <= last,
                format("line = %g: must be in [0, %d] (%s index units)", line, last, direction == EG2D_XI ? "xi" : "eta"));
        require(decay >= 0.0, format("decay = %g: must be >= 0", decay));
        edit_controls(grid, [&](ControlSet &set) {
            AttractionControl next;
            if (auto *old = dynamic_cast<AttractionControl *>(set.find(ControlKind::Sources))) next = *old;
            next.lines.push_back({direction, line, amplitude, decay});
            set.put(next.clone());
        });
    });
}

EG2D_API int eg2d_add_point_source(eg2d_grid *grid, double xi, double eta, double amplitude, double decay) {
    return guard(grid, "eg2d_add_point_source", [&] {
        require_finite(xi, "xi");
        require_finite(eta, "eta");
        require_finite(amplitude, "amplitude");
        require_finite(decay, "decay");
        const int ni = grid->gen.grid().ni(), nj = grid->gen.grid().nj();
        require(xi >= 0.0 && xi <= ni - 1, format("xi = %g: must be in [0, %d]", xi, ni - 1));
        require(eta >= 0.0 && eta <= nj - 1, format("eta = %g: must be in [0, %d]", eta, nj - 1));
        require(decay >= 0.0, format("decay = %g: must be >= 0", decay));
        edit_controls(grid, [&](ControlSet &set) {
            AttractionControl next;
            if (auto *old = dynamic_cast<AttractionControl *>(set.find(ControlKind::Sources))) next = *old;
            next.points.push_back({xi, eta, amplitude, decay});
            set.put(next.clone());
        });
    });
}

EG2D_API int eg2d_clear_sources(eg2d_grid *grid) {
    return guard(grid, "eg2d_clear_sources",
                 [&] { edit_controls(grid, [](ControlSet &set) { set.remove(ControlKind::Sources); }); });
}

EG2D_API int eg2d_set_source_arrays(eg2d_grid *grid, const double *P, const double *Q) {
    return guard(grid, "eg2d_set_source_arrays", [&] {
        const std::size_t n = grid->gen.grid().size();
        std::vector<double> p, q;
        if (P) p = take_array(P, n, "P");
        if (Q) q = take_array(Q, n, "Q");
        edit_controls(grid, [&](ControlSet &set) {
            if (!P && !Q) set.remove(ControlKind::Arrays);
            else set.put(make_source_arrays(std::move(p), std::move(q)));
        });
    });
}

EG2D_API int eg2d_set_orthogonality(eg2d_grid *grid, int method) {
    return guard(grid, "eg2d_set_orthogonality", [&] {
        const OrthogonalityMethod *m = find_orthogonality(method);
        require(m != nullptr, format("method = %d: not %s", method, orthogonality_ids().c_str()));
        edit_controls(grid, [&](ControlSet &set) {
            if (!m->make) set.remove(ControlKind::Orthogonality);
            else set.put(m->make(wall_sides(grid->wall_height)));
        });
    });
}

namespace {

void require_side(const eg2d_grid *grid, int side) {
    require(side >= EG2D_SIDE_JMIN && side <= EG2D_SIDE_IMIN, format("side = %d: not an EG2D_SIDE_* value (0-3)", side));
    require(grid->gen.grid().has_side(static_cast<Side>(side)),
            format("side %s: the grid's topology has no such side", side_name(static_cast<Side>(side))));
}

// eg2d_set_wall_spacing after its checks: the side's one height (a wall
// control takes it) and its heights node by node (`nodes`, empty: none).
void put_wall_spacing(eg2d_grid *grid, int side, double height, std::vector<double> nodes) {
    std::array<double, 4> next = grid->wall_height;
    next[side] = height < 0.0 ? -1.0 : height;
    ControlSet set = grid->gen.controls();
    // A wall control in use takes the new sides; with no orthogonality
    // control yet, a wall asked for is one (a first cell set without
    // EG2D_ORTHO_WALL did nothing, silently: 0.02-1 chord first cells on
    // NACA 0012 385x97 at y+ 1).
    Control *ortho = set.find(ControlKind::Orthogonality);
    if (is_wall_control(ortho) || (!ortho && next[side] >= 0.0)) set.put(make_wall_control(wall_sides(next)));
    grid->gen.controls() = std::move(set);
    grid->wall_height = next;
    grid->gen.set_wall_node_spacing(static_cast<Side>(side), std::move(nodes));
    grid->gen.changed_controls();
}

}  // namespace

EG2D_API int eg2d_set_wall_spacing(eg2d_grid *grid, int side, double height) {
    return guard(grid, "eg2d_set_wall_spacing", [&] {
        require_side(grid, side);
        require_finite(height, "height");
        put_wall_spacing(grid, side, height, {});
    });
}

EG2D_API int eg2d_set_wall_spacing_nodes(eg2d_grid *grid, int side, int n, const double *heights) {
    return guard(grid, "eg2d_set_wall_spacing_nodes", [&] {
        require_side(grid, side);
        if (!heights) return put_wall_spacing(grid, side, -1.0, {});
        const int length = grid->gen.grid().side_length(static_cast<Side>(side));
        require(n == length, format("n = %d: side %s has %d nodes", n, side_name(static_cast<Side>(side)), length));
        std::vector<double> h(heights, heights + n);
        for (int k = 0; k < n; ++k)
            require(std::isfinite(h[static_cast<std::size_t>(k)]) && h[static_cast<std::size_t>(k)] > 0.0,
                    format("heights[%d] = %g: must be finite and > 0", k, h[static_cast<std::size_t>(k)]));
        const double least = *std::min_element(h.begin(), h.end());
        put_wall_spacing(grid, side, least, std::move(h));
    });
}

EG2D_API int eg2d_set_parameter_grid(eg2d_grid *grid, const double *s, const double *t) {
    return guard(grid, "eg2d_set_parameter_grid", [&] {
        require((s == nullptr) == (t == nullptr), "s and t must both be given, or both NULL to remove");
        if (!s) {
            edit_controls(grid, [](ControlSet &set) { set.remove(ControlKind::ParameterGrid); });
            return;
        }
        const std::size_t n = grid->gen.grid().size();
        std::vector<double> sv = take_array(s, n, "s"), tv = take_array(t, n, "t");
        const ParameterFold f = parameter_grid_fold(grid->gen.grid().connectivity(), sv.data(), tv.data());
        require(f.i < 0, format("the parameter grid is folded or degenerate at node (%d, %d): "
                                "s_xi t_eta - s_eta t_xi changes sign or is zero there", f.i, f.j));
        edit_controls(grid, [&](ControlSet &set) { set.put(make_parameter_grid(std::move(sv), std::move(tv))); });
    });
}

EG2D_API int eg2d_set_weight(eg2d_grid *grid, const double *w) {
    return guard(grid, "eg2d_set_weight", [&] {
        if (!w) {
            edit_controls(grid, [](ControlSet &set) { set.remove(ControlKind::Weight); });
            return;
        }
        std::vector<double> wv = take_array(w, grid->gen.grid().size(), "w", true);
        edit_controls(grid, [&](ControlSet &set) { set.put(make_weight_control(std::move(wv))); });
    });
}

EG2D_API int eg2d_clustering_map(int kind, double a, double b, double strength, int n, double *u_out) {
    return guard_without_grid("eg2d_clustering_map", [&] {
        require(kind >= EG2D_CLUSTER_LINE && kind <= EG2D_CLUSTER_BOUNDARIES,
                format("kind = %d: not an EG2D_CLUSTER_* value (0-2)", kind));
        require_ptr(u_out, "u_out");
        require(n >= 2, format("n = %d: need at least 2 points", n));
        require_finite(a, "a");
        require_finite(strength, "strength");
        require(a > 0.0 && a < 1.0, format("a = %g: must be in (0, 1)", a));
        if (kind == EG2D_CLUSTER_TWO_LINES) {
            require_finite(b, "b");
            require(b > a && b < 1.0, format("b = %g: must be in (a, 1) = (%g, 1)", b, a));
        }
        require(strength >= 0.0 && strength <= 50.0, format("strength = %g: must be in (0, 50] (or 0 for Khattri's (2006) default)", strength));
        const double k = strength > 0.0 ? strength : (kind == EG2D_CLUSTER_BOUNDARIES ? 4.0 : 3.0);
        for (int i = 0; i < n; ++i) {
            const double u = i == n - 1 ? 1.0 : static_cast<double>(i) / (n - 1);
            u_out[i] = clustering_map(static_cast<Clustering>(kind), a, b, k, u);
        }
        u_out[0] = 0.0;
        u_out[n - 1] = 1.0;
    });
}

EG2D_API int eg2d_tensor_parameter_grid(int ni, int nj, const double *u, const double *v, double *s, double *t) {
    return guard_without_grid("eg2d_tensor_parameter_grid", [&] {
        require(ni >= 3 && nj >= 3, format("ni = %d, nj = %d: need at least 3 each", ni, nj));
        require_ptr(u, "u");
        require_ptr(v, "v");
        require_ptr(s, "s");
        require_ptr(t, "t");
        for (int i = 0; i < ni; ++i) require_finite(u[i], "u");
        for (int j = 0; j < nj; ++j) require_finite(v[j], "v");
        for (int i = 1; i < ni; ++i)
            require(u[i] > u[i - 1], format("u[%d] = %g <= u[%d] = %g: u must increase", i, u[i], i - 1, u[i - 1]));
        for (int j = 1; j < nj; ++j)
            require(v[j] > v[j - 1], format("v[%d] = %g <= v[%d] = %g: v must increase", j, v[j], j - 1, v[j - 1]));
        for (int j = 0; j < nj; ++j)
            for (int i = 0; i < ni; ++i) {
                const std::size_t k = static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j;
                s[k] = u[i];
                t[k] = v[j];
            }
    });
}

EG2D_API int eg2d_get_controls(const eg2d_grid *grid, double *P, double *Q) {
    return guard(grid, "eg2d_get_controls", [&] {
        require(P || Q, "P and Q are both NULL");
        const std::size_t n = grid->gen.grid().x.size();
        std::vector<double> p(P ? n : 0), q(Q ? n : 0);
        grid->gen.control_sources(P ? p.data() : nullptr, Q ? q.data() : nullptr);
        if (P) std::copy(p.begin(), p.end(), P);
        if (Q) std::copy(q.begin(), q.end(), Q);
    });
}

}  // extern "C"
