// System, solver and parameters.
#include "api/airfoil_apply.hpp"
#include "api/handle.hpp"
#include "base/parameters.hpp"
#include "solvers/solver.hpp"

using namespace eg2d;
using namespace eg2d::api;

namespace {
int set_param(eg2d_grid *grid, const char *function, int param, double value) {
    return guard(grid, function, [&] {
        const ParameterInfo *p = find_parameter(param);
        require(p != nullptr, format("parameter %d: no such parameter", param));
        check_parameter(*p, value);
        Settings next = grid->gen.settings;
        next.*(p->field) = value;
        check_settings(next);
        std::set<int> by_caller = grid->set_by_caller;  // allocates before the change: strong guarantee
        by_caller.insert(param);
        set_settings_remaking_airfoil(grid, next);
        grid->set_by_caller.swap(by_caller);
    });
}
}  // namespace

extern "C" {

EG2D_API int eg2d_set_system(eg2d_grid *grid, int system) {
    return guard(grid, "eg2d_set_system", [&] {
        require(system == EG2D_SYSTEM_LAPLACE || system == EG2D_SYSTEM_WINSLOW || system == EG2D_SYSTEM_VARIATIONAL,
                format("system = %d: not EG2D_SYSTEM_LAPLACE (0), EG2D_SYSTEM_WINSLOW (1) or "
                       "EG2D_SYSTEM_VARIATIONAL (2)", system));
        grid->gen.set_system(static_cast<System>(system));
    });
}

EG2D_API int eg2d_set_solver(eg2d_grid *grid, int solver) {
    return guard(grid, "eg2d_set_solver", [&] {
        require(solver >= 0 && solver <= 99, format("solver = %d: no such solver id", solver));
        grid->gen.set_solver(solver);
    });
}

EG2D_API int eg2d_get_solver(const eg2d_grid *grid, int *solver) {
    return guard(grid, "eg2d_get_solver", [&] {
        require_ptr(solver, "solver");
        *solver = grid->gen.solver_id();
    });
}

EG2D_API int eg2d_set_relaxation(eg2d_grid *grid, double omega) {
    return set_param(grid, "eg2d_set_relaxation", EG2D_PARAM_RELAXATION, omega);
}

EG2D_API int eg2d_set_tolerance(eg2d_grid *grid, double tolerance) {
    return set_param(grid, "eg2d_set_tolerance", EG2D_PARAM_TOLERANCE, tolerance);
}

EG2D_API int eg2d_set_max_iterations(eg2d_grid *grid, int max_iterations) {
    return set_param(grid, "eg2d_set_max_iterations", EG2D_PARAM_MAX_ITERATIONS, max_iterations);
}

EG2D_API int eg2d_set_af_cycle(eg2d_grid *grid, double dtau_min, double dtau_max, int steps) {
    return guard(grid, "eg2d_set_af_cycle", [&] {
        const struct { int id; double value; } in[] = {
            {EG2D_PARAM_AF_DTAU_MIN, dtau_min}, {EG2D_PARAM_AF_DTAU_MAX, dtau_max}, {EG2D_PARAM_AF_STEPS, static_cast<double>(steps)}};
        Settings next = grid->gen.settings;
        for (const auto &v : in) {
            const ParameterInfo *p = find_parameter(v.id);
            check_parameter(*p, v.value);
            next.*(p->field) = v.value;
        }
        check_settings(next);
        grid->gen.settings = next;
    });
}

EG2D_API int eg2d_set_af_time_rule(eg2d_grid *grid, double a, double b) {
    return guard(grid, "eg2d_set_af_time_rule", [&] {
        const ParameterInfo *pa = find_parameter(EG2D_PARAM_AF_A), *pb = find_parameter(EG2D_PARAM_AF_B);
        check_parameter(*pa, a);
        check_parameter(*pb, b);
        grid->gen.settings.af_a = a;
        grid->gen.settings.af_b = b;
    });
}

EG2D_API int eg2d_set_parameter(eg2d_grid *grid, int param, double value) {
    return set_param(grid, "eg2d_set_parameter", param, value);
}

EG2D_API int eg2d_get_parameter(const eg2d_grid *grid, int param, double *value) {
    return guard(grid, "eg2d_get_parameter", [&] {
        require_ptr(value, "value");
        const ParameterInfo *p = find_parameter(param);
        require(p != nullptr, format("parameter %d: no such parameter", param));
        *value = grid->gen.settings.*(p->field);
    });
}

}  // extern "C"
