#include "solvers/variational_newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "base/error.hpp"
#include "operator/operator.hpp"
#include "operator/smoothness_cell.hpp"
#include "operator/variational_cell.hpp"
#include "solvers/multigrid_variational.hpp"

namespace eg2d {

namespace {

// Eisenstat-Walker (1996) choice 2 for the CG tolerance ||H d + g|| <=
// forcing ||g||: gamma (||g_k||/||g_k-1||)^2, safeguarded, in [kForcingMin, kForcingMax].
constexpr double kForcingGamma = 0.9, kForcingMax = 0.1, kForcingMin = 1e-8;
constexpr int kMaxCg = 200;
// The Levenberg shift, relative to the Hessian's diagonal: first value,
// growth on a failure, decay after a full step; a shift below kShiftFloor is 0.
constexpr double kShiftFirst = 1e-3, kShiftGrowth = 10.0, kShiftDecay = 0.1, kShiftFloor = 1e-6;
constexpr int kHalvings = 30;
// The trust region (update_radius()): thresholds on the ratio of V's actual
// to predicted decrease, and the radius's shrink and growth factors.
constexpr double kRhoLow = 0.25, kRhoHigh = 0.75, kRadiusShrink = 0.25, kRadiusGrowth = 2.0;
// Nonlinear elimination (eliminate()): the fraction of the unknowns where the
// Newton direction is largest, the rings of neighbours added round them, and
// the Newton steps on that patch (variational_patch.hpp) at most, stopping
// once its gradient is down by kPatchReduction. Measured on the swan at 257^2
// (bench/RESULTS.md): 5% of the nodes and 2 rings left twice the global
// steps; 20% and 2 rings fewer global steps but more time on the patch.
constexpr double kEliminated = 0.1;
constexpr int kEliminationRings = 4, kPatchSteps = 8;
constexpr double kPatchReduction = 1e-2;
constexpr double kArmijo = 1e-4;
// Grid sequencing (sequence()): coarse levels down to kCoarsestNodes a side,
// each minimised to kCoarseTolerance in at most kCoarseSteps Newton steps.
constexpr int kCoarsestNodes = 17;
constexpr double kCoarseTolerance = 1e-6;
constexpr int kCoarseSteps = 60;

double dot(const std::vector<Vec2> &a, const std::vector<Vec2> &b) {
    double s = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) s += a[k].x * b[k].x + a[k].y * b[k].y;
    return s;
}

// The mean of the cells' signed areas (their sum is fixed by the boundary).
double mean_area(const Connectivity &conn, const double *x, const double *y) {
    const std::size_t ni = static_cast<std::size_t>(conn.ni()), nj = static_cast<std::size_t>(conn.nj());
    double sum = 0.0;
    for (std::size_t j = 0; j + 1 < nj; ++j)
        for (std::size_t i = 0; i + 1 < ni; ++i) {
            const std::size_t k = i + ni * j;
            sum += 0.5 * ((x[k + ni + 1] - x[k]) * (y[k + ni] - y[k + 1]) - (y[k + ni + 1] - y[k]) * (x[k + ni] - x[k + 1]));
        }
    return sum / (static_cast<double>(ni - 1) * static_cast<double>(nj - 1));
}

}  // namespace

void VariationalNewton::reset() {
    started_ = false;
    restart();
}

void VariationalNewton::restart() {
    noted_shift_ = false;
    shift_ = 0.0;
    last_gradient_ = -1.0;
    forcing_ = kForcingMax;
    last_limited_ = false;
    last_full_ = false;
    radius_ = std::numeric_limits<double>::infinity();
    boundary_ = false;
    progress_.restart();
}

