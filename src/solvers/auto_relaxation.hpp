// Automatic over-relaxation for the SOR sweeps. For Laplace it is seed 003's
// optimal factor (SOR converges there for any omega in (0, 2)). Winslow's
// frozen coefficients make that factor unstable on some grids (valley 257^2 and a NACA0012 O-grid 257x65 diverge at
// omega = 1.97: the residual creeps up for a hundred sweeps, then explodes),
// so Winslow starts at the optimum of a grid half as fine (2 - omega doubled;
// 1.952 at 257^2, which converges there), and whenever the residual after a
// sweep rises 10x above the best seen after any earlier sweep, 2 - omega is
// doubled again. The start grid's residual does not count: the first sweep from TFI
// often raises the max-norm residual. Stable cases keep the optimal factor.
#pragma once
#include <limits>

#include "core/settings.hpp"
#include "operator/system.hpp"

namespace eg2d {

class AutoRelaxation {
public:
    // The user's factor if one is set, else the adaptive one for an n1 x n2 grid.
    double omega(const Settings &settings, System system, int n1, int n2) const;
    // The residual after an iteration.
    void observe(double residual);
    void reset() {
        widening_ = 1.0;
        best_ = std::numeric_limits<double>::infinity();
    }

private:
    double widening_ = 1.0;  // multiplies 2 - omega_opt
    double best_ = std::numeric_limits<double>::infinity();
};

}  // namespace eg2d
