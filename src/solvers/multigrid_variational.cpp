#include "solvers/multigrid_variational.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "base/folds.hpp"

namespace eg2d {

long variational_sweeps(const Level &L) {
    const Connectivity &conn = *L.conn;
    long refused = 0;
    auto relax = [&](int i, int j) { refused += relax_variational(L, i, j, 1.0) == NodeStep::Limited; };
    for (int j = conn.j_begin(); j < conn.j_end(); ++j)
        for (int i = conn.i_begin(); i < conn.i_end(); ++i) relax(i, j);
    for (const Connectivity::Node &n : conn.extra_unknowns()) relax(n.i, n.j);
    for (int j = conn.j_end() - 1; j >= conn.j_begin(); --j)
        for (int i = conn.i_end() - 1; i >= conn.i_begin(); --i) relax(i, j);
    for (const Connectivity::Node &n : conn.extra_unknowns()) relax(n.i, n.j);
    return refused;
}

long folded_cells(const Level &L, int orientation) {
    const std::size_t ni = static_cast<std::size_t>(L.conn->ni()), nj = static_cast<std::size_t>(L.conn->nj());
    long folded = 0;
    for (std::size_t j = 0; j + 1 < nj; ++j)
        for (std::size_t i = 0; i + 1 < ni; ++i) {
            const std::size_t k = i + ni * j, corner[4] = {k, k + 1, k + 1 + ni, k + ni};
            Cell c;
            for (int m = 0; m < 4; ++m) {
                c.x[m] = L.x[corner[m]];
                c.y[m] = L.y[corner[m]];
            }
            folded += is_folded(c, orientation);
        }
    return folded;
}

double prolong_guarded(const MgLevel &coarse, const Level &fine, std::vector<double> &save) {
    const int orientation = fine.functional ? fine.functional->orientation : 0;
    if (orientation == 0) {
        prolong_correction(coarse, fine);
        return 1.0;
    }
    const std::size_t n = static_cast<std::size_t>(fine.conn->ni()) * fine.conn->nj();
    save.resize(2 * n);
    std::copy(fine.x, fine.x + n, save.begin());
    std::copy(fine.y, fine.y + n, save.begin() + static_cast<std::ptrdiff_t>(n));
    const long before = folded_cells(fine, orientation);
    prolong_correction(coarse, fine);
    double kept = 1.0;
    while (folded_cells(fine, orientation) > before) {
        kept *= 0.5;
        // Back to the start plus `kept` of the full correction: the fine
        // arrays hold start + full/2^k, so halving the step from the start is
        // x = (x + save)/2.
        for (std::size_t k = 0; k < n; ++k) {
            fine.x[k] = kept < 0.1 ? save[k] : 0.5 * (fine.x[k] + save[k]);
            fine.y[k] = kept < 0.1 ? save[n + k] : 0.5 * (fine.y[k] + save[n + k]);
        }
        if (kept < 0.1) return 0.0;
    }
    return kept;
}

void FoldStall::observe(double residual, long refused) {
    if (best_ < 0.0 || residual <= kProgress * best_) {
        best_ = residual;
        since_ = 0;
        refused_ = 0;
        return;
    }
    refused_ += refused;
    if (++since_ < kCycles || refused_ == 0) return;
    fail(Failure::NotConverged,
         format("variational: the gradient norm fell by less than %g in %d cycles (best %.3g) while the fold "
                "guard shortened %ld node steps: the minimum of V for these weights folds or collapses cells, and "
                "the grid is kept unfolded short of it. Raise the area weight, or set EG2D_PARAM_FOLD_CHECK to 0 "
                "for the unconstrained minimum",
                1.0 / kProgress, kCycles, best_, refused_));
}

}  // namespace eg2d
