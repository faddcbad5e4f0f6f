// Curves, distributions, side curves and the wall spacing: the C boundary of
// src/geometry. Curve calls have no grid, so their errors go to the thread.
#include <algorithm>
#include <functional>
#include <memory>
#include <vector>

#include "api/airfoil_apply.hpp"
#include "api/handle.hpp"
#include "geometry/curve.hpp"
#include "geometry/distribution.hpp"
#include "geometry/side_curve.hpp"
#include "geometry/yplus.hpp"

struct eg2d_curve {
    explicit eg2d_curve(std::shared_ptr<const eg2d::Curve> c) : arc(std::move(c)) {}
    eg2d::ArcLength arc;
};

using namespace eg2d;
using namespace eg2d::api;

namespace {

// A user callback as a Curve; a non-finite point is an error, not a grid.
class FunctionCurve final : public Curve {
public:
    FunctionCurve(eg2d_curve_fn fn, void *user) : fn_(fn), user_(user) {}
    void eval(double t, double &x, double &y) const override {
        x = y = 0.0;
        fn_(user_, t, &x, &y);
        if (!std::isfinite(x) || !std::isfinite(y))
            fail(Failure::Argument, format("the curve function gave (%g, %g) at t = %.17g: must be finite", x, y, t));
    }

private:
    eg2d_curve_fn fn_;
    void *user_;
};

int make_curve(const char *function, eg2d_curve **curve, const std::function<std::shared_ptr<const Curve>()> &build) {
    if (curve) *curve = nullptr;
    return guard_without_grid(function, [&] {
        require_ptr(curve, "curve");
        *curve = new eg2d_curve(build());
    });
}

void require_curve(const eg2d_curve *c) { require_ptr(c, "curve"); }

}  // namespace

extern "C" {

EG2D_API int eg2d_curve_polyline(int n, const double *x, const double *y, eg2d_curve **curve) {
    return make_curve("eg2d_curve_polyline", curve, [&] {
        require_ptr(x, "x");
        require_ptr(y, "y");
        return make_polyline(x, y, n);
    });
}

EG2D_API int eg2d_curve_spline(int n, const double *x, const double *y, eg2d_curve **curve) {
    return make_curve("eg2d_curve_spline", curve, [&] {
        require_ptr(x, "x");
        require_ptr(y, "y");
        return make_spline(x, y, n, false);
    });
}

EG2D_API int eg2d_curve_function(eg2d_curve_fn fn, void *user, eg2d_curve **curve) {
    return make_curve("eg2d_curve_function", curve, [&]() -> std::shared_ptr<const Curve> {
        require(fn != nullptr, "fn is NULL");
        return std::make_shared<FunctionCurve>(fn, user);
    });
}

EG2D_API int eg2d_curve_naca4(const char *digits, int flags, eg2d_curve **curve) {
    return make_curve("eg2d_curve_naca4", curve, [&] {
        require_ptr(digits, "digits");
        require(flags == 0 || flags == EG2D_NACA_CLOSED_TE,
                format("flags = %d: only 0 or EG2D_NACA_CLOSED_TE (1)", flags));
        return make_naca4(digits, flags == EG2D_NACA_CLOSED_TE);
    });
}

EG2D_API int eg2d_curve_read_airfoil(const char *path, eg2d_curve **curve) {
    return make_curve("eg2d_curve_read_airfoil", curve, [&] {
        require_ptr(path, "path");
        return read_airfoil(path);
    });
}

EG2D_API void eg2d_curve_destroy(eg2d_curve *curve) { delete curve; }

EG2D_API int eg2d_curve_length(const eg2d_curve *curve, double *length) {
    return guard_without_grid("eg2d_curve_length", [&] {
        require_curve(curve);
        require_ptr(length, "length");
        *length = curve->arc.length();
    });
}

EG2D_API int eg2d_curve_evaluate(const eg2d_curve *curve, double s, double *x, double *y) {
    return guard_without_grid("eg2d_curve_evaluate", [&] {
        require_curve(curve);
        require_ptr(x, "x");
        require_ptr(y, "y");
        require(s >= 0.0 && s <= 1.0, format("s = %g: must be in [0, 1]", s));
        double px, py;
        curve->arc.point(s, px, py);
        *x = px;
        *y = py;
    });
}

EG2D_API int eg2d_distribution(int distribution, int n, double p1, double p2, double *s) {
    return guard_without_grid("eg2d_distribution", [&] {
        require_ptr(s, "s");
        require(n >= 2, format("n = %d: need at least 2 points", n));
        std::vector<double> out(static_cast<std::size_t>(n));
        distribute(distribution, n, p1, p2, 1.0, out.data());
        std::copy(out.begin(), out.end(), s);
    });
}

EG2D_API int eg2d_distribution_parameter(int distribution, int n, double first_spacing, double p2, double *p1) {
    return guard_without_grid("eg2d_distribution_parameter", [&] {
        require_ptr(p1, "p1");
        *p1 = distribution_parameter(distribution, n, first_spacing, p2);
    });
}

EG2D_API int eg2d_curve_points(const eg2d_curve *curve, int n, int distribution, double p1, double p2, double *x,
                               double *y) {
    return guard_without_grid("eg2d_curve_points", [&] {
        require_curve(curve);
        require_ptr(x, "x");
        require_ptr(y, "y");
        require(n >= 2, format("n = %d: need at least 2 points", n));
        std::vector<double> px(static_cast<std::size_t>(n)), py(static_cast<std::size_t>(n));
        curve_points(curve->arc, n, distribution, p1, p2, px.data(), py.data());
        std::copy(px.begin(), px.end(), x);
        std::copy(py.begin(), py.end(), y);
    });
}

EG2D_API int eg2d_set_side_curve(eg2d_grid *grid, int side, const eg2d_curve *curve, int distribution, double p1,
                                 double p2, int flags) {
    return guard(grid, "eg2d_set_side_curve", [&] {
        require(side >= EG2D_SIDE_JMIN && side <= EG2D_SIDE_IMIN,
                format("side = %d: not one of EG2D_SIDE_JMIN (0), IMAX (1), JMAX (2), IMIN (3)", side));
        require_curve(curve);
        require((flags & ~(EG2D_CURVE_REVERSE | EG2D_CURVE_ORIENT | EG2D_CURVE_SLIDING)) == 0,
                format("flags = %d: only EG2D_CURVE_REVERSE (1), EG2D_CURVE_ORIENT (2), EG2D_CURVE_SLIDING (4)",
                       flags));
        set_side_curve(grid->gen, static_cast<Side>(side), curve->arc, distribution, p1, p2, flags);
    });
}

EG2D_API int eg2d_set_airfoil(eg2d_grid *grid, const eg2d_curve *section, int topology) {
    return guard(grid, "eg2d_set_airfoil", [&] {
        require_curve(section);
        require(topology == EG2D_TOPO_O || topology == EG2D_TOPO_C,
                format("topology = %d: an airfoil grid is EG2D_TOPO_O (1) or EG2D_TOPO_C (2)", topology));
        apply_airfoil(grid, std::make_shared<const ArcLength>(section->arc), topology, grid->gen.settings);
        airfoil_run_defaults(grid, topology);
    });
}

EG2D_API int eg2d_first_cell_height(double yplus, double reynolds, double chord, double *height) {
    return guard_without_grid("eg2d_first_cell_height", [&] {
        require_ptr(height, "height");
        *height = first_cell_height(yplus, reynolds, chord);
    });
}

}  // extern "C"
