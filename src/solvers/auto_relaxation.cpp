#include "solvers/auto_relaxation.hpp"

#include "solvers/solver.hpp"

namespace eg2d {

namespace {
constexpr double kRiseFactor = 10.0;
}

double AutoRelaxation::omega(const Settings &settings, System system, int n1, int n2) const {
    if (settings.relaxation > 0.0) return settings.relaxation;
    const double widening = system == System::Winslow ? 2.0 * widening_ : widening_;
    const double omega = 2.0 - widening * (2.0 - optimal_sor_omega(n1, n2));
    return omega > 1.0 ? omega : 1.0;
}

void AutoRelaxation::observe(double residual) {
    if (!(residual == residual)) return;  // NaN: the run loop handles divergence
    if (residual > kRiseFactor * best_) {
        widening_ *= 2.0;
        best_ = residual;
    } else if (residual < best_) {
        best_ = residual;
    }
}

}  // namespace eg2d
