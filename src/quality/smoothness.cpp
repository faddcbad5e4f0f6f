// Smoothness: how abruptly the cell size changes from a cell to its
// neighbours. The size in i is the cell's mean width along i, and the
// smoothness in i of a cell is the largest ratio (>= 1) of its size to the
// size of its neighbours at i-1 and i+1 (the stretching ratio); likewise j.
// On an O-grid the neighbours in i continue across the branch cut.
#include <algorithm>
#include <limits>
#include <vector>

#include "base/cell.hpp"
#include "quality/quality.hpp"

namespace eg2d {

namespace {
double ratio(double a, double b) {
    const double lo = std::min(a, b), hi = std::max(a, b);
    if (hi == 0.0) return 1.0;
    return lo > 0.0 ? hi / lo : std::numeric_limits<double>::infinity();
}

void smoothness(const Grid &g, double *out, bool along_i) {
    const int ci = g.ni() - 1, cj = g.nj() - 1;
    const bool periodic = along_i && g.connectivity().periodic_i();
    std::vector<double> size(cell_count(g));
    for (int j = 0; j < cj; ++j)
        for (int i = 0; i < ci; ++i) {
            const Cell c = Cell::at(g, i, j);
            size[cell_index(g, i, j)] = along_i ? c.width_i() : c.width_j();
        }
    for (int j = 0; j < cj; ++j)
        for (int i = 0; i < ci; ++i) {
            const double s = size[cell_index(g, i, j)];
            double r = 1.0;
            for (int d = -1; d <= 1; d += 2) {
                int ni = along_i ? i + d : i, nj = along_i ? j : j + d;
                if (periodic) ni = (ni + ci) % ci;
                if (ni < 0 || ni >= ci || nj < 0 || nj >= cj) continue;
                r = std::max(r, ratio(s, size[cell_index(g, ni, nj)]));
            }
            out[cell_index(g, i, j)] = r;
        }
}
}  // namespace

void cell_smoothness_i(const Grid &g, double *out) { smoothness(g, out, true); }
void cell_smoothness_j(const Grid &g, double *out) { smoothness(g, out, false); }

}  // namespace eg2d
