#include "solvers/newton_progress.hpp"

#include <cmath>

#include "base/error.hpp"

namespace eg2d {

void NewtonProgress::restart() { *this = NewtonProgress{}; }

void NewtonProgress::observe(double residual, double energy, bool limited, bool barrier, double shift) {
    limited_ = limited ? limited_ + 1 : 0;
    // V is infinite on a folded corner with a barrier in it: against an
    // infinite mark (the first, or V at a step from a folded grid) any finite
    // V counts as lower; an infinite or NaN V never does. Tested before the
    // arithmetic, which would raise FE_INVALID (inf - inf).
    const bool lower = std::isfinite(energy) &&
                       (!std::isfinite(mark_) || energy < mark_ - kEnergyProgress * std::fabs(mark_));
    if (lower) mark_ = energy;
    if (best_ < 0.0 || residual <= kProgress * best_) {
        best_ = residual;
        since_best_ = since_progress_ = 0;
        mark_ = energy;
        return;
    }
    if (!(barrier && limited)) ++since_best_;
    since_progress_ = lower ? 0 : since_progress_ + 1;
    if (limited_ >= kStallSteps && since_best_ >= kStallSteps && !barrier)
        fail(Failure::NotConverged,
             format("variational: the fold guard shortened the last %d Newton steps and the residual fell by less "
                    "than %g in them (best %.3g): the minimum of V for these weights folds or collapses cells, and "
                    "the grid is kept unfolded short of it. Raise the area weight, or set EG2D_PARAM_FOLD_CHECK to 0 "
                    "for the unconstrained minimum",
                    limited_, 1.0 / kProgress, best_));
    if (barrier && limited_ >= kBarrierSteps)
        fail(Failure::NotConverged,
             format("variational: the fold limit shortened the last %d Newton steps (residual best %.3g): V's "
                    "minimum lies near flat corners that the steps approach slowly",
                    limited_, best_));
    if (since_best_ >= kNoProgressSteps && since_progress_ >= kNoProgressSteps)
        fail(Failure::NotConverged,
             format("variational: in %d Newton steps the residual fell by less than %g and V by less than %g of "
                    "itself (residual best %.3g, Levenberg shift %.3g)",
                    kNoProgressSteps, 1.0 / kProgress, kEnergyProgress, best_, shift));
}

}  // namespace eg2d
