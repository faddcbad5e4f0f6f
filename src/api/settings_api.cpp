// System, solver and parameters.
#include "api/airfoil_apply.hpp"
#include "api/handle.hpp"
#include "base/parameters.hpp"
#include "solvers/solver.hpp"

using namespace eg2d;
using namespace eg2d::api;

namespace {
struct ParamValue {
    int id;
    double value;
};

// Every parameter setter goes through here, so the handle records each
// parameter the caller set (eg2d_set_airfoil's run defaults leave those alone).
template <std::size_t N>
int set_params(eg2d_grid *grid, const char *function, const ParamValue (&values)[N]) {
    return guard(grid, function, [&] {
        Settings next = grid->gen.settings;
        std::set<int> by_caller = grid->set_by_caller;  // allocates before the change: strong guarantee
        for (const ParamValue &v : values) {
            const ParameterInfo *p = find_parameter(v.id);
            require(p != nullptr, format("parameter %d: no such parameter", v.id));
            check_parameter(*p, v.value);
            next.*(p->field) = v.value;
            by_caller.insert(v.id);
        }
        check_settings(next);
        set_settings_remaking_airfoil(grid, next);
        grid->set_by_caller.swap(by_caller);
    });
}

int set_param(eg2d_grid *grid, const char *function, int param, double value) {
    const ParamValue one[] = {{param, value}};
    return set_params(grid, function, one);
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
    const ParamValue in[] = {
        {EG2D_PARAM_AF_DTAU_MIN, dtau_min}, {EG2D_PARAM_AF_DTAU_MAX, dtau_max}, {EG2D_PARAM_AF_STEPS, static_cast<double>(steps)}};
    return set_params(grid, "eg2d_set_af_cycle", in);
}

EG2D_API int eg2d_set_af_time_rule(eg2d_grid *grid, double a, double b) {
    const ParamValue in[] = {{EG2D_PARAM_AF_A, a}, {EG2D_PARAM_AF_B, b}};
    return set_params(grid, "eg2d_set_af_time_rule", in);
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
