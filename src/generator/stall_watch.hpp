// When a run has stopped making progress (Generator::run): no new best of
// the residual, or of a wall control's mismatch, by kStallGain within a
// window of iterations. A run that ends NOT_CONVERGED after 100,000
// iterations at a rate of 1.0000 says no more than one that ends after a
// window, and takes minutes where the window takes a second.
#pragma once

namespace eg2d {

class StallWatch {
public:
    explicit StallWatch(long window) : window_(window) {}
    // After iteration `it`: residual r, mismatch m (0 without a dynamic
    // control). True once `window` iterations have passed with neither
    // bettered by kStallGain.
    bool stalled(long it, double r, double m) {
        if (r < kStallGain * best_r_ || m < kStallGain * best_m_ || it == 0) {
            if (r < best_r_) best_r_ = r;
            if (m < best_m_) best_m_ = m;
            since_ = it;
        }
        return window_ > 0 && it - since_ >= window_;
    }
    long since() const { return since_; }
    long window() const { return window_; }
    double best_residual() const { return best_r_; }

    // A mismatch not measured yet (before a dynamic control's first update).
    static constexpr double kUnknown = 1e300;
    // A new best by less than this (10%) is no progress.
    static constexpr double kStallGain = 0.9;

private:
    long window_;
    double best_r_ = kUnknown, best_m_ = kUnknown;
    long since_ = 0;
};

}  // namespace eg2d
