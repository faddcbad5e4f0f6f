// Hermite TFI at chosen sides, in both directions: the Boolean sum
// P_xi + P_eta - P_xi P_eta (the grid-generation lecture notes eq 2.3) of Hermite projectors (eq 2.4)
// whose derivatives at the chosen sides are solved from the discrete form of
// the orthogonality and spacing conditions (eqs 2.5-2.6): the first interior
// node of each grid line leaving a chosen side lies on the side's normal at
// the height h. Eq 2.6's d/Delta ~ r_s holds only to first order (the phi
// terms move the node by O(Delta^2) along the side, degrees on coarse
// grids); the first node is affine in its own derivative, so solving for it
// makes the angle and the height exact. Fold guard: the derivative's reach.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "base/error.hpp"
#include "base/folds.hpp"
#include "grid/initializers.hpp"

namespace eg2d {

namespace {

struct Vec {
    double x = 0.0, y = 0.0;
};

// The blending functions of one direction for parameter t in [0, 1]: values
// at both ends; derivatives at the chosen ends only (cubic with both,
// quadratic with one, linear with none). psi0 reaches only to t = sigma:
// psi0 = t (1 - t/sigma)^2 for t < sigma (sigma = 1: eq 2.4's (1-t)^2 t), so
// a shorter reach keeps the normal push near the side where normals from
// curved sides would otherwise cross.
struct Blend {
    double phi0, phi1, psi0, psi1;
};
double reach(double t, double sigma) { return t < sigma ? t * (1 - t / sigma) * (1 - t / sigma) : 0.0; }
Blend blend(double t, bool at0, bool at1, double sigma) {
    if (at0 && at1) return {(2 * t + 1) * (1 - t) * (1 - t), (3 - 2 * t) * t * t, reach(t, sigma), -reach(1 - t, sigma)};
    if (at0) return {1 - t * t, t * t, reach(t, sigma), 0.0};
    if (at1) return {(1 - t) * (1 - t), 1 - (1 - t) * (1 - t), 0.0, -reach(1 - t, sigma)};
    return {1 - t, t, 0.0, 0.0};
}

// The derivative data of the four sides: d r/d eta at JMIN/JMAX per column
// (dj[0], dj[1]), d r/d xi at IMIN/IMAX per row (di[0], di[1]), parameters
// r = i/(ni-1), s = j/(nj-1).
struct Derivatives {
    std::array<std::vector<Vec>, 2> dj, di;
};

class HermiteSides {
public:
    HermiteSides(Grid &g, const Settings &settings)
        : g_(g), ni_(g.ni()), nj_(g.nj()), periodic_(g.connectivity().periodic_i()),
          mask_(static_cast<unsigned>(settings.hermite_sides)) {
        const double heights[4] = {settings.hermite_height_jmin, settings.hermite_height_imax,
                                   settings.hermite_height_jmax, settings.hermite_height_imin};
        for (int s = 0; s < 4; ++s) {
            if (!chosen(Side(s))) continue;
            if (!g.has_side(Side(s)))
                fail(Failure::Argument, format("hermite_sides: side %s is chosen, but a %s grid has no such side",
                                               side_name(Side(s)), topology_name(g.topology())));
            height_[s] = heights[s];
        }
        alpha_ = settings.hermite_spacing;
        eta_ = chosen(Side::JMin) || chosen(Side::JMax);
        xi_ = !periodic_ && (chosen(Side::IMin) || chosen(Side::IMax));
        d_.dj[0].assign(static_cast<std::size_t>(ni_), Vec{});
        d_.dj[1] = d_.dj[0];
        d_.di[0].assign(static_cast<std::size_t>(nj_), Vec{});
        d_.di[1] = d_.di[0];
        corner_slopes();
        make_targets();
    }

    // Solves the derivatives for the targets at the longest reach that does
    // not fold; throws Folded when even the shortest folds.
    void run() {
        const double shortest = 3.0 / (std::min(xi_ ? ni_ : nj_, eta_ ? nj_ : ni_) - 1);
        long folded = 0;
        for (double sigma = 1.0;; sigma *= 0.5) {
            sigma = std::max(sigma, shortest);
            solve(sigma);
            folded = fold_summary(g_).folded;
            if (folded == 0 || sigma <= shortest) break;
        }
        if (folded > 0)
            fail(Failure::Folded, format("Hermite TFI at the chosen sides folds %ld cells even with the derivatives' "
                                         "reach cut to 3 cells: the first-cell heights are too large for the "
                                         "sides' curvature",
                                         folded));
    }

private:
    bool chosen(Side s) const { return (mask_ >> static_cast<int>(s)) & 1u; }
    std::size_t at(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni_) * j; }
    Vec node(int i, int j) const { return Vec{g_.x[at(i, j)], g_.y[at(i, j)]}; }