void VariationalNewton::layout(const Connectivity &conn) {
    ni_ = conn.ni();
    periodic_ = conn.periodic_i();
    nc_ = periodic_ ? ni_ - 1 : ni_;
    nr_ = conn.nj();
    if (H_.nc != nc_ || H_.nr != nr_ || H_.periodic != periodic_) {
        H_.resize(nc_, nr_, periodic_);
        C_.resize(nc_, nr_, periodic_);
        const std::size_t n = H_.nodes();
        for (std::vector<Vec2> *v : {&g_, &d_, &r_, &z_, &p_, &q_}) v->assign(n, Vec2{});
        diag_.assign(n, 0.0);
    }
    std::fill(H_.unknown.begin(), H_.unknown.end(), 0);
    for (int j = conn.j_begin(); j < conn.j_end(); ++j)
        for (int i = conn.i_begin(); i < conn.i_end(); ++i)
            H_.unknown[static_cast<std::size_t>(i) + static_cast<std::size_t>(nc_) * j] = !conn.fixed(i, j);
    C_.unknown = H_.unknown;
}

double VariationalNewton::assemble(const double *gx, const double *gy, const Functional &F) {
    static const int lx[4] = {0, 1, 1, 0}, ly[4] = {0, 0, 1, 1};
    std::fill(g_.begin(), g_.end(), Vec2{});
    std::fill(H_.a.begin(), H_.a.end(), Mat2{});
    std::fill(C_.a.begin(), C_.a.end(), Mat2{});
    const int cells_i = periodic_ ? nc_ : nc_ - 1;
    double value = 0.0;
    CellTerms t;
    for (int j = 0; j + 1 < nr_; ++j)
        for (int i = 0; i < cells_i; ++i) {
            std::size_t u[4];
            double x[4], y[4];
            bool any = false;
            for (int m = 0; m < 4; ++m) {
                const int ci = periodic_ && i + lx[m] == nc_ ? 0 : i + lx[m], cj = j + ly[m];
                u[m] = static_cast<std::size_t>(ci) + static_cast<std::size_t>(nc_) * cj;
                const std::size_t k = static_cast<std::size_t>(ci) + static_cast<std::size_t>(ni_) * cj;
                x[m] = gx[k];
                y[m] = gy[k];
                any = any || H_.unknown[u[m]];
            }
            if (!any) continue;  // all four corners fixed: a constant
            cell_terms(F, mean_, x, y, true, t);
            value += t.value;
            for (int p = 0; p < 4; ++p) {
                if (!H_.unknown[u[p]]) continue;
                g_[u[p]].x += t.g[2 * p];
                g_[u[p]].y += t.g[2 * p + 1];
                for (int q = 0; q < 4; ++q) {
                    if (!H_.unknown[u[q]]) continue;
                    Mat2 &b = H_.at(u[p], lx[q] - lx[p], ly[q] - ly[p]);
                    b.a += t.h[2 * p][2 * q];
                    b.b += t.h[2 * p][2 * q + 1];
                    b.c += t.h[2 * p + 1][2 * q];
                    b.d += t.h[2 * p + 1][2 * q + 1];
                    Mat2 &c = C_.at(u[p], lx[q] - lx[p], ly[q] - ly[p]);
                    c.a += t.hc[2 * p][2 * q];
                    c.b += t.hc[2 * p][2 * q + 1];
                    c.c += t.hc[2 * p + 1][2 * q];
                    c.d += t.hc[2 * p + 1][2 * q + 1];
                }
            }
        }
    for (std::size_t u = 0; u < H_.nodes(); ++u) {
        if (!H_.unknown[u]) H_.at(u, 0, 0) = C_.at(u, 0, 0) = Mat2{1.0, 0.0, 0.0, 1.0};
        diag_[u] = std::max(C_.at(u, 0, 0).a, C_.at(u, 0, 0).d);
    }
    return value;
}

