// The Newton minimiser's parts: one cell's V, gradient and Hessians
// (operator/variational_cell) against finite differences, the convex
// Hessian positive semidefinite where the exact one is not, and the block
// multigrid V-cycle (solvers/block_multigrid) as a convergent iteration on
// a nine-point 2x2-block system.
#include <cmath>
#include <cstdio>
#include <vector>

#include "operator/smoothness_cell.hpp"
#include "operator/variational_cell.hpp"
#include "solvers/block_multigrid.hpp"

static int failures = 0;
static void check(bool ok, const char *what, double value) {
    std::printf("%-58s %.3e %s\n", what, value, ok ? "ok" : "FAILED");
    if (!ok) ++failures;
}

static double value_at(const eg2d::Functional &F, double mean, const double *z) {
    double x[4], y[4];
    for (int m = 0; m < 4; ++m) x[m] = z[2 * m], y[m] = z[2 * m + 1];
    return eg2d::cell_value(F, mean, x, y);
}

static void gradient_at(const eg2d::Functional &F, double mean, const double *z, double *g) {
    double x[4], y[4];
    for (int m = 0; m < 4; ++m) x[m] = z[2 * m], y[m] = z[2 * m + 1];
    eg2d::CellTerms t;
    eg2d::cell_terms(F, mean, x, y, false, t);
    for (int k = 0; k < 8; ++k) g[k] = t.g[k];
}

// The smallest x^T h x over many unit vectors (a cheap lower bound check).
static double smallest_form(const double h[8][8]) {
    double worst = 1e300;
    for (int s = 0; s < 4000; ++s) {
        double v[8], n = 0.0;
        for (int k = 0; k < 8; ++k) v[k] = std::sin(12.9898 * (s + 1) * (k + 1) + 78.233 * k), n += v[k] * v[k];
        double q = 0.0;
        for (int p = 0; p < 8; ++p)
            for (int r = 0; r < 8; ++r) q += v[p] * h[p][r] * v[r];
        worst = std::fmin(worst, q / n);
    }
    return worst;
}

// With the smoothness term's weight d, O as dot products or as squared cotangents.
static void test_cell(double d, bool cotangents) {
    std::printf("a = 10, b = 1, c = 5, d = %g, O as %s:\n", d, cotangents ? "cotangents" : "dot products");
    const eg2d::Functional F = eg2d::make_functional(10.0, 1.0, 5.0, d, cotangents, 0.02, 1);
    // A skewed, uneven cell, its area far from the mean 0.02.
    const double z0[8] = {0.0, 0.0, 0.31, 0.05, 0.42, 0.37, -0.08, 0.21};
    const double mean = 0.02, eps = 1e-6;
    double x[4], y[4];
    for (int m = 0; m < 4; ++m) x[m] = z0[2 * m], y[m] = z0[2 * m + 1];
    eg2d::CellTerms t;
    eg2d::cell_terms(F, mean, x, y, true, t);
    check(std::fabs(t.value - value_at(F, mean, z0)) <= 1e-14 * std::fabs(t.value), "value = cell_value",
          std::fabs(t.value - value_at(F, mean, z0)));
    double gerr = 0.0, herr = 0.0, scale = 0.0;
    for (int k = 0; k < 8; ++k) {
        double zp[8], zm[8], gp[8], gm[8];
        for (int q = 0; q < 8; ++q) zp[q] = zm[q] = z0[q];
        zp[k] += eps;
        zm[k] -= eps;
        gerr = std::fmax(gerr, std::fabs((value_at(F, mean, zp) - value_at(F, mean, zm)) / (2 * eps) - t.g[k]));
        gradient_at(F, mean, zp, gp);
        gradient_at(F, mean, zm, gm);
        for (int q = 0; q < 8; ++q) {
            herr = std::fmax(herr, std::fabs((gp[q] - gm[q]) / (2 * eps) - t.h[q][k]));
            scale = std::fmax(scale, std::fabs(t.h[q][k]));
        }
    }
    check(gerr < 1e-6, "gradient against central differences of V", gerr);
    check(herr < 1e-6 * scale, "exact Hessian against differences of the gradient", herr / scale);
    const double exact_min = smallest_form(t.h), convex_min = smallest_form(t.hc);
    check(exact_min < -1e-3 * scale, "exact Hessian indefinite on this cell (smallest form)", exact_min);
    check(convex_min > -1e-12 * scale, "convex Hessian positive semidefinite (smallest form)", convex_min);
    // At a right-angled square of the mean area every f is 0: both agree.
    const double side = std::sqrt(mean);
    const double xs[4] = {0.0, side, side, 0.0}, ys[4] = {0.0, 0.0, side, side};
    eg2d::cell_terms(F, mean, xs, ys, true, t);
    double diff = 0.0;
    for (int p = 0; p < 8; ++p)
        for (int q = 0; q < 8; ++q) diff = std::fmax(diff, std::fabs(t.h[p][q] - t.hc[p][q]));
    check(diff < 1e-12, "exact = convex Hessian where areas and angles are right", diff);
}

