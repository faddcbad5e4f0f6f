#include "tmr_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace eg2dtool {

namespace {

// The finest TMR level's published figures.
constexpr int kFinestNi = 7169, kFinestNj = 2049, kLevels = 7;
constexpr int kAirfoilCells = 4096, kWakeCells = 1536;
constexpr double kFirstCell = 1e-7, kGrowth = 1.02, kLeSpacing = 1.25e-5, kFarField = 500.0;

std::string line(const char *figure, const std::string &published, const std::string &grid) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "  %-38s %-28s %s\n", figure, published.c_str(), grid.c_str());
    return buf;
}

std::string number(const char *fmt, double a, double b = 0.0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, a, b);
    return buf;
}

}  // namespace

int tmr_level(int ni, int nj) {
    for (int k = 0; k < kLevels; ++k)
        if (ni == (kFinestNi - 1) / (1 << k) + 1 && nj == (kFinestNj - 1) / (1 << k) + 1) return k;
    return -1;
}

std::string tmr_comparison(const eg2d_grid *g, int ni, int nj, int wake, double farfield, int written_below) {
    const int k = tmr_level(ni, nj);
    if (k < 0) return {};
    const int s = 1 << k;
    std::vector<double> x(static_cast<std::size_t>(ni) * nj), y(x.size());
    eg2d_get_coordinates(g, x.data(), y.data());
    auto at = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
    auto dist = [&](std::size_t a, std::size_t b) { return std::hypot(x[b] - x[a], y[b] - y[a]); };
    const int b0 = wake, b1 = ni - 1 - wake;  // the body's nodes, trailing edge to trailing edge
    double h_min = std::numeric_limits<double>::infinity(), h_max = 0, ds_min = h_min, g_sum = 0, g_max = 0;
    for (int i = b0; i <= b1; ++i) {
        const double h1 = dist(at(i, 0), at(i, 1)), h2 = dist(at(i, 1), at(i, 2));
        h_min = std::min(h_min, h1);
        h_max = std::max(h_max, h1);
        if (i > b0 && i < b1) {  // the trailing edge's two nodes turn with the cut
            g_sum += h2 / h1;
            g_max = std::max(g_max, h2 / h1);
        }
        if (i < b1) ds_min = std::min(ds_min, dist(at(i, 0), at(i + 1, 0)));
    }
    // The far field: the least distance of an outer node from the section
    // (its nodes every 8th, enough at 500 chords).
    double far = std::numeric_limits<double>::infinity();
    for (int i = 0; i < ni; ++i)
        for (int w = b0; w <= b1; w += 8) far = std::min(far, dist(at(i, nj - 1), at(w, 0)));
    const double tmr_first = kFirstCell * (std::pow(kGrowth, s) - 1.0) / (kGrowth - 1.0);

    std::string out = number("against the published NASA TMR NACA 0012 C-grid family, its level %.0f of 7 "
                             "(%.0f times coarser than 7169x2049):\n", k + 1, s);
    out += line("figure", "TMR (published, this level)", "this grid");
    out += line("size", number("%.0fx%.0f", ni, nj), number("%.0fx%.0f", ni, nj));
    out += line("points on the airfoil", number("%.0f", kAirfoilCells / s + 1), number("%.0f", b1 - b0 + 1));
    out += line("points on each side of the wake", number("%.0f", kWakeCells / s + 1), number("%.0f", wake + 1));
    out += line("first cell, chords", number("%.3g", tmr_first), number("%.4g to %.4g", h_min, h_max));
    out += line("wall-normal growth, first cells", number("about %.3g", std::pow(kGrowth, s)),
                number("mean %.4g, largest %.4g", g_sum / std::max(1, b1 - b0 - 1), g_max));
    out += line("leading-edge spacing, chords", number("about %.3g", kLeSpacing * s), number("%.4g (smallest)", ds_min));
    out += line("far field, chords", number("about %.0f", kFarField),
                number("%.4g (nearest outer node; %g asked)", far, farfield));
    out += line("coarser nested levels below this one", k == kLevels - 1 ? std::string("none (the coarsest)") : number("%.0f, down to 113x33", kLevels - 1 - k),
                number("%.0f written, each every other node", written_below));
    return out;
}

}  // namespace eg2dtool