    // At a corner the other family's side gives the derivative (its own
    // one-sided slope), so P_xi P_eta reproduces the sides there; the twist
    // r_xi_eta is taken as 0.
    void corner_slopes() {
        for (int e = 0; e < 2; ++e) {
            const int j = e == 0 ? 0 : nj_ - 1, jn = e == 0 ? 1 : nj_ - 2;
            const int i = e == 0 ? 0 : ni_ - 1, in = e == 0 ? 1 : ni_ - 2;
            const double sj = e == 0 ? (nj_ - 1) : -(nj_ - 1), si = e == 0 ? (ni_ - 1) : -(ni_ - 1);
            if (!periodic_)
                for (int c : {0, ni_ - 1}) {
                    const Vec a = node(c, j), b = node(c, jn);
                    d_.dj[e][static_cast<std::size_t>(c)] = Vec{(b.x - a.x) * sj, (b.y - a.y) * sj};
                }
            for (int r : {0, nj_ - 1}) {
                const Vec a = node(i, r), b = node(in, r);
                d_.di[e][static_cast<std::size_t>(r)] = Vec{(b.x - a.x) * si, (b.y - a.y) * si};
            }
        }
    }

    // One unknown derivative: which array, which entry, and its coefficient
    // in the first interior node (psi at the first node's parameter).
    struct Unknown {
        std::vector<Vec> *d;
        std::size_t k;
        bool eta;     // an eta-derivative (JMIN/JMAX) or a xi one
        bool at_one;  // at the side t = 1 (psi1, negative)
    };
    struct Target {
        int i, j;
        Vec where;
        std::vector<Unknown> by;
    };

    // The wanted first interior nodes: r(p) + h n at every node of a chosen
    // side (corners excluded; a closed side's every node once).
    void make_targets() {
        const int orientation = boundary_orientation(g_);
        std::vector<int> slot(g_.size(), -1);
        for (int s = 0; s < 4; ++s) {
            const Side side = Side(s);
            if (!chosen(side)) continue;
            const bool eta = side == Side::JMin || side == Side::JMax;
            const int n = g_.side_length(side);
            // Interior to the left of the side's direction for JMIN and IMAX
            // on a right-handed grid (eta to the left of xi).
            const double turn = (side == Side::JMin || side == Side::IMax ? 1.0 : -1.0) * orientation;
            for (int p = periodic_ ? 0 : 1; p < n - 1; ++p) {
                int pw = p - 1, pe = p + 1;
                if (pw < 0) pw = n - 2;  // a closed side: node n-1 is node 0
                const NodeIJ a = side_ij(ni_, nj_, side, pw), b = side_ij(ni_, nj_, side, pe);
                const NodeIJ c = side_ij(ni_, nj_, side, p), q = side_ij(ni_, nj_, side, p, 1);
                const Vec ra = node(a.i, a.j), rb = node(b.i, b.j), rc = node(c.i, c.j);
                const double tx = rb.x - ra.x, ty = rb.y - ra.y, t = std::hypot(tx, ty);
                if (!(t > 0))
                    fail(Failure::Boundary, format("Hermite TFI: side %s has repeated points round its node %d",
                                                   side_name(side), p));
                const Vec nrm{-turn * ty / t, turn * tx / t};
                double h = height_[s];
                if (h == 0.0) {  // alpha times the grid line's straight length over its cells
                    const NodeIJ o = side_ij(ni_, nj_, side, p, (eta ? nj_ : ni_) - 1);
                    const Vec ro = node(o.i, o.j);
                    h = alpha_ * std::hypot(ro.x - rc.x, ro.y - rc.y) / ((eta ? nj_ : ni_) - 1);
                }
                const Vec want{rc.x + h * nrm.x, rc.y + h * nrm.y};
                const bool one = side == Side::JMax || side == Side::IMax;
                Unknown u{eta ? &d_.dj[one] : &d_.di[one], static_cast<std::size_t>(p), eta, one};
                const std::size_t k = at(q.i, q.j);
                if (slot[k] < 0) {
                    slot[k] = static_cast<int>(targets_.size());
                    targets_.push_back(Target{q.i, q.j, want, {u}});
                    normals_.push_back({rc, nrm, h});
                    continue;
                }
                // A node next to a corner of two chosen sides: where both
                // normals cross if that is near both heights, else halfway.
                Target &tg = targets_[static_cast<std::size_t>(slot[k])];
                const Normal &o = normals_[static_cast<std::size_t>(slot[k])];
                const double det = nrm.x * (-o.n.y) - nrm.y * (-o.n.x);
                const double bx = o.r.x - rc.x, by = o.r.y - rc.y;
                const double la = det != 0.0 ? (bx * (-o.n.y) - by * (-o.n.x)) / det : -1.0;
                const double lb = det != 0.0 ? (nrm.x * by - nrm.y * bx) / det : -1.0;
                if (la >= 0.5 * h && la <= 2 * h && lb >= 0.5 * o.h && lb <= 2 * o.h)
                    tg.where = Vec{rc.x + la * nrm.x, rc.y + la * nrm.y};
                else
                    tg.where = Vec{0.5 * (tg.where.x + want.x), 0.5 * (tg.where.y + want.y)};
                tg.by.push_back(u);
            }
        }
    }

