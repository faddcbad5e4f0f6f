// Coarse-to-fine ("nested") iteration, seed 000's main program with
// `interpol` and `nsub`: the equations are first converged on every s-th grid
// line (s = 2^k, the largest power of two that divides ni-1 and nj-1 and
// leaves at least one interior line), the result is interpolated linearly to
// every s/2-th line, converged again, and so on down to the full grid; then
// plain point SOR sweeps continue on the full grid.
//
// One iteration is one point SOR sweep of the full grid; the first iteration
// after a new start also does the whole coarse-to-fine phase. Each coarse
// level is a grid of its own (the fine nodes at stride s, the fine control
// fields sampled there and rescaled to its index units, control_fields.hpp)
// and is swept with the relaxation setting (automatic: the optimal SOR factor
// of its size) until its residual is
// below max(tolerance, kCoarseTolerance). Like seed 000, the start replaces
// the interior: of a warm start only the nodes of the coarsest level are used.
// (Right after interpolation the max-norm residual is larger than a smooth
// start's, from the kinks of linear interpolation, though the error is
// smaller; so the residual cannot judge which start is better.) A start
// with more folded cells than the grid had is dropped.
#include <algorithm>
#include <cmath>
#include <vector>

#include "base/folds.hpp"
#include "solvers/auto_relaxation.hpp"
#include "solvers/solver.hpp"

namespace eg2d {

namespace {
// A coarse level is converged to this residual at most: below it the
// interpolation error of the next level dominates anyway.
constexpr double kCoarseTolerance = 1e-7;

// The largest power-of-two stride with a coarse grid that still has an
// interior (and, periodic in i, at least three distinct columns).
int coarsest_stride(const Connectivity &c) {
    const int mi = c.ni() - 1, mj = c.nj() - 1, min_i = c.periodic_i() ? 3 : 2;
    int s = 1;
    while (mi % (2 * s) == 0 && mj % (2 * s) == 0 && mi / (2 * s) >= min_i && mj / (2 * s) >= 2) s *= 2;
    return s;
}

// Control fields at the nodes of stride s, in the coarse grid's index units:
// r_xi grows by s, so a, b, c terms scale by s and d terms by 1/s.
ControlFields coarse_controls(const ControlFields &fine, int ni, int s, int nci, int ncj) {
    ControlFields out;
    for (int t = 0; t < kTermCount; ++t) {
        const Term term = static_cast<Term>(t);
        const double *f = fine.data(term);
        if (!f) continue;
        const bool d_term = term == Term::DXi || term == Term::DEta;
        const double scale = d_term ? 1.0 / s : static_cast<double>(s);
        std::vector<double> &v = out.at(term, static_cast<std::size_t>(nci) * ncj);
        for (int j = 0; j < ncj; ++j)
            for (int i = 0; i < nci; ++i)
                v[i + static_cast<std::size_t>(nci) * j] = scale * f[i * s + static_cast<std::size_t>(ni) * j * s];
    }
    return out;
}

// Seed 000's `interpol(s)`: the nodes on every s/2-th line that are not on
// an s-th line get the mean of their two neighbours at distance s/2, first
// along eta (on the s-th columns), then along xi. Only unknown nodes change.
void interpolate(const Connectivity &c, double *f, int s) {
    const int ni = c.ni(), h = s / 2;
    auto at = [&](int i, int j) -> double & { return f[i + static_cast<std::size_t>(ni) * j]; };
    for (int i = c.i_begin(); i < c.i_end(); ++i) {
        if (i % s != 0) continue;
        for (int j = h; j < c.nj() - 1; j += s) at(i, j) = 0.5 * (at(i, j - h) + at(i, j + h));
    }
    c.sync(f);  // the cut column, read by the xi pass
    for (int j = h; j < c.nj() - 1; j += h)
        for (int i = h; i < c.i_end(); i += s) at(i, j) = 0.5 * (at(i - h, j) + at(i + h, j));
    c.sync(f);
}

class Nested final : public Solver {
public:
    void reset() override {
        started_ = false;
        relaxation_.reset();
    }