double VariationalNewton::energy(const double *gx, const double *gy, const Functional &F, double alpha) const {
    static const int lx[4] = {0, 1, 1, 0}, ly[4] = {0, 0, 1, 1};
    const int cells_i = periodic_ ? nc_ : nc_ - 1;
    double value = 0.0;
    for (int j = 0; j + 1 < nr_; ++j)
        for (int i = 0; i < cells_i; ++i) {
            double x[4], y[4];
            bool any = false;
            for (int m = 0; m < 4; ++m) {
                const int ci = periodic_ && i + lx[m] == nc_ ? 0 : i + lx[m], cj = j + ly[m];
                const std::size_t u = static_cast<std::size_t>(ci) + static_cast<std::size_t>(nc_) * cj;
                const std::size_t k = static_cast<std::size_t>(ci) + static_cast<std::size_t>(ni_) * cj;
                x[m] = gx[k] + alpha * d_[u].x;
                y[m] = gy[k] + alpha * d_[u].y;
                any = any || H_.unknown[u];
            }
            if (any) value += cell_value(F, mean_, x, y);
        }
    return value;
}

double VariationalNewton::fold_limit(const double *gx, const double *gy, int orientation) const {
    static const int lx[4] = {0, 1, 1, 0}, ly[4] = {0, 0, 1, 1};
    const int cells_i = periodic_ ? nc_ : nc_ - 1;
    double limit = std::numeric_limits<double>::infinity();
    for (int j = 0; j + 1 < nr_; ++j)
        for (int i = 0; i < cells_i; ++i) {
            double x[4], y[4], dx[4], dy[4];
            for (int m = 0; m < 4; ++m) {
                const int ci = periodic_ && i + lx[m] == nc_ ? 0 : i + lx[m], cj = j + ly[m];
                const std::size_t u = static_cast<std::size_t>(ci) + static_cast<std::size_t>(nc_) * cj;
                const std::size_t k = static_cast<std::size_t>(ci) + static_cast<std::size_t>(ni_) * cj;
                x[m] = gx[k];
                y[m] = gy[k];
                dx[m] = d_[u].x;
                dy[m] = d_[u].y;
            }
            limit = std::min(limit, cell_fold_limit(x, y, dx, dy, orientation));
        }
    return limit;
}

// CG on K d = -g, preconditioned by one V-cycle (mg_), inside the trust
// region ||d||_D <= radius_ (Steihaug 1983; Nocedal & Wright 2006, algorithm
// 7.2): `negative` on a direction of non-positive curvature of K, followed
// to the region's edge (with no region: the iterate so far, or the
// preconditioned gradient if that is still 0); `boundary_` when the iterate
// left the region and was cut back to its edge.
int VariationalNewton::solve(const BlockStencil &K, double forcing, bool &negative) {
    negative = false;
    boundary_ = false;
    const bool bounded = std::isfinite(radius_);
    const double r2 = radius_ * radius_;
    // ||d + tau p||_D = radius for tau >= 0 (dd <= r2).
    auto to_edge = [&](double dd, double dp, double pp) {
        const double disc = std::max(0.0, dp * dp + pp * (r2 - dd));
        return pp > 0.0 ? (std::sqrt(disc) - dp) / pp : 0.0;
    };
    auto along = [&](double tau) {
        for (std::size_t k = 0; k < d_.size(); ++k) {
            d_[k].x += tau * p_[k].x;
            d_[k].y += tau * p_[k].y;
        }
    };
    std::fill(d_.begin(), d_.end(), Vec2{});
    for (std::size_t k = 0; k < g_.size(); ++k) r_[k] = Vec2{-g_[k].x, -g_[k].y};
    const double target = forcing * std::sqrt(dot(r_, r_));
    mg_.apply(r_.data(), z_.data());
    p_ = z_;
    double rz = dot(r_, z_);
    double dd = 0.0;  // ||d||_D^2
    for (int it = 1; it <= kMaxCg; ++it) {
        K.multiply(p_.data(), q_.data());
        for (std::size_t k = 0; k < q_.size(); ++k)
            if (!K.unknown[k]) q_[k] = Vec2{};
        const double pq = dot(p_, q_);
        double dp = 0.0, pp = 0.0;
        if (bounded)
            for (std::size_t k = 0; k < d_.size(); ++k) {
                dp += diag_[k] * (d_[k].x * p_[k].x + d_[k].y * p_[k].y);
                pp += diag_[k] * (p_[k].x * p_[k].x + p_[k].y * p_[k].y);
            }
        if (!(pq > 0.0)) {
            negative = true;
            if (bounded) {
                along(to_edge(dd, dp, pp));
                boundary_ = true;
            } else if (it == 1) {
                d_ = z_;
            }
            return it;
        }
        const double a = rz / pq;
        if (bounded && dd + 2.0 * a * dp + a * a * pp >= r2) {
            along(to_edge(dd, dp, pp));
            boundary_ = true;
            return it;
        }
        dd += 2.0 * a * dp + a * a * pp;
        for (std::size_t k = 0; k < d_.size(); ++k) {
            d_[k].x += a * p_[k].x;
            d_[k].y += a * p_[k].y;
            r_[k].x -= a * q_[k].x;
            r_[k].y -= a * q_[k].y;
        }
        if (std::sqrt(dot(r_, r_)) <= target) return it;
        mg_.apply(r_.data(), z_.data());
        const double rz1 = dot(r_, z_);
        if (!(rz1 > 0.0)) return it;  // a preconditioner not positive definite here: the iterate so far
        const double b = rz1 / rz;
        rz = rz1;
        for (std::size_t k = 0; k < p_.size(); ++k) p_[k] = Vec2{z_[k].x + b * p_[k].x, z_[k].y + b * p_[k].y};
    }
    return kMaxCg;
}