// The smoothness term alone, (|u|^2 + |v|^2)/(u x v) at each corner: its
// Hessian is indefinite on some unfolded cells, the convex one positive
// semidefinite on all (and equal to it on a square: test_cell); the value
// is infinite on a folded cell.
static void test_smoothness_convex() {
    eg2d::Functional F = eg2d::make_functional(0.0, 0.0, 0.0, 1.0, false, 0.02, 1);
    F.spacing = 0.0;
    double worst = 1e300, exact = 1e300;
    for (int s = 0; s < 200; ++s) {
        // Convex cells: corners on a circle at increasing angles, jittered radii.
        double x[4], y[4];
        for (int m = 0; m < 4; ++m) {
            const double t = 1.5707963 * m + 0.6 * std::sin(3.1 * s + m), r = 1.0 + 0.4 * std::cos(1.7 * s * m + 0.3);
            x[m] = r * std::cos(t), y[m] = r * std::sin(t);
        }
        eg2d::CellTerms t;
        eg2d::cell_terms(F, 0.0, x, y, true, t);
        if (!std::isfinite(t.value)) continue;  // a corner flat or reflex: not in the term's domain
        double scale = 0.0;
        for (int p = 0; p < 8; ++p) scale = std::fmax(scale, std::fabs(t.h[p][p]));
        exact = std::fmin(exact, smallest_form(t.h) / scale);
        worst = std::fmin(worst, smallest_form(t.hc) / scale);
    }
    check(exact < -1e-3, "smoothness term's exact Hessian indefinite somewhere (200 cells)", exact);
    check(worst > -1e-12, "smoothness term's convex Hessian positive semidefinite (200 cells)", worst);
    const double xf[4] = {0.0, 1.0, 0.2, 0.0}, yf[4] = {0.0, 0.0, -0.3, 1.0};  // corner 2 reflex
    eg2d::CellTerms t;
    eg2d::cell_terms(F, 0.0, xf, yf, false, t);
    check(std::isinf(t.value), "smoothness term infinite on a folded cell", t.value);
}