    // The Boolean sum with the current derivatives, into the interior.
    void evaluate(double sigma) {
        const double hx = 1.0 / (ni_ - 1), hy = 1.0 / (nj_ - 1);
        const bool j0 = chosen(Side::JMin), j1 = chosen(Side::JMax);
        const bool i0 = xi_ && chosen(Side::IMin), i1 = xi_ && chosen(Side::IMax);
        for (int pass = 0; pass < 2; ++pass) {
            double *f = pass == 0 ? g_.x.data() : g_.y.data();
            auto c = [pass](const Vec &v) { return pass == 0 ? v.x : v.y; };
            auto dj = [&](int e, int i) { return c(d_.dj[e][static_cast<std::size_t>(i)]); };
            auto di = [&](int e, int j) { return c(d_.di[e][static_cast<std::size_t>(j)]); };
            for (int j = 1; j < nj_ - 1; ++j) {
                const Blend be = blend(j * hy, j0 && eta_, j1 && eta_, sigma);
                auto p_eta = [&](int i) {
                    return be.phi0 * f[at(i, 0)] + be.phi1 * f[at(i, nj_ - 1)] + be.psi0 * dj(0, i) +
                           be.psi1 * dj(1, i);
                };
                if (periodic_) {
                    for (int i = 0; i < ni_; ++i) out_[at(i, j)] = p_eta(i);
                    continue;
                }
                // P_xi P_eta: P_xi of P_eta's values and xi-derivatives at
                // the columns 0 and ni-1 (the latter from the corners' d r/d xi).
                const double left = p_eta(0), right = p_eta(ni_ - 1);
                const double dleft = be.phi0 * di(0, 0) + be.phi1 * di(0, nj_ - 1);
                const double dright = be.phi0 * di(1, 0) + be.phi1 * di(1, nj_ - 1);
                for (int i = 1; i < ni_ - 1; ++i) {
                    const Blend bx = blend(i * hx, i0, i1, sigma);
                    const double p_xi = bx.phi0 * f[at(0, j)] + bx.phi1 * f[at(ni_ - 1, j)] + bx.psi0 * di(0, j) +
                                        bx.psi1 * di(1, j);
                    const double both = bx.phi0 * left + bx.phi1 * right + bx.psi0 * dleft + bx.psi1 * dright;
                    out_[at(i, j)] = p_xi + p_eta(i) - both;
                }
            }
            for (int j = 1; j < nj_ - 1; ++j)
                for (int i = periodic_ ? 0 : 1; i < (periodic_ ? ni_ : ni_ - 1); ++i) f[at(i, j)] = out_[at(i, j)];
            g_.connectivity().sync(f);
        }
    }

    // The derivatives that put the first nodes on their targets: each node
    // is affine in its own unknowns with coefficient psi at the first node;
    // the nodes next to corners couple weakly (psi1 at the first node is
    // O(Delta^2)), so a few corrections reach round-off.
    void solve(double sigma) {
        out_.assign(g_.size(), 0.0);
        const double coef_eta = reach(1.0 / (nj_ - 1), sigma), coef_xi = reach(1.0 / (ni_ - 1), sigma);
        for (const Target &t : targets_)
            for (const Unknown &u : t.by) (*u.d)[u.k] = Vec{};
        const double tiny = 1e-15 * g_.extent();
        for (int sweep = 0; sweep < 50; ++sweep) {
            evaluate(sigma);
            double worst = 0.0;
            for (const Target &t : targets_) {
                const Vec r = node(t.i, t.j);
                const double mx = t.where.x - r.x, my = t.where.y - r.y;
                worst = std::max(worst, std::max(std::fabs(mx), std::fabs(my)));
                const double share = 1.0 / static_cast<double>(t.by.size());
                for (const Unknown &u : t.by) {
                    const double c = (u.eta ? coef_eta : coef_xi) * (u.at_one ? -1.0 : 1.0);
                    Vec &d = (*u.d)[u.k];
                    d.x += share * mx / c;
                    d.y += share * my / c;
                }
            }
            if (worst <= tiny) break;
        }
        evaluate(sigma);
    }

    struct Normal {
        Vec r, n;
        double h;
    };

    Grid &g_;
    const int ni_, nj_;
    const bool periodic_;
    const unsigned mask_;
    bool eta_ = false, xi_ = false;
    double alpha_ = 1.0;
    double height_[4] = {0, 0, 0, 0};
    Derivatives d_;
    std::vector<Target> targets_;
    std::vector<Normal> normals_;
    std::vector<double> out_;
};

}  // namespace

void tfi_hermite_sides(Grid &g, const Settings &settings) {
    HermiteSides h(g, settings);
    h.run();
}

}  // namespace eg2d