namespace {

// Cells of (x, y) on conn's grid that fold against `orientation` (multigrid_variational.hpp).
long folds(const Connectivity &conn, double *x, double *y, int orientation) {
    Level L;
    L.conn = &conn;
    L.x = x;
    L.y = y;
    return folded_cells(L, orientation);
}

// fine += the bilinear interpolation of (coarse - base), coarse and base on
// the grid with every other node (the boundary's correction is 0).
void add_correction(const Connectivity &fine, double *f, const std::vector<double> &coarse,
                    const std::vector<double> &base) {
    const int ni = fine.ni(), nic = (ni - 1) / 2 + 1;
    auto c = [&](int I, int J) {
        const std::size_t k = static_cast<std::size_t>(I) + static_cast<std::size_t>(nic) * J;
        return coarse[k] - base[k];
    };
    for (int j = fine.j_begin(); j < fine.j_end(); ++j)
        for (int i = fine.i_begin(); i < fine.i_end(); ++i) {
            const int I0 = i / 2, J0 = j / 2, I1 = i % 2 ? I0 + 1 : I0, J1 = j % 2 ? J0 + 1 : J0;
            f[static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j] +=
                0.25 * (c(I0, J0) + c(I1, J0) + c(I0, J1) + c(I1, J1));
        }
    fine.sync(f);
}

}  // namespace

std::string VariationalNewton::solve_level(const Connectivity &conn, double *x, double *y, const Functional &F,
                                           double extent) {
    restart();
    Level L;
    L.conn = &conn;
    L.x = x;
    L.y = y;
    L.functional = &F;
    int limited = 0;
    for (int s = 0; s < kCoarseSteps; ++s) {
        if (residual(System::Variational, L, extent).value <= kCoarseTolerance) return {};
        step(conn, x, y, F, nullptr);
        // Here also with a barrier: a hard coarse level is given up cheaply (the fine grid keeps its start).
        limited = last_limited_ ? limited + 1 : 0;
        if (limited >= NewtonProgress::kStallSteps)
            return format("stalled at the fold guard (%d shortened Newton steps in a row)", limited);
    }
    if (residual(System::Variational, L, extent).value <= kCoarseTolerance) return {};
    return format("did not reach the residual %g in %d Newton steps", kCoarseTolerance, kCoarseSteps);
}