// S's Hessian (b = 1) on an n x n block plus an x-y coupling, as the
// minimiser assembles it; the V-cycle as a stationary iteration must
// reduce the error by a factor well below 1 per cycle.
static void test_multigrid() {
    const int n = 65;
    eg2d::BlockStencil A;
    A.resize(n, n, false);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t u = static_cast<std::size_t>(i) + static_cast<std::size_t>(n) * j;
            const bool inner = i > 0 && j > 0 && i < n - 1 && j < n - 1;
            A.unknown[u] = inner;
            if (!inner) {
                A.at(u, 0, 0) = eg2d::Mat2{1, 0, 0, 1};
                continue;
            }
            A.at(u, 0, 0) = eg2d::Mat2{9.5, 0.5, 0.5, 9.5};  // symmetric, diagonally dominant: SPD
            const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
            for (int k = 0; k < 4; ++k) {
                const int qi = i + di[k], qj = j + dj[k];
                if (qi > 0 && qj > 0 && qi < n - 1 && qj < n - 1) A.at(u, di[k], dj[k]) = eg2d::Mat2{-2, 0, 0, -2};
            }
            // A diagonal coupling, symmetric: (i, j) with (i+1, j+1) and back.
            if (i + 1 < n - 1 && j + 1 < n - 1) A.at(u, 1, 1) = eg2d::Mat2{-0.25, 0.1, 0.1, -0.25};
            if (i > 1 && j > 1) A.at(u, -1, -1) = eg2d::Mat2{-0.25, 0.1, 0.1, -0.25};
        }
    eg2d::BlockMultigrid mg;
    const bool factored = mg.setup(A);
    check(factored && mg.levels() == 4, "block multigrid: 4 levels (9^2 coarsest), factor positive definite", mg.levels());
    std::vector<eg2d::Vec2> x(A.nodes()), b(A.nodes()), r(A.nodes()), z(A.nodes()), ax(A.nodes());
    for (std::size_t u = 0; u < A.nodes(); ++u)
        if (A.unknown[u]) b[u] = eg2d::Vec2{std::sin(0.37 * u), std::cos(0.11 * u)};
    auto residual_norm = [&] {
        A.multiply(x.data(), ax.data());
        double s = 0.0;
        for (std::size_t u = 0; u < A.nodes(); ++u)
            if (A.unknown[u]) {
                r[u] = eg2d::Vec2{b[u].x - ax[u].x, b[u].y - ax[u].y};
                s += r[u].x * r[u].x + r[u].y * r[u].y;
            }
        return std::sqrt(s);
    };
    const double r0 = residual_norm();
    double rn = r0;
    for (int c = 0; c < 8; ++c) {
        mg.apply(r.data(), z.data());
        for (std::size_t u = 0; u < A.nodes(); ++u) x[u].x += z[u].x, x[u].y += z[u].y;
        rn = residual_norm();
    }
    const double factor = std::pow(rn / r0, 1.0 / 8.0);
    check(factor < 0.3, "block multigrid: mean residual factor per V-cycle (65^2)", factor);
}

// The corner terms' shortcuts (smoothness_cell.hpp) against the cell's
// full terms, on 200 cells (some folded) and both senses: corner_node_terms
// is the cell's corner-0 gradient and 2 x 2 blocks and corner_terms_value
// its value, to the last bit (the residual and the line search read them,
// and a run must take the same steps as with the full terms).
static void test_corner_shortcuts() {
    double worst = 0.0;
    int cells = 0, folded = 0;
    for (int sense : {1, -1})
        for (int s = 0; s < 200; ++s) {
            eg2d::Functional F = eg2d::make_functional(0.0, 1.0, 2.0, 1.0, true, 0.02, sense);
            F.sense = sense;
            double x[4], y[4];
            for (int m = 0; m < 4; ++m) {
                const double t = sense * (1.5707963 * m + 0.9 * std::sin(3.1 * s + m)),
                             r = 1.0 + 0.4 * std::cos(1.7 * s * m + 0.3);
                x[m] = r * std::cos(t) - 0.3, y[m] = r * std::sin(t) + 0.1;
            }
            eg2d::CellTerms full;
            eg2d::add_corner_terms(F, x, y, true, full);
            const double value = eg2d::corner_terms_value(F, x, y);
            const eg2d::NodeTerms with = eg2d::corner_node_terms(F, x, y, true);
            const eg2d::NodeTerms without = eg2d::corner_node_terms(F, x, y, false);
            ++cells;
            if (std::isinf(full.value)) ++folded;
            // Equal or both infinite (the same bits either way).
            if (!(value == full.value)) worst = std::fmax(worst, 1.0);
            for (int p = 0; p < 2; ++p) {
                worst = std::fmax(worst, std::fabs(with.g[p] - full.g[p]));
                worst = std::fmax(worst, std::fabs(without.g[p] - full.g[p]));
                for (int q = 0; q < 2; ++q) {
                    worst = std::fmax(worst, std::fabs(with.h[p][q] - full.h[p][q]));
                    worst = std::fmax(worst, std::fabs(with.hc[p][q] - full.hc[p][q]));
                    worst = std::fmax(worst, std::fabs(without.hc[p][q] - full.hc[p][q]));
                    worst = std::fmax(worst, std::fabs(without.h[p][q]));
                }
            }
        }
    check(worst == 0.0, "corner shortcuts = the cell's terms, bit for bit (400 cells)", worst);
    check(folded > 0 && folded < cells, "  of which some but not all with a flat or folded corner", folded);
}

int main() {
    test_cell(0.0, false);
    test_cell(1.0, false);
    test_cell(1.0, true);
    test_smoothness_convex();
    test_corner_shortcuts();
    test_multigrid();
    return failures == 0 ? 0 : 1;
}
