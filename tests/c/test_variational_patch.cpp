// The variational minimiser's local Newton on a patch
// (solvers/variational_patch): on a square grid with its interior nodes
// shaken, V over a patch of nodes falls, the patch's gradient falls by the
// asked factor, the nodes outside the patch stay where they were and no cell
// folds.
#include <cmath>
#include <cstdio>
#include <vector>

#include "base/connectivity.hpp"
#include "operator/variational_cell.hpp"
#include "solvers/variational_patch.hpp"

static int failures = 0;
static void check(bool ok, const char *what, double value) {
    std::printf("%-58s %.3e %s\n", what, value, ok ? "ok" : "FAILED");
    if (!ok) ++failures;
}

static const int lx[4] = {0, 1, 1, 0}, ly[4] = {0, 0, 1, 1};

// V over the whole grid and the gradient's norm over the nodes in `in`.
static double grid_value(int n, const std::vector<double> &x, const std::vector<double> &y, const eg2d::Functional &F,
                         double mean, const std::vector<char> &in, double &gnorm) {
    std::vector<double> g(2 * x.size(), 0.0);
    double v = 0.0;
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            double cx[4], cy[4];
            int k[4];
            for (int m = 0; m < 4; ++m) {
                k[m] = i + lx[m] + n * (j + ly[m]);
                cx[m] = x[k[m]];
                cy[m] = y[k[m]];
            }
            eg2d::CellTerms t;
            eg2d::cell_terms(F, mean, cx, cy, false, t);
            v += t.value;
            for (int m = 0; m < 4; ++m) {
                g[2 * k[m]] += t.g[2 * m];
                g[2 * k[m] + 1] += t.g[2 * m + 1];
            }
        }
    gnorm = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k)
        if (in[k]) gnorm += g[2 * k] * g[2 * k] + g[2 * k + 1] * g[2 * k + 1];
    gnorm = std::sqrt(gnorm);
    return v;
}

static int folded(int n, const std::vector<double> &x, const std::vector<double> &y) {
    int count = 0;
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i)
            for (int m = 0; m < 4; ++m) {
                const int a = i + lx[m] + n * (j + ly[m]), b = i + lx[(m + 1) % 4] + n * (j + ly[(m + 1) % 4]),
                          c = i + lx[(m + 3) % 4] + n * (j + ly[(m + 3) % 4]);
                if ((x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a]) <= 0.0) ++count;
            }
    return count;
}

int main() {
    const int n = 17;
    const double h = 1.0 / (n - 1), mean = h * h;
    // a large (10, 1, 1 as cotangents, d 1), under the fold guard.
    const eg2d::Functional F = eg2d::make_functional(10.0, 1.0, 1.0, 1.0, true, mean, 1);
    std::vector<double> x(n * n), y(n * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const bool inner = i > 0 && j > 0 && i + 1 < n && j + 1 < n;
            x[i + n * j] = i * h + (inner ? 0.3 * h * std::sin(1.7 * i + 2.3 * j) : 0.0);
            y[i + n * j] = j * h + (inner ? 0.3 * h * std::cos(2.9 * i - 1.1 * j) : 0.0);
        }
    const eg2d::Connectivity conn(n, n, eg2d::Topology::Single);
    eg2d::BlockStencil layout;
    layout.resize(n, n, false);
    for (int j = 1; j + 1 < n; ++j)
        for (int i = 1; i + 1 < n; ++i) layout.unknown[i + n * j] = 1;
    // The patch: a 6x4 block of nodes off the centre.
    std::vector<std::size_t> set;
    std::vector<char> in(n * n, 0);
    for (int j = 4; j < 8; ++j)
        for (int i = 5; i < 11; ++i) {
            set.push_back(static_cast<std::size_t>(i + n * j));
            in[i + n * j] = 1;
        }
    double g0 = 0.0, g1 = 0.0;
    const double v0 = grid_value(n, x, y, F, mean, in, g0);
    const std::vector<double> x0 = x, y0 = y;
    eg2d::PatchNewton patch;
    const int steps = patch.solve(conn, layout, set, x.data(), y.data(), F, mean, 20, 1e-6);
    const double v1 = grid_value(n, x, y, F, mean, in, g1);
    check(steps > 0 && steps < 20, "Newton steps on the patch (to a gradient 1e-6 of its first)", steps);
    check(v1 < v0, "V falls", v0 - v1);
    check(g1 <= 1e-6 * g0, "the patch's gradient falls by 1e-6", g1 / g0);
    double moved = 0.0;
    for (int k = 0; k < n * n; ++k)
        if (!in[k]) moved = std::fmax(moved, std::fabs(x[k] - x0[k]) + std::fabs(y[k] - y0[k]));
    check(moved == 0.0, "nodes outside the patch held", moved);
    check(folded(n, x, y) == 0, "no corner flat or folded", folded(n, x, y));
    return failures ? 1 : 0;
}
