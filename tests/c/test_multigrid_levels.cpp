// The multigrid hierarchy from the inside: which levels a size gets, that a
// coarse level's operator (with the rescaled control fields) is the fine one
// times operator_scale up to O(h^2) -- for every control term, for full and
// for semicoarsening -- and that multigrid with control terms converges in
// few cycles to the grid point SOR finds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "controls/control.hpp"
#include "generator/generator.hpp"
#include "eg2d.h"
#include "operator/operator.hpp"
#include "solvers/multigrid_hierarchy.hpp"

using namespace eg2d;

static int failures = 0, passes = 0;
static void check(bool ok, const std::string &what) {
    std::printf("%-72s %s\n", what.c_str(), ok ? "ok" : "FAILED");
    if (!ok) ++failures;
    else ++passes;
}

static std::string shape(const std::vector<MgLevel> &levels) {
    std::string s;
    for (const MgLevel &m : levels) s += std::to_string(m.conn.ni()) + "x" + std::to_string(m.conn.nj()) + " ";
    return s;
}

static void hierarchy_shapes() {
    struct Case {
        int ni, nj;
        Topology topo;
        System sys;
        const char *expect;
    } cases[] = {
        {1025, 1025, Topology::Single, System::Winslow, "1025x1025 513x513 257x257 129x129 65x65 33x33 17x17 9x9 5x5 "},
        // Any count coarsens: ceil((n-1)/2) cells; down to 5 nodes, then the
        // direction stays (semicoarsening for Winslow, the end for Laplace).
        {37, 23, Topology::Single, System::Winslow, "37x23 19x12 10x7 6x4 4x4 "},
        {37, 23, Topology::Single, System::Laplace, "37x23 19x12 10x7 6x4 "},
        {250, 100, Topology::Single, System::Winslow, "250x100 126x51 64x26 33x14 17x8 9x5 5x5 "},
        {65, 7, Topology::Single, System::Winslow, "65x7 33x4 17x4 9x4 5x4 "},
        {33, 17, Topology::O, System::Winslow, "33x17 17x9 9x5 "},
        // The periodic direction keeps at least 8 cells round the body.
        {30, 9, Topology::O, System::Winslow, "30x9 16x5 9x5 "},
        {4, 4, Topology::Single, System::Winslow, "4x4 "},
    };
    for (const Case &c : cases) {
        const std::string got = shape(build_hierarchy(Connectivity(c.ni, c.nj, c.topo), c.sys, 5));
        check(got == c.expect, std::string("levels of ") + std::to_string(c.ni) + "x" + std::to_string(c.nj) + " " +
                                   topology_name(c.topo) + " " + system_name(c.sys) + ": " + got);
    }
}

// A smooth, skewed map sampled at unit-spaced index points h apart.
static void smooth_map(int ni, int nj, double h, std::vector<double> &x, std::vector<double> &y) {
    x.resize(static_cast<std::size_t>(ni) * nj);
    y.resize(x.size());
    for (int j = 0; j < nj; ++j)
        for (int i = 0; i < ni; ++i) {
            const double s = i * h, t = j * h;
            x[i + ni * j] = s + 0.3 * t + 0.1 * t * t + 0.05 * std::sin(2.0 * s);
            y[i + ni * j] = t + 0.1 * s * t - 0.05 * s * s + 0.04 * std::sin(2.5 * t);
        }
}

// max over coarse unknowns |L_c - scale L_f| / max |scale L_f|, for control term
// `term` (-1: none) with a smooth field of size ~1 in fine index units.
static double coarse_consistency(int ni, int nj, int term) {
    const double h = 1.0 / (std::max(ni, nj) - 1);  // the long direction spans [0, 1]
    Connectivity fine(ni, nj, Topology::Single);
    std::vector<double> x, y;
    smooth_map(ni, nj, h, x, y);
    ControlFields fields;
    if (term >= 0) {
        std::vector<double> &f = fields.at(static_cast<Term>(term), x.size());
        for (int j = 0; j < nj; ++j)
            for (int i = 0; i < ni; ++i) f[i + ni * j] = 0.5 + 0.3 * std::cos(3.0 * i * h + 2.0 * j * h);
    }
    std::vector<MgLevel> levels = build_hierarchy(fine, System::Winslow, 3);
    MgLevel &c = levels[1];
    inject(fine, x.data(), c, c.x.data());
    inject(fine, y.data(), c, c.y.data());
    restrict_controls(term >= 0 ? &fields : nullptr, fine, c);
    Level lf;
    lf.conn = &fine;
    lf.x = x.data();
    lf.y = y.data();
    lf.controls = term >= 0 ? &fields : nullptr;
    Level lc = c.level;
    lc.fx = lc.fy = nullptr;
    double worst = 0.0, size = 0.0;
    for (int J = 1; J < c.conn.nj() - 1; ++J)
        for (int I = 1; I < c.conn.ni() - 1; ++I) {
            // Even counts of fine cells: the coarse nodes are fine nodes.
            const NodeEquation ef = node_equation(System::Winslow, lf,
                                                  fine.stencil(static_cast<int>(c.ai.pos[I]), static_cast<int>(c.aj.pos[J])));
            const double scale = operator_scale(System::Winslow, c, I, J);
            const NodeEquation ec = node_equation(System::Winslow, lc, c.conn.stencil(I, J));
            worst = std::fmax(worst, std::fmax(std::fabs(ec.rx - scale * ef.rx), std::fabs(ec.ry - scale * ef.ry)));
            size = std::fmax(size, std::fmax(std::fabs(scale * ef.rx), std::fabs(scale * ef.ry)));
        }
    return worst / size;
}

