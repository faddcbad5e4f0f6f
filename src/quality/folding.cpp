// The per-cell fold flag (base/folds.hpp says what a fold is).
#include "base/folds.hpp"
#include "quality/quality.hpp"

namespace eg2d {

void cell_folded(const Grid &g, double *out) {
    const int o = grid_orientation(g);
    for (int j = 0; j < g.nj() - 1; ++j)
        for (int i = 0; i < g.ni() - 1; ++i) out[cell_index(g, i, j)] = is_folded(Cell::at(g, i, j), o) ? 1.0 : 0.0;
}

}  // namespace eg2d