// Grid sequencing: V's minimum on grids with every 2nd, 4th, ... node first
// (each from the start grid sampled there plus the coarser minimum's change
// of it, interpolated), so the fine grid starts close to its own minimum.
// Only where the grid halves evenly in both directions and has no fixed
// lines or held rows; a coarse level that stalls or a start that folds
// ends it (noted), and the fine grid keeps the start it had.
void VariationalNewton::sequence(Problem &p) {
    const Connectivity &fine = p.grid.connectivity();
    if (fine.has_fixed() || fine.held_rows() > 0) return;
    std::vector<Connectivity> conns{fine};
    for (;;) {
        const Connectivity &c = conns.back();
        const int ni = c.ni(), nj = c.nj();
        if ((ni - 1) % 2 || (nj - 1) % 2 || (ni - 1) / 2 + 1 < kCoarsestNodes || (nj - 1) / 2 + 1 < kCoarsestNodes) break;
        if (c.periodic_i() && (ni - 1) / 2 < 8) break;
        conns.push_back(c.coarsened(2, 2));
    }
    if (conns.size() < 2) return;
    // The start grid on every level (level 0: the grid's own).
    const std::size_t n_levels = conns.size();
    std::vector<std::vector<double>> wx(n_levels), wy(n_levels), vx(n_levels), vy(n_levels);
    wx[0] = p.grid.x;
    wy[0] = p.grid.y;
    for (std::size_t l = 1; l < n_levels; ++l) {
        const int ni = conns[l].ni(), nj = conns[l].nj(), nif = conns[l - 1].ni();
        wx[l].resize(static_cast<std::size_t>(ni) * nj);
        wy[l].resize(wx[l].size());
        for (int j = 0; j < nj; ++j)
            for (int i = 0; i < ni; ++i) {
                const std::size_t k = static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j;
                const std::size_t kf = static_cast<std::size_t>(2 * i) + static_cast<std::size_t>(nif) * (2 * j);
                wx[l][k] = wx[l - 1][kf];
                wy[l][k] = wy[l - 1][kf];
            }
    }
    const double extent = p.grid.extent();
    const int orientation = p.functional.orientation;
    for (std::size_t l = n_levels; l-- > 1;) {
        vx[l] = wx[l];
        vy[l] = wy[l];
        if (l + 1 < n_levels) {
            add_correction(conns[l], vx[l].data(), vx[l + 1], wx[l + 1]);
            add_correction(conns[l], vy[l].data(), vy[l + 1], wy[l + 1]);
            if (orientation != 0 && folds(conns[l], vx[l].data(), vy[l].data(), orientation) >
                                        folds(conns[l], wx[l].data(), wy[l].data(), orientation)) {
                vx[l] = wx[l];
                vy[l] = wy[l];
            }
        }
        // The same weights over this level's mean cell area (variational.hpp).
        const double ratio = static_cast<double>(conns[l].ni() - 1) * (conns[l].nj() - 1) /
                             (static_cast<double>(fine.ni() - 1) * (fine.nj() - 1));
        Functional F = p.functional;
        scale_weights(F, ratio);
        const std::string why = solve_level(conns[l], vx[l].data(), vy[l].data(), F, extent);
        if (!why.empty()) {
            p.note(format("variational: the minimisation on the %dx%d grid (grid sequencing) %s; the %dx%d grid "
                          "starts from its initial grid instead",
                          conns[l].ni(), conns[l].nj(), why.c_str(), fine.ni(), fine.nj()));
            restart();
            return;
        }
    }
    std::vector<double> x = p.grid.x, y = p.grid.y;
    add_correction(fine, x.data(), vx[1], wx[1]);
    add_correction(fine, y.data(), vy[1], wy[1]);
    if (orientation != 0 && folds(fine, x.data(), y.data(), orientation) >
                                folds(fine, p.grid.x.data(), p.grid.y.data(), orientation)) {
        p.note("variational: the coarse grids' minimum interpolated folds cells of the fine grid; it starts from "
               "its initial grid instead");
    } else {
        p.grid.x = x;
        p.grid.y = y;
    }
    restart();
}

