// A graded line's cells fitted to its length away from its walls
// (graded_layer.hpp): the walls' cells keep their heights.
#include <algorithm>
#include <cmath>

#include "grid/graded_layer.hpp"

namespace eg2d {

namespace {

// fit_length's factor F is at most e^kMostLogScale either way (beyond, the
// cells are scaled in proportion), found by kBisections halvings of its log.
constexpr double kMostLogScale = 20.0;
constexpr int kBisections = 60;

}  // namespace

std::vector<double> wall_shares(int cells, bool lo, bool hi) {
    auto share = [](int k) {
        const double t = std::clamp(static_cast<double>(k - kGradedRows) / kGradedRows, 0.0, 1.0);
        return 1.0 - t * t * (3.0 - 2.0 * t);
    };
    std::vector<double> v(static_cast<std::size_t>(std::max(cells, 0)));
    for (int k = 0; k < cells; ++k) v[static_cast<std::size_t>(k)] = std::max(lo ? share(k) : 0.0, hi ? share(cells - 1 - k) : 0.0);
    return v;
}

std::vector<double> fit_length(std::vector<double> cells, const std::vector<double> &share, double length) {
    auto sum = [&](double log_f) {
        double t = 0.0;
        for (std::size_t q = 0; q < cells.size(); ++q) t += cells[q] * std::exp((1.0 - share[q]) * log_f);
        return t;
    };
    double a = -kMostLogScale, b = kMostLogScale;
    if (sum(a) < length && sum(b) > length) {
        for (int it = 0; it < kBisections; ++it) (sum(0.5 * (a + b)) < length ? a : b) = 0.5 * (a + b);
        const double log_f = 0.5 * (a + b);
        for (std::size_t q = 0; q < cells.size(); ++q) cells[q] *= std::exp((1.0 - share[q]) * log_f);
        return cells;
    }
    double total = 0.0;  // no room away from the walls: all cells in proportion
    for (double c : cells) total += c;
    for (double &c : cells) c *= length / total;
    return cells;
}

}  // namespace eg2d
