// Anderson acceleration of a fixed-point iteration x = G(x) (Walker and Ni,
// SIAM J. Numer. Anal. 49 (2011), "type II"): from the last m iterates and
// their residuals f = G(x) - x, the next iterate is the mixed update of the
// combination whose residual is smallest in the 2-norm,
//   x+ = x + beta f - (dX + beta dF) gamma,  gamma = argmin |f - dF gamma|.
// On a linear map it is GMRES on (I - G'); on a slowly contracting one it
// turns a factor 0.7 per step into the factors of a Krylov method. Used by
// the wall control (wall.cpp), whose fixed point is a control for which the
// converged grid puts the first interior nodes at their targets.
#pragma once
#include <cstddef>
#include <vector>

namespace eg2d {

class Anderson {
public:
    explicit Anderson(int depth = 5) : depth_(depth) {}
    // The next iterate from x and its residual f (same length); the first
    // call, or the first after restart(), is the plain mixed step x + beta f.
    std::vector<double> next(const std::vector<double> &x, const std::vector<double> &f, double beta);
    // Forget the history (the iteration jumped: a limiter acted, the grid changed).
    void restart() { dx_.clear(); df_.clear(); last_x_.clear(); last_f_.clear(); }
    std::size_t history() const { return dx_.size(); }

private:
    int depth_;
    std::vector<std::vector<double>> dx_, df_;  // oldest first
    std::vector<double> last_x_, last_f_;
};

}  // namespace eg2d