static void coarse_operator_consistency() {
    const char *names[] = {"none", "a_xi", "b_xi", "c_xi", "d_xi", "a_eta", "b_eta", "c_eta", "d_eta"};
    // (ni, nj) pairs: both directions coarsened, xi only (nj at the coarsest
    // count, 3), eta only.
    const int sizes[3][2][2] = {{{33, 33}, {65, 65}}, {{33, 3}, {65, 3}}, {{3, 33}, {3, 65}}};
    const char *kinds[3] = {"full", "xi only", "eta only"};
    for (int k = 0; k < 3; ++k)
        for (int t = -1; t < kTermCount; ++t) {
            const double e1 = coarse_consistency(sizes[k][0][0], sizes[k][0][1], t);
            const double e2 = coarse_consistency(sizes[k][1][0], sizes[k][1][1], t);
            char buf[160];
            std::snprintf(buf, sizeof buf, "coarse operator = scale * fine, %-8s term %-5s: %.2e -> %.2e (%.1fx)",
                          kinds[k], names[t + 1], e1, e2, e1 / e2);
            // Second order: the mismatch falls about 4x per halving of h.
            check(e1 < 0.05 && e1 / e2 > 3.0, buf);
        }
}

// A constant source in every control term: multigrid and point SOR agree.
class ConstantTerms final : public Control {
public:
    std::unique_ptr<Control> clone() const override { return std::make_unique<ConstantTerms>(*this); }
    void add_to(const Grid &grid, ControlFields &fields) const override {
        const double v[kTermCount] = {0.02, 0.01, -0.02, 0.3, -0.01, 0.02, 0.01, -0.2};
        for (int t = 0; t < kTermCount; ++t) {
            std::vector<double> &f = fields.at(static_cast<Term>(t), grid.size());
            for (double &e : f) e += v[t] * 32.0 / (grid.ni() - 1);  // the same continuous source at any size
        }
    }
};

static void controls_converge() {
    std::vector<double> xs[3], ys[3];
    int cycles = 0;
    for (int s = 0; s < 3; ++s) {  // point SOR, multigrid; multigrid without the terms
        Generator gen(33, 33);
        std::vector<double> x, y;
        smooth_map(33, 33, 1.0 / 32.0, x, y);
        gen.set_coordinates(x.data(), y.data());
        if (s < 2) gen.controls().add(std::make_unique<ConstantTerms>());
        gen.changed_controls();
        gen.set_solver(s == 0 ? EG2D_SOLVER_PSOR : EG2D_SOLVER_MULTIGRID);
        gen.settings.tolerance = 1e-13;
        gen.solve();
        xs[s] = gen.grid().x;
        ys[s] = gen.grid().y;
        if (s == 1) cycles = gen.iterations();
    }
    double d = 0.0, move = 0.0;
    for (std::size_t k = 0; k < xs[0].size(); ++k) {
        d = std::fmax(d, std::hypot(xs[0][k] - xs[1][k], ys[0][k] - ys[1][k]));
        move = std::fmax(move, std::hypot(xs[2][k] - xs[1][k], ys[2][k] - ys[1][k]));
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, "all eight control terms: multigrid %d cycles, grids differ by %.1e", cycles, d);
    check(d < 1e-10 && cycles <= 10, buf);
    std::snprintf(buf, sizeof buf, "the control terms move the grid by %.3f", move);
    check(move > 0.01, buf);
}

int main() {
    hierarchy_shapes();
    coarse_operator_consistency();
    controls_converge();
    std::printf("%d passed, %d failed\n", passes, failures);
    return failures == 0 ? 0 : 1;
}
