#include "solvers/auto_relaxation.hpp"

#include <algorithm>
#include <cmath>

namespace eg2d {

namespace {
std::size_t nodes(const Level &L) { return static_cast<std::size_t>(L.conn->ni()) * L.conn->nj(); }
}  // namespace

double AutoRelaxation::omega(double target) const {
    const double ramp =
        ramp_ > 0 ? std::min(1.0, static_cast<double>(sweeps_ + 1) / static_cast<double>(ramp_)) : 1.0;
    return 1.0 + share_ * ramp * (target - 1.0);
}

void AutoRelaxation::LevelGuard::save() {
    prev_x.assign(L.x, L.x + nodes(L));
    prev_y.assign(L.y, L.y + nodes(L));
}

double AutoRelaxation::LevelGuard::move() const {
    double m = 0.0;
    for (std::size_t k = 0; k < prev_x.size(); ++k) {
        const double dx = std::fabs(L.x[k] - prev_x[k]), dy = std::fabs(L.y[k] - prev_y[k]);
        if (!std::isfinite(dx + dy)) return std::numeric_limits<double>::infinity();  // std::max drops NaN
        m = std::max(m, std::max(dx, dy));
    }
    return m;
}

void AutoRelaxation::LevelGuard::restore() const {
    std::copy(prev_x.begin(), prev_x.end(), L.x);
    std::copy(prev_y.begin(), prev_y.end(), L.y);
}

bool AutoRelaxation::jumped(double m) {
    if (std::isfinite(m) && m <= kJump * last_move_) return false;
    share_ *= 0.5;
    least_move_ = std::numeric_limits<double>::infinity();
    return true;
}

void AutoRelaxation::settle(double m) {
    const bool ramping = sweeps_ + 1 < ramp_;
    if (ramping) {
        least_move_ = std::numeric_limits<double>::infinity();
    } else if (m > kCreep * least_move_) {
        share_ *= 0.5;
        least_move_ = m;
    } else {
        least_move_ = std::min(least_move_, m);
    }
    last_move_ = m;
    ++sweeps_;
}

long AutoRelaxation::ramp_for(double target) {
    return target < 2.0 ? static_cast<long>(std::ceil(kRampScale / (2.0 - target))) : 0;
}

void AutoRelaxation::reset() {
    sweeps_ = 0;
    share_ = 1.0;
    last_move_ = least_move_ = std::numeric_limits<double>::infinity();
}

}  // namespace eg2d
