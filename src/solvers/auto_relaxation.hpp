// Automatic over-relaxation for the SOR sweeps (point, line, coarse-to-fine),
// when the relaxation setting is 0. Each solver names a target factor (the
// optimum of the Laplace model problem, the elliptic-grid course notes for points, line_relax.hpp
// for lines); this class decides how much of its over-relaxation (omega - 1)
// a sweep may use, from what the sweeps do to the grid:
//  - a ramp: from Gauss-Seidel (omega = 1) linearly up to the target over the
//    first ramp_for(target) sweeps after a reset: the sweeps the target needs
//    for about four decades of residual (SOR's rate at omega is about
//    omega - 1: 1/(2 - omega) sweeps per e-fold), so about max(ni, nj) for
//    line SOR on a square grid but 50 on a 257x33 one (the old ramp of
//    max(ni, nj) cost 3x there). Over-relaxing from a TFI start folds
//    Winslow grids: fixed omega = 1.8 diverges in 1-5 sweeps on the swan and
//    the NACA0012 O- and C-grids at 129 (bench), yet the same factors
//    converge once the grid is near its solution.
//  - a jump guard: a sweep whose largest move is more than kJump times the
//    previous sweep's is undone, the over-relaxation halved, and the sweep
//    redone. A sweep that converges moves the grid a little less each time;
//    a blow-up starts with such a jump (the NACA0012 O-grid at 513x129 blew
//    up within one sweep under an earlier line-SOR rule). No bench case
//    triggers it now; it is the net under the ramp.
//  - a creep guard, once the ramp is over: a move kCreep times the least
//    since the ramp ended (or the last back-off) halves the over-relaxation.
//    During the ramp the moves legitimately grow (about 10x on the swan
//    257^2: the faster a sweep converges the more it moves), which the old
//    rule (a 10x rise over the whole run) took for divergence, backing the
//    swan 257^2 off to 2747+ sweeps where 569 suffice.
#pragma once
#include <cstddef>
#include <limits>
#include <vector>

#include "operator/operator.hpp"

namespace eg2d {

class AutoRelaxation {
public:
    // The factor to use this sweep for a solver whose target is `target`.
    double omega(double target) const;

    // One guarded sweep: `sweep()` relaxes L with factors from omega(); it
    // may run twice (undone and redone after a jump). `ramp` = 0: the start
    // is already near the solution (coarse-to-fine), no ramp.
    template <class Sweep>
    void sweep(const Level &L, long ramp, Sweep &&sweep) {
        LevelGuard guard{L, prev_x_, prev_y_};
        sweep_guarded(guard, ramp, sweep);
    }
    // The same on any coordinates a sweep moves: `guarded` keeps them
    // (save()), puts them back (restore()) and gives the largest change
    // since (move(), infinite if any is not finite): a set of blocks
    // (blocks/composite.hpp) as well as a grid level.
    template <class Guarded, class Sweep>
    void sweep_guarded(Guarded &guarded, long ramp, Sweep &&sweep) {
        ramp_ = ramp;
        guarded.save();
        sweep();
        double m = guarded.move();
        if (jumped(m)) {
            guarded.restore();
            sweep();
            m = guarded.move();
        }
        settle(m);
    }

    void reset();

    // The ramp length for a target factor: kRampScale / (2 - target) sweeps
    // (line SOR's model optimum on an n x n grid: 2 - omega = 8.9/n).
    static long ramp_for(double target);
    static constexpr double kRampScale = 9.0;

private:
    static constexpr double kJump = 3.0;
    static constexpr double kCreep = 10.0;
    // A grid level's coordinates, kept in the class's arrays (their
    // capacity kept: no allocation after the first sweep).
    struct LevelGuard {
        const Level &L;
        std::vector<double> &prev_x, &prev_y;
        void save();
        void restore() const;
        double move() const;
    };
    bool jumped(double move);           // backs off if so
    void settle(double move);

    long ramp_ = 0;
    long sweeps_ = 0;     // since the last reset
    double share_ = 1.0;  // of the target's over-relaxation still allowed
    double last_move_ = std::numeric_limits<double>::infinity();
    double least_move_ = std::numeric_limits<double>::infinity();
    std::vector<double> prev_x_, prev_y_;
};

}  // namespace eg2d
