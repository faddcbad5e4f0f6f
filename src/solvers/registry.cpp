// The solvers this library has, by their public EG2D_SOLVER_* id.
// Adding a solver: a file with its class and factory, and one line here.
#include <string>

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
    {EG2D_SOLVER_PSOR, "psor", make_psor, true},
    {EG2D_SOLVER_LSOR, "lsor", make_lsor, false},
    {EG2D_SOLVER_MULTIGRID, "multigrid", make_multigrid, true},
    {EG2D_SOLVER_AF, "af", make_af, false},
    {EG2D_SOLVER_NESTED, "nested", make_nested, true},
};
}

Table<SolverInfo> solver_table() { return table_of(kSolvers); }

const SolverInfo *find_solver(int id) { return solver_table().find(id); }

std::string variational_solver_names() {
    std::string names;
    for (const SolverInfo &s : kSolvers)
        if (s.variational) names += std::string(names.empty() ? "" : ", ") + s.name;
    return names;
}

}  // namespace eg2d