    void iterate(Problem &p) override {
        const Level L = p.level();
        if (!started_) {
            coarse_to_fine(p);
            started_ = true;
        }
        guarded_sweep(p.system, L, p.settings, relaxation_);
    }

private:
    void coarse_to_fine(Problem &p) {
        const Level fine = p.level();
        const Connectivity &conn = *fine.conn;
        const int top = coarsest_stride(conn);
        if (top == 1) return;
        const double extent = p.grid.extent();
        const std::vector<double> start_x = p.grid.x, start_y = p.grid.y;
        const long folded_before = fold_summary(p.grid).folded;
        const int ni = conn.ni();
        const double target = std::max(p.settings.tolerance, kCoarseTolerance);
        for (int s = top; s > 1; s /= 2) {
            const int nci = (ni - 1) / s + 1, ncj = (conn.nj() - 1) / s + 1;
            const Connectivity cc = conn.coarsened(s, s);
            std::vector<double> cx(static_cast<std::size_t>(nci) * ncj), cy(cx.size());
            auto fine_index = [&](int i, int j) { return i * s + static_cast<std::size_t>(ni) * j * s; };
            for (int j = 0; j < ncj; ++j)
                for (int i = 0; i < nci; ++i) {
                    cx[i + static_cast<std::size_t>(nci) * j] = p.grid.x[fine_index(i, j)];
                    cy[i + static_cast<std::size_t>(nci) * j] = p.grid.y[fine_index(i, j)];
                }
            const ControlFields cf = p.controls.empty() ? ControlFields{} : coarse_controls(p.controls, ni, s, nci, ncj);
            Level coarse;
            coarse.conn = &cc;
            coarse.x = cx.data();
            coarse.y = cy.data();
            coarse.controls = cf.empty() ? nullptr : &cf;
            converge(p.system, coarse, extent, target, p.settings);
            for (int j = 0; j < ncj; ++j)
                for (int i = 0; i < nci; ++i) {
                    p.grid.x[fine_index(i, j)] = cx[i + static_cast<std::size_t>(nci) * j];
                    p.grid.y[fine_index(i, j)] = cy[i + static_cast<std::size_t>(nci) * j];
                }
            interpolate(conn, fine.x, s);
            interpolate(conn, fine.y, s);
        }
        // A coarse grid can misrepresent strong control terms (an attraction
        // that decays within a few fine lines) and fold; such a start is
        // worse than none.
        if (fold_summary(p.grid).folded > folded_before) {
            p.grid.x = start_x;
            p.grid.y = start_y;
        }
    }

    // Point SOR sweeps on a coarse level until its residual is below target,
    // the sweeps stop helping, or a cap proportional to its size.
    static void converge(System system, const Level &L, double extent, double target, const Settings &settings) {
        const int cap = 50 * std::max(L.conn->ni(), L.conn->nj()) + 100;
        AutoRelaxation relaxation;
        double best = residual(system, L, extent).value;
        for (int k = 0; k < cap && best > target; ++k) {
            guarded_sweep(system, L, settings, relaxation);
            const double r = residual(system, L, extent).value;
            if (!std::isfinite(r) || r > 1e4 * best) return;  // the fine grid's run loop reports it
            best = std::min(best, r);
        }
    }

    // A point SOR sweep at the user's factor, or the automatic one with no
    // ramp: every level starts from the converged coarser one. Its target is
    // seed 003's optimum but at most kLimit: the error left by the coarser
    // level is not the model's slowest mode, and more over-relaxation only
    // slows it (bench, swan/valley: 402/518 sweeps at 257^2, 503/493 at
    // 513^2 with the limit; 774/732 and 1040+/1083+ (capped) at the
    // optimum; 424/585 and 775/816 at the optimum of a grid half as fine).
    static void guarded_sweep(System system, const Level &L, const Settings &settings, AutoRelaxation &relaxation) {
        constexpr double kLimit = 1.95;
        if (settings.relaxation > 0.0) return sor_sweep(system, L, settings.relaxation);
        const double target = std::min(kLimit, optimal_sor_omega(L.conn->ni(), L.conn->nj()));
        relaxation.sweep(L, 0, [&] { sor_sweep(system, L, relaxation.omega(target)); });
    }

    bool started_ = false;
    AutoRelaxation relaxation_;
};

}  // namespace

std::unique_ptr<Solver> make_nested() { return std::make_unique<Nested>(); }

}  // namespace eg2d
