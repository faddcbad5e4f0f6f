#include "blocks/set_multigrid.hpp"

#include "base/error.hpp"
#include "solvers/multigrid_hierarchy.hpp"  // kMaxCoarseStretching

namespace eg2d {

namespace {
// The coarsest level: sweeps until its residual falls by this, at most kCoarseSweeps.
constexpr double kCoarseReduction = 1e-3;
constexpr int kCoarseSweeps = 50;
// A coarsest level with more nodes than this along a block's side is a
// level the set could not halve (an odd cell count), not its natural bottom.
constexpr int kLargeSetCoarsest = 17;
}  // namespace

SetMultigrid::SetMultigrid(const Composite &fine) {
    const Composite *c = &fine;
    while (c->coarsenable()) {
        Composite next = c->coarsened();
        // Phi and Psi double with each halving (the wall layer's): as the
        // single block's hierarchy (multigrid_hierarchy.hpp), a level past
        // kMaxCoarseStretching is not built unless the one above is large;
        // then it is, its controls clipped. Large is a side of more than
        // kLargeSetCoarsest nodes, not the single block's 65536 nodes: the
        // bump in two blocks with walls (8000 nodes) stalled at 1e-3 on the
        // smoother alone, and converges in 3 cycles clipped.
        const double stretching = next.stretching();
        if (stretching > kMaxCoarseStretching) {
            if (c->longest() <= kLargeSetCoarsest) {
                stopped_ = format("its controls (Phi, Psi up to %.3g there) would pass %g", stretching,
                                  kMaxCoarseStretching);
                return;
            }
            clipped_ += next.clip_stretching(kMaxCoarseStretching);
        }
        coarse_.push_back(std::move(next));
        c = &coarse_.back();
    }
    // Said when the set did not halve at all, or its coarsest level is still
    // large: a set halved down to a few nodes a side has stopped where any
    // multigrid stops.
    if (coarse_.empty() || c->longest() > kLargeSetCoarsest) stopped_ = c->why_not_coarsenable();
}

void SetMultigrid::cycle(System system, Composite &fine, int index, int pre, int post) {
    cycle(system, fine, 0, index, pre, post);
}

void SetMultigrid::solve_coarsest(System system, Composite &c) const {
    const double r0 = c.residual(system, 0.0);
    for (int s = 0; s < kCoarseSweeps && c.residual(system, 0.0) > kCoarseReduction * r0; ++s) c.smooth(system);
}

void SetMultigrid::fmg(System system, Composite &fine, int index, int pre, int post) {
    if (coarse_.empty()) {
        cycle(system, fine, 0, index, pre, post);
        return;
    }
    for (std::size_t l = 0; l < coarse_.size(); ++l) {
        coarse_[l].sample(l == 0 ? fine : coarse_[l - 1]);
        coarse_[l].start_fmg();
    }
    solve_coarsest(system, coarse_.back());
    for (std::size_t l = coarse_.size(); l-- > 0;) {
        Composite &finer = l == 0 ? fine : coarse_[l - 1];
        coarse_[l].prolong_to(finer);
        cycle(system, finer, l, index, pre, post);
    }
}

void SetMultigrid::cycle(System system, Composite &fine, std::size_t level, int index, int pre, int post) {
    if (level == coarse_.size()) {  // the coarsest level (or a set that does not coarsen)
        solve_coarsest(system, fine);
        return;
    }
    for (int s = 0; s < pre; ++s) fine.smooth(system);
    fine.compute_residual(system);
    Composite &coarse = coarse_[level];
    coarse.sample(fine);
    coarse.restrict_from(system, fine);
    for (int g = 0; g < (level + 1 == coarse_.size() ? 1 : index); ++g) cycle(system, coarse, level + 1, index, pre, post);
    coarse.prolong_to(fine);
    for (int s = 0; s < post; ++s) fine.smooth(system);
}

}  // namespace eg2d