void VariationalNewton::iterate(Problem &p) {
    if (!started_ && p.fresh_start) sequence(p);
    // New weights start the iteration over, as a fresh run from this grid:
    // a re-solve kept the last run's trust region (4 of a restart's 11
    // Newton steps on the swan at 257^2 regrew its radius).
    const Functional &F = p.functional, &G = functional_;
    if (started_ && (F.area != G.area || F.spacing != G.spacing || F.orthogonality != G.orthogonality ||
                     F.smoothness != G.smoothness || F.cotangent != G.cotangent))
        restart();
    functional_ = F;
    started_ = true;
    step(p.grid.connectivity(), p.grid.x.data(), p.grid.y.data(), p.functional, &p);
}

void VariationalNewton::step(const Connectivity &conn, double *x, double *y, const Functional &F, Problem *p) {
    layout(conn);
    mean_ = mean_area(conn, x, y);
    const double v0 = assemble(x, y, F);
    const double gnorm = std::sqrt(dot(g_, g_));
    last_limited_ = false;
    v_last_ = v0;
    barrier_ = has_corner_terms(F);
    if (gnorm == 0.0) return;
    if (last_gradient_ > 0.0) {
        const double ratio = gnorm / last_gradient_;
        double eta = kForcingGamma * ratio * ratio;
        const double safe = kForcingGamma * forcing_ * forcing_;
        if (safe > 0.1) eta = std::max(eta, safe);
        forcing_ = std::clamp(eta, kForcingMin, kForcingMax);
    }
    last_gradient_ = gnorm;
    // The Newton direction: CG on the exact Hessian, preconditioned by a
    // V-cycle, inside the trust region (solve()). Measured on the swan, c
    // large, 257^2: the steps as many (147 against 146), 25% less CPU (30.8
    // against 40.9 s), as CG stops on the region's edge where unbounded it
    // ran on into directions the line search then cut back.
    // A Levenberg shift (shift_ times the diagonal) on both while a step
    // finds no descent.
    for (std::size_t u = 0; shift_ > 0.0 && u < H_.nodes(); ++u)
        if (H_.unknown[u]) {
            H_.at(u, 0, 0).a += shift_ * diag_[u];
            H_.at(u, 0, 0).d += shift_ * diag_[u];
            C_.at(u, 0, 0).a += shift_ * diag_[u];
            C_.at(u, 0, 0).d += shift_ * diag_[u];
        }
    bool negative = false;
    // The V-cycle is on the exact Hessian after a full step along a
    // direction of positive curvature (near the minimum) where its Galerkin
    // hierarchy has a positive definite coarsest matrix, else, or when the
    // direction it gives does not descend (the V-cycle of an indefinite
    // matrix need not be positive definite), on the convex one
    // (variational_cell.hpp; positive definite). The convex Hessian alone is
    // a preconditioner whose CG iterations per step double with each
    // doubling of the grid (swan, c large: 3.4, 7.4, 9.7, 18.9, 24.9 per
    // step from 17^2 to 257^2, where CG on the convex Hessian itself takes 2
    // per step at every size: the V-cycle is fine, the convex Hessian is far
    // from the exact one); on the exact one about half that. On the exact
    // one from the start, the steps far from the minimum were worse: the
    // antenna (c large, 129^2) took 55 Newton steps instead of 11, and with
    // a large it ended at another minimum (largest angle deviation 83.3
    // instead of 81.5 degrees; bench/RESULTS.md).
    bool on_exact = last_full_ && mg_.setup(H_);
    if (on_exact) {
        solve(H_, forcing_, negative);
        const double slope = dot(g_, d_);
        if (!(slope < 0.0)) on_exact = false;
    }
    if (!on_exact) {
        if (!mg_.setup(C_))
            fail(Failure::NotConverged, "variational: the convex Hessian's coarsest factor failed (a spacing weight of 0 "
                                        "on a grid where A and O alone leave a node free?)");
        solve(H_, forcing_, negative);
    }
    // The step: at most kToFold of the way to the first corner turning flat,
    // then halved until V falls enough (Armijo). A decrease below V's
    // round-off is taken as it is (near the minimum).
    const double slope = dot(g_, d_);
    double alpha = 1.0;
    if (F.orientation != 0) {
        const double limit = kToFold * fold_limit(x, y, F.orientation);
        if (limit < 1.0) {
            alpha = limit;
            last_limited_ = true;
        }
    }
    const bool limited_fold = last_limited_;
    // The model's curvature along d, for the trust region's ratio test.
    double curv = 0.0, dnorm = 0.0;
    H_.multiply(d_.data(), q_.data());
    for (std::size_t k = 0; k < q_.size(); ++k)
        if (H_.unknown[k]) {
            curv += d_[k].x * q_[k].x + d_[k].y * q_[k].y;
            dnorm += diag_[k] * (d_[k].x * d_[k].x + d_[k].y * d_[k].y);
        }
    dnorm = std::sqrt(dnorm);
    const bool noise = -slope <= 1e-13 * std::fabs(v0);
    int halvings = 0;
    double v1 = v0;  // V after the step
    while (!noise) {
        v1 = energy(x, y, F, alpha);
        if (v1 <= v0 + kArmijo * alpha * slope) break;
        if (++halvings > kHalvings) {
            alpha = 0.0;
            v1 = v0;
            break;
        }
        alpha *= 0.5;
    }
    if (alpha > 0.0) {
        for (int j = 0; j < nr_; ++j)
            for (int i = 0; i < nc_; ++i) {
                const std::size_t u = static_cast<std::size_t>(i) + static_cast<std::size_t>(nc_) * j;
                if (!H_.unknown[u]) continue;
                const std::size_t k = static_cast<std::size_t>(i) + static_cast<std::size_t>(ni_) * j;
                x[k] += alpha * d_[u].x;
                y[k] += alpha * d_[u].y;
            }
        conn.sync(x);
        conn.sync(y);
    }
    const double predicted = -(alpha * slope + 0.5 * alpha * alpha * curv);
    const double rho = noise ? 1.0 : predicted > 0.0 ? (v0 - v1) / predicted : 0.0;
    update_radius(alpha, halvings, limited_fold, rho, dnorm);
    if (!limited_fold) eliminate(conn, x, y, F);
    // A full step: the shift may shrink; no step: it must grow.
    last_full_ = alpha == 1.0 && !negative;
    if (alpha == 1.0) {
        shift_ = shift_ * kShiftDecay < kShiftFloor ? 0.0 : shift_ * kShiftDecay;
    } else if (alpha == 0.0) {
        shift_ = shift_ == 0.0 ? kShiftFirst : shift_ * kShiftGrowth;
        if (!noted_shift_ && p) {
            noted_shift_ = true;
            p->note(format("variational: a Newton step found no descent (residual %.3g); the steps add a Levenberg "
                          "shift (%.3g times the Hessian's diagonal, more if needed)", gnorm, shift_));
        }
    }
}

