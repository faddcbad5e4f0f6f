// The solvers this library has, by their public EG2D_SOLVER_* id.
// Adding a solver: a file with its class and factory, and one line here.
#include "eg2d.h"
#include "solvers/solver.hpp"

namespace eg2d {

std::unique_ptr<Solver> make_psor();
std::unique_ptr<Solver> make_lsor();
std::unique_ptr<Solver> make_multigrid();
std::unique_ptr<Solver> make_af();
std::unique_ptr<Solver> make_nested();

namespace {
const SolverInfo kSolvers[] = {
    {EG2D_SOLVER_PSOR, "psor", make_psor},
    {EG2D_SOLVER_LSOR, "lsor", make_lsor},
    {EG2D_SOLVER_MULTIGRID, "multigrid", make_multigrid},
    {EG2D_SOLVER_AF, "af", make_af},
    {EG2D_SOLVER_NESTED, "nested", make_nested},
};
}

const SolverInfo *find_solver(int id) {
    for (const SolverInfo &s : kSolvers)
        if (s.id == id) return &s;
    return nullptr;
}

}  // namespace eg2d
