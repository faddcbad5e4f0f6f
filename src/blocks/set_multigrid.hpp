// FAS multigrid over a set of blocks (Trottenberg, Oosterlee & Schueller
// 2001, ch. 5): every level is the whole set coarsened by two (each block
// and each join halved: Composite::coarsened), so the coarse grids correct
// the set as one grid and the joins coarsen with it. Smoother: the ILU
// sweeps of the single-block multigrid on each block in turn, its copies
// and halos passed on after each block; full weighting across the joins
// (the residual's halos), bilinear corrections, the coarsest level
// smoothed to a thousandth of its residual.
#pragma once
#include <string>
#include <vector>

#include "blocks/composite.hpp"

namespace eg2d {

class SetMultigrid {
public:
    // The levels below `fine` while the set coarsens (Composite::coarsenable).
    explicit SetMultigrid(const Composite &fine);
    int levels() const { return static_cast<int>(coarse_.size()) + 1; }
    // Why there is no coarser level below the coarsest ("" when it is too
    // small to halve again is not the reason: Composite::why_not_coarsenable).
    const std::string &stopped() const { return stopped_; }
    // Coarse control values clipped to kMaxCoarseStretching (0: none).
    long clipped() const { return clipped_; }
    // One cycle: index 1 V, 2 W; pre and post smoothing sweeps per level.
    void cycle(System system, Composite &fine, int index, int pre, int post);
    // Full multigrid from the start the fine level holds: every level
    // sampled from it, the coarsest solved, then on each finer level the
    // coarser one's correction and one cycle (counts as the first cycle).
    void fmg(System system, Composite &fine, int index, int pre, int post);
    // The nested iteration's start (Petrilli 1989, the Phoenix grid code's
    // coarse-to-fine phase): from the coarsest level up, each level swept
    // by `solve` until its residual is below `tolerance` or it makes no
    // progress, its change interpolated into the next finer one.
    template <class Solve>
    void coarse_to_fine(Composite &fine, Solve &&solve) {
        for (std::size_t l = 0; l < coarse_.size(); ++l) {
            coarse_[l].sample(l == 0 ? fine : coarse_[l - 1]);
            coarse_[l].start_fmg();
        }
        for (std::size_t l = coarse_.size(); l-- > 0;) {
            solve(coarse_[l]);
            coarse_[l].prolong_to(l == 0 ? fine : coarse_[l - 1]);
        }
    }

private:
    void solve_coarsest(System system, Composite &c) const;
    void cycle(System system, Composite &fine, std::size_t level, int index, int pre, int post);
    std::vector<Composite> coarse_;
    std::string stopped_;
    long clipped_ = 0;
};

}  // namespace eg2d