// Nonlinear elimination (Lanzkron, Rose & Wilkes 1996; Cai & Li 2011) after
// a step: the nodes where the step's direction was largest (|d|^2 D) and
// kEliminationRings rings of neighbours round them, minimised over with the
// rest of the grid held by Newton steps on that patch (variational_patch.hpp).
// Where the steps are long the barriers' strong nonlinearity sits in a
// strip of nodes that move together (swan, a large, 129^2: 1% of the nodes
// carry 40-60% of |d|_D^2, along the lower side), which limits the global
// quadratic model's reach; solved for there, the global Newton steps fall
// 4-6 fold (bench/RESULTS.md). Coupled Newton on the patch, not point sweeps
// (the earlier elimination: 4 symmetric sweeps over 1% of the nodes cut the
// steps by 10-25% only): the strip's nodes move together. Not after a step
// the fold limit shortened: on the antenna (a large) that changed the
// minimum the run ends at (65^2, with point sweeps: largest angle deviation
// 79.9 against 79.2 degrees, area ratio 41.0 against 40.1).
void VariationalNewton::eliminate(const Connectivity &conn, double *x, double *y, const Functional &F) {
    const std::size_t n = H_.nodes();
    std::vector<std::pair<double, std::size_t>> score;
    score.reserve(n);
    for (std::size_t u = 0; u < n; ++u)
        if (H_.unknown[u] && diag_[u] > 0.0)
            score.emplace_back(diag_[u] * (d_[u].x * d_[u].x + d_[u].y * d_[u].y), u);
    const std::size_t least = 4,
                      k = std::min(score.size(), std::max(least, static_cast<std::size_t>(
                                                                    kEliminated * static_cast<double>(score.size()))));
    if (k == 0) return;
    std::nth_element(score.begin(), score.begin() + (k - 1), score.end(), std::greater<>());
    std::vector<char> in(n, 0);
    for (std::size_t m = 0; m < k; ++m) in[score[m].second] = 1;
    for (int ring = 0; ring < kEliminationRings; ++ring) {
        std::vector<char> grown = in;
        for (int j = 0; j < nr_; ++j)
            for (int i = 0; i < nc_; ++i) {
                if (!in[static_cast<std::size_t>(i) + static_cast<std::size_t>(nc_) * j]) continue;
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di) {
                        int ii = i + di;
                        const int jj = j + dj;
                        if (periodic_) ii = (ii + nc_) % nc_;
                        if (ii < 0 || ii >= nc_ || jj < 0 || jj >= nr_) continue;
                        grown[static_cast<std::size_t>(ii) + static_cast<std::size_t>(nc_) * jj] = 1;
                    }
            }
        in.swap(grown);
    }
    std::vector<std::size_t> set;
    for (std::size_t u = 0; u < n; ++u)
        if (in[u] && H_.unknown[u]) set.push_back(u);
    patch_.solve(conn, H_, set, x, y, F, mean_, kPatchSteps, kPatchReduction);
}

