// When the variational Newton minimiser (variational_newton.hpp) gives up:
// its stop tests on the residual, on V and on the fold limit, one place
// apart from the steps so that they can be tested on given sequences.
#pragma once

#include <limits>

namespace eg2d {

class NewtonProgress {
public:
    // The fold guard's stall: the fold limit shortened the last kStallSteps
    // Newton steps and the residual is not down by kProgress in them (a
    // corner driven towards flat comes half the way closer per step and
    // never arrives). Grid sequencing's coarse levels give up after as many.
    static constexpr int kStallSteps = 12;
    static constexpr double kProgress = 0.8;
    // With a barrier in V (the smoothness term W or O's cotangent form, both
    // infinite on a flat corner) V's minimum is unfolded, and steps the fold
    // limit shortens are the way there (the antenna with a = 10, b = 1,
    // c = 1 as cotangents, d = 1: at 129^2 all but the last 5 or so of its
    // 81 Newton steps are shortened; bench/RESULTS.md). The residual need not
    // fall on that way, so a shortened step is not counted against progress
    // either; kBarrierSteps shortened steps in a row end the run.
    static constexpr int kBarrierSteps = 500;
    // No progress at all in kNoProgressSteps steps ends the run too: neither
    // the residual down by kProgress nor V down by kEnergyProgress of itself.
    // V is not convex, and its residual (a max norm) need not fall on the way
    // from a saddle to the minimum: Ab on the swan at 129^2 lowers V steadily
    // for about 110 steps with the residual between 2e-6 and 4e-5, then
    // converges quadratically (bench/RESULTS.md).
    static constexpr int kNoProgressSteps = 40;
    static constexpr double kEnergyProgress = 1e-9;

    void restart();
    // After a step: the residual after it, V where it began (so a fall in V
    // is seen one step late), whether the fold limit shortened it, whether V
    // has a barrier, the Levenberg shift (for the message). Throws
    // Failure::NotConverged saying which test ended the run.
    void observe(double residual, double energy, bool limited, bool barrier, double shift);

private:
    double best_ = -1.0;  // the best residual so far
    double mark_ = std::numeric_limits<double>::infinity();  // V when the run last made progress
    int since_best_ = 0;      // steps since the residual fell by kProgress (not counting barrier-limited ones)
    int since_progress_ = 0;  // steps since the residual or V fell enough
    int limited_ = 0;         // fold-limited steps in a row
};

}  // namespace eg2d
