// The orthogonality methods of eg2d_set_orthogonality, by their public
// EG2D_ORTHO_* id. Adding a method: a file with its Control and factory,
// and one line here (a factory nothing else calls is declared just above
// the table, as solvers/registry.cpp does).
#include "controls/registry.hpp"

#include "eg2d.h"
#include "base/error.hpp"
#include "controls/controls.hpp"

namespace eg2d {

namespace {
const OrthogonalityMethod kMethods[] = {
    {EG2D_ORTHO_NONE, "none", "EG2D_ORTHO_NONE", nullptr},
    {EG2D_ORTHO_MIDDLECOFF_THOMAS, "middlecoff-thomas", "EG2D_ORTHO_MIDDLECOFF_THOMAS",
     [](const std::array<double, 4> &) { return make_middlecoff_thomas(); }},
    {EG2D_ORTHO_WALL, "wall", "EG2D_ORTHO_WALL", make_wall_control},
};
}  // namespace

Table<OrthogonalityMethod> orthogonality_table() { return table_of(kMethods); }

const OrthogonalityMethod *find_orthogonality(int id) { return orthogonality_table().find(id); }

std::string orthogonality_ids() {
    std::string s;
    const std::size_t n = sizeof kMethods / sizeof kMethods[0];
    for (std::size_t k = 0; k < n; ++k) {
        if (k > 0) s += k + 1 == n ? " or " : ", ";
        s += format("%s (%d)", kMethods[k].constant, kMethods[k].id);
    }
    return s;
}

}  // namespace eg2d