// The trust region's radius after a step of alpha d (||d||_D = dnorm) that
// lowered V by rho times the model's decrease (Nocedal & Wright 2006,
// algorithm 4.1, with the step's length from the line search, as in Nocedal
// & Yuan 1998): there is none until the line search halves a step or the
// model is poor (rho < kRhoLow), so the steps near a benign minimum stay
// plain Newton steps; then it is the accepted step's length (a quarter of
// it where the model was poor) and doubles after full steps to its edge
// that the model predicted well. A step the fold limit alone shortened
// leaves it as it was: bounding the next direction there changed the
// minimum the antenna ends at ("a large", 129^2: largest angle deviation
// 82.4 against 81.5 degrees; bench/RESULTS.md).
void VariationalNewton::update_radius(double alpha, int halvings, bool limited, double rho, double dnorm) {
    const double length = alpha * dnorm;
    if (alpha == 0.0) {
        radius_ = kRadiusShrink * std::min(radius_, dnorm);
    } else if (halvings > 0 || rho < kRhoLow) {
        radius_ = (rho < kRhoLow ? kRadiusShrink : 1.0) * length;
    } else if (alpha == 1.0 && !limited && rho > kRhoHigh && boundary_) {
        radius_ *= kRadiusGrowth;
    }
}

void VariationalNewton::observe(double residual) {
    progress_.observe(residual, v_last_, last_limited_, barrier_, shift_);
}

}  // namespace eg2d
