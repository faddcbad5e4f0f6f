// Wall orthogonality with a first-cell height: a Sorenson (GRAPE) /
// Steger-Sorenson-type control, updated during the iteration.
//
// For each wall side and each wall node w, the node c one cell inward should
// sit at T = r_w + h n (n the unit normal into the domain, perpendicular to
// the wall's central tangent; h the requested height, or for height 0 the
// current normal height, so only the angle is imposed). Before each
// iteration we ask which control coefficients (C_xi, C_eta) would make the
// discrete equation at c hold with c at T and its neighbours where they are:
//   [r_xi r_eta] (C_xi, C_eta)^T = -(alpha r_xixi - 2 beta r_xieta + gamma r_etaeta) - C_others,
// all evaluated on the 3x3 stencil with its centre at T. This is Sorenson's
// idea of solving the wall-limit equation for P, Q with r_eta prescribed,
// taken one cell in, where the discrete equation actually lives; at a fixed
// point of solver and control the node is exactly at T. The coefficients
// are scaled by the metric of the wall-normal direction (gamma for eta =
// const walls, alpha for xi = const walls), so the normal part is a psi
// (r_etaeta + psi r_eta: the spacing ratio of consecutive cells is
// (1 - psi/2) / (1 + psi/2)), independent of the domain's size.
//
// Robustness (as in GRAPE, Sorenson 1980, and Hilgenstock's 1988
// updates): the coefficients are under-relaxed
// (EG2D_PARAM_WALL_RELAXATION), the normal one is limited to
// |psi| <= 3 and the tangential one to |phi| <= 1, both relative to the
// wall-normal metric and widened up to 4x where the along-wall metric is
// the larger (kPsiLimit, kPhiLimit, kWidenLimit); the value found at the first
// interior row decays as exp(-a (m - 1)) at depth m (a = EG2D_PARAM_WALL_DECAY).
// Against a multigrid cycle, which converges the grid for each state, the
// updates are a fixed-point iteration of the control alone, whose factor is
// about 1 - relaxation (0.7 per cycle): past the start-up ramp they are
// Anderson-accelerated (anderson.hpp; NACA0012 r = 10 at 1e-5 chord: 29-35
// cycles instead of 43-48; 25-32 since psi has a gain of its own,
// damped_update).
// Nothing uses the wall's curvature, so straight walls with corners (the
// channels of Petrilli 1989, where Middlecoff-Thomas degenerates) are no special case.
#include <algorithm>
#include <cmath>
#include <string>

#include "base/folds.hpp"
#include "base/error.hpp"
#include "controls/anderson.hpp"
#include "controls/controls.hpp"
#include "grid/graded_layer.hpp"
#include "grid/hybrid_layer.hpp"
#include "operator/operator.hpp"

namespace eg2d {

namespace {
// Where these numbers come from. The limits on psi and phi and their
// widening came with the first wall control (823dc6d; limited, relaxed
// coefficients as in GRAPE and Hilgenstock's updates, above) and have not
// been measured one by one; what is measured of them is in bench/RESULTS.md
// ("The wall control in numbers" and its lab log): at the NACA0012
// trailing edge phi's target jumps between its limits +-1, and at
// 257x65, 1e-3 chord the limit binds (the first cell stops 20% short).
// |psi| <= 3 (823dc6d's text gave 1.5, where the spacing ratio
// (1 - psi/2)/(1 + psi/2) reaches 7; its code had 3, unchanged since).
constexpr double kPsiLimit = 3.0;
constexpr double kPhiLimit = 1.0;
// The widening by the along-wall metric (the rounded cap round a sharp
// trailing edge needs more) stops at 4x: a choice, not measured.
constexpr double kWidenLimit = 4.0;
// The smallest gain an oscillating node is damped to, and the halving on a
// turn / 10% recovery (damped_update): 3a10abd, which made multigrid
// converge on Petrilli's (1989) channel 1; the two-gain measurements are in
// bench/RESULTS.md, "Multigrid under the wall control (naca0012-wall)".
constexpr double kMinGain = 1e-3;
// Largest change of a coefficient per update: a ramp from the start grid.
// bench/RESULTS.md ("About 16 cycles are the ramp"): multigrid's pace is 5x
// this; 7x, 10x and 15x fold a cycle at the leading edge at some sizes.
constexpr double kStepLimit = 0.02;
// Depths where exp(-a (m-1)) is below this get nothing: a choice, not
// measured.
constexpr double kDecayCutoff = 1e-4;
// Damped updates before Anderson acceleration (advance): bench/RESULTS.md
// ("Past the start-up ramp (three damped updates ...)"): started from the
// first update the acceleration folded cells at 129x33.
constexpr int kCalmUpdates = 3;
// EG2D_PARAM_WALL_LAYER 3 (the default): the hybrid layer where its first
// cells meet the control's contract within these (the acceptance
// figures for wall-resolved O-grids), else the control. Measured: NACA 0012
// 250x100 at 1.04e-5 chord 0.1% and 0.03 degrees; 65x33 at 1e-3 off by up
// to 36% and 6 degrees (bench/RESULTS.md).
constexpr double kAutomaticLayer = 3.0;
constexpr double kAutoHeightError = 0.01;
constexpr double kAutoWallAngle = 0.5;
// and whose rows grow by at most this: the schedule's ratio is the one that
// reaches the far field in nj-1 rows, 2.5 on NACA 0012 65x17 at 1e-5 chord
// to 15 chords, where the solve above the layer folded every cell.
constexpr double kAutoGrowth = 1.25;
// A graded wall has settled when no node's gap exceeds this share of its
// first cell (0.1%: a height within 0.1%, a line within 0.06 degrees of the
// normal), whatever the tolerance asks of the domain as a whole.
constexpr double kGradedSettled = 1e-3;
constexpr double kNoGap = 1e300;       // the gap before any update (a sentinel, larger than any gap)

bool j_side(int side) { return side == 0 || side == 2; }  // JMIN, JMAX: eta = const walls

// Node (i, j) at along-wall index k and depth m from a side (base/grid.hpp).
NodeIJ place(const Grid &g, int side, int k, int m) { return side_ij(g.ni(), g.nj(), static_cast<Side>(side), k, m); }
int wall_length(const Grid &g, int side) { return j_side(side) ? g.ni() : g.nj(); }
int depth_count(const Grid &g, int side) { return j_side(side) ? g.nj() : g.ni(); }

class WallControl final : public Control {
public:
    explicit WallControl(const std::array<double, 4> &h) : height_(h) {}
    std::unique_ptr<Control> clone() const override { return std::make_unique<WallControl>(*this); }
    ControlKind kind() const override { return ControlKind::Orthogonality; }
    // With a marched layer (shape_start) the control is static.
    bool dynamic() const override { return layer_growth_ == 0.0; }

    void add_to(const Grid &g, ControlFields &fields) const override {
        if (!hybrid_.phi.empty()) {  // frozen: the march's own controls
            std::vector<double> &phi = fields.at(Term::AXi, g.size()), &psi = fields.at(Term::CEta, g.size());
            for (std::size_t k = 0; k < phi.size(); ++k) {
                phi[k] += hybrid_.phi[k];
                psi[k] += hybrid_.psi[k];
            }
            return;
        }
        if (layer_growth_ > 0.0) return add_wall_layer_fields(g, layer_growth_, fields);
        add_background(g, fields);
        for (int side = 0; side < 4; ++side) add_side(g, side, fields);
    }

    // An O- or C-grid whose only wall is JMIN, with a height: a marched
    // layer, held (grid/wall_layer.hpp). Anything else: the Sorenson-type
    // updates below.
    WallLayerShape shape_start(Grid &g, const Settings &settings, bool fill_above) override {
        hybrid_ = HybridLayer{};
        std::string note;
        const bool automatic = settings.wall_layer == kAutomaticLayer;
        // The marched and hybrid layers march one height.
        if (g.topology() != Topology::Single && jmin_only(g) && !g.wall_node_spacing[0].empty() &&
            (settings.wall_layer == 1.0 || settings.wall_layer == 2.0 || (automatic && !graded_applies(g))))
            note = "wall layer: the marched and hybrid layers take one first-cell height; JMIN's heights node by "
                   "node (eg2d_set_wall_spacing_nodes) are the wall control's updates' instead";
        if (hybrid_candidate(g, settings)) {
            try {
                Grid trial = g;
                HybridLayer hybrid = shape_hybrid_layer(trial, settings, height_[0], fill_above);
                if (automatic && (hybrid.height_error > kAutoHeightError || hybrid.wall_angle > kAutoWallAngle ||
                                  hybrid.shape.growth > kAutoGrowth)) {
                    note = format("wall layer (automatic): the hybrid layer would grow by %.3g per row with first "
                                  "cells off by %.3g%% and %.3g degrees (more than %g, %g%% or %g: too few rows for "
                                  "the far field, or too coarse a wall); the wall control's updates instead",
                                  hybrid.shape.growth, 100 * hybrid.height_error, hybrid.wall_angle, kAutoGrowth,
                                  100 * kAutoHeightError, kAutoWallAngle);
                } else {
                    g = std::move(trial);
                    hybrid_ = std::move(hybrid);
                    layer_growth_ = hybrid_.shape.growth;
                    return hybrid_.shape;
                }
            } catch (const Error &e) {  // the march cannot make this grid: the updates below instead
                if (e.failure() == Failure::Interrupted) throw;  // the monitor stopped it
                note = std::string("wall layer (hybrid) not made: ") + e.what() +
                       "; the wall control's updates instead";
            }
        }
        graded_ = GradedLayer{};
        if (automatic && note.empty() && graded_applies(g)) {
            Grid trial = g;
            graded_ = shape_graded_layer(trial, height_);
            g = std::move(trial);
            layer_growth_ = 0.0;
            if (g.held_rows() > 0) g.hold_rows(0);
            WallLayerShape shape = graded_.shape;
            shape.note = graded_note(g) + (shape.note.empty() ? "" : "; " + shape.note);
            return shape;
        }
        const bool layer = settings.wall_layer != 0.0 && !automatic &&
                           (g.topology() == Topology::C || (g.topology() == Topology::O && !wall_has_sharp_corner(g))) &&
                           jmin_only(g);
        if (!layer || !note.empty()) {
            layer_growth_ = 0.0;
            if (g.held_rows() > 0) g.hold_rows(0);
            WallLayerShape none;
            none.note = note;
            return none;
        }
        const WallLayerShape shape = shape_wall_layer(g, height_[0], settings.wall_growth, fill_above);
        layer_growth_ = shape.rows > 0 ? shape.growth : 0.0;
        return shape;
    }
    std::array<double, 4> wall_heights() const override { return height_; }
    bool shapes_after_cycle() const override { return !graded_.families.empty() && !graded_.frozen; }
    void shape_after_cycle(Grid &g) override {
        reshape_graded_layer(g, graded_);
        restart();  // the updates' state belongs to the lines before
    }
    bool grades(const Grid &g, const Settings &settings) const override {
        return settings.wall_layer == kAutomaticLayer && graded_applies(g) && !hybrid_candidate(g, settings);
    }
    double mismatch() const override { return mismatch_; }
    // A graded layer's first cells of 4e-6 in a domain 50 long (the TMR
    // bump) are within the mismatch test of tolerance 1e-8 (5e-7) with
    // their lines 5 degrees off the normal: each node's gap is measured
    // against its own height too.
    bool settled() const override { return graded_.families.empty() || (graded_.frozen && graded_rel_ <= kGradedSettled); }
    bool restart() override {
        const bool had = has_state();
        for (int side = 0; side < 4; ++side) clear_side(side);
        accel_.restart();
        calm_ = 0;
        last_gap_ = best_gap_ = kNoGap;
        mismatch_ = 0.0;
        return had;
    }

    bool advance(const Grid &g, const ControlFields &others, const Settings &settings,
                 const ControlPace &pace) override {
        bool moved = decay_ != settings.wall_decay && has_state();
        decay_ = settings.wall_decay;
        const double omega = std::min(1.0, pace.relaxation * settings.wall_relaxation);
        const double step = pace.step * kStepLimit;
        const double orient = boundary_orientation(g);  // J's sign, from the boundary alone (base/folds.hpp)
        for (int side = 0; side < 4; ++side) {
            if (!active(g, side)) {
                moved = moved || !phi_[side].empty();
                clear_side(side);
                continue;
            }
            const std::size_t n = static_cast<std::size_t>(wall_length(g, side));
            phi_[side].resize(n, 0.0);
            psi_[side].resize(n, 0.0);
            gain_phi_[side].resize(n, 1.0);
            gain_psi_[side].resize(n, 1.0);
            lastp_[side].resize(n, 0.0);
            lastq_[side].resize(n, 0.0);
        }
        std::vector<Node> nodes;
        // A frozen graded layer that meets its targets already (a start kept
        // and turned to the normals, graded_layer.hpp) is left as it is: the
        // fields, and so the run's residual, stand (on a straight channel
        // the update and the residual after it were a fifth of the run).
        if (!graded_.families.empty() && graded_.frozen) {
            for (int side = 0; side < 4; ++side) add_targets(g, others, orient, side, nodes);
            const double gap = mismatch(nodes), rel = relative_gap(nodes);
            if (rel <= kGradedSettled && gap <= settings.tolerance * g.extent()) {
                mismatch_ = gap;
                graded_rel_ = rel;
                return moved;
            }
            nodes.clear();
        }
        // Acceleration once the ramp is over (kCalmUpdates damped updates in
        // a row that no step limit cut and that shrank the gap), from every
        // node's target at the state as it is (a fixed point of all walls at
        // once); back to damped updates if the gap grows past twice its best
        // (an extrapolation that went wrong).
        if (pace.accelerate && calm_ >= kCalmUpdates) {
            for (int side = 0; side < 4; ++side) add_targets(g, others, orient, side, nodes);
            const double gap = mismatch(nodes);
            if (gap < 2.0 * best_gap_) {  // twice its best: bench/RESULTS.md, with kCalmUpdates
                accelerated_update(nodes, omega, step);
                last_gap_ = gap;
                best_gap_ = std::min(best_gap_, gap);
                mismatch_ = mismatch(nodes);
                graded_rel_ = relative_gap(nodes);
                return true;
            }
            nodes.clear();
        }
        double gap = 0.0;
        const bool clamped = damped_update(g, others, orient, omega, step, pace.one_gain, nodes, gap);
        accel_.restart();
        calm_ = (pace.accelerate && !clamped && gap < last_gap_) ? calm_ + 1 : 0;
        last_gap_ = best_gap_ = gap;
        mismatch_ = mismatch(nodes);
        graded_rel_ = relative_gap(nodes);
        return true;
    }

private:
    // A depth-1 node with its target coefficients.
    struct Node {
        int side, k;
        double phi, psi;
        double unit[4];
        double widen;  // the node's limits are kPhiLimit, kPsiLimit times this
    };

    // The change |dR|/diag of the node's equation that closing its gap
    // (target - state) would make: Control::mismatch() per node.
    double gap_of(const Node &nd) const {
        const double gp = nd.phi - phi_[nd.side][nd.k], gq = nd.psi - psi_[nd.side][nd.k];
        return std::max(std::fabs(gp * nd.unit[0] + gq * nd.unit[2]), std::fabs(gp * nd.unit[1] + gq * nd.unit[3]));
    }
    // The largest gap on a graded wall over its node's first-cell height.
    double relative_gap(const std::vector<Node> &nodes) const {
        double most = 0.0;
        for (const Node &nd : nodes) {
            const std::vector<double> &h = graded_.heights[static_cast<std::size_t>(nd.side)];
            if (!h.empty() && h[static_cast<std::size_t>(nd.k)] > 0.0)
                most = std::max(most, gap_of(nd) / h[static_cast<std::size_t>(nd.k)]);
        }
        return most;
    }

    double mismatch(const std::vector<Node> &nodes) const {
        double mm = 0.0;
        for (const Node &nd : nodes) mm = std::max(mm, gap_of(nd));
        return mm;
    }

    // Against sweeps, and during the ramp: under-relaxed, each node's gain
    // halved when its update turns (a solver that converges much per
    // iteration answers a change at once) and recovering slowly otherwise.
    // psi has a gain of its own, halved only by its own turns: it is the
    // coefficient that ramps for many updates, and where phi's target is
    // near zero (a symmetric trailing edge) phi turns on noise, which with
    // one gain per node held psi back. phi's gain still halves on either
    // turn: at the NACA0012 trailing edge phi's target jumps between its
    // limits for a small change of phi, and a lagging grid then drives a
    // slow oscillation (AF, 65x33 at 1e-3: not converged in 100000 steps
    // when phi had its own gain too). NACA0012 r = 10, multigrid,
    // iterations with one gain -> with two: 257x65 at 1e-4 chord 1264 ->
    // 29, 513x129 at 1e-4 4062 -> 41, 129x33 at 1e-3 617 -> 196
    // (bench/RESULTS.md). AF keeps one gain (ControlPace::one_gain): with
    // two, naca0012-wall 257x65 converged to a folded grid; PSOR, LSOR and
    // nested do as well or better with two.
    // True if a step limit cut any change; gap: the largest gap before it.
    bool damped_update(const Grid &g, const ControlFields &others, double orient, double omega, double step,
                       bool one_gain, std::vector<Node> &nodes, double &gap) {
        bool clamped = false;
        for (int side = 0; side < 4; ++side) {
            // Wall by wall: a wall's targets see the walls updated before it.
            const std::size_t first = nodes.size();
            add_targets(g, others, orient, side, nodes);
            for (std::size_t m = first; m < nodes.size(); ++m) {
                const Node &nd = nodes[m];
                gap = std::max(gap, gap_of(nd));
                double &p = phi_[nd.side][nd.k], &q = psi_[nd.side][nd.k];
                double &gp = gain_phi_[nd.side][nd.k], &gq = gain_psi_[nd.side][nd.k];
                const double dp = nd.phi - p, dq = nd.psi - q;
                double &lp = lastp_[nd.side][nd.k], &lq = lastq_[nd.side][nd.k];
                auto adapt = [](double gain, bool turned) {
                    return turned ? std::max(0.5 * gain, kMinGain) : std::min(1.1 * gain, 1.0);
                };
                const bool turned_psi = dq * lq < 0.0;
                gp = adapt(gp, dp * lp < 0.0 || turned_psi);
                gq = one_gain ? gp : adapt(gq, turned_psi);
                lp = dp;
                lq = dq;
                clamped = clamped || std::fabs(gp * omega * dp) > step || std::fabs(gq * omega * dq) > step;
                p += std::clamp(gp * omega * dp, -step, step);
                q += std::clamp(gq * omega * dq, -step, step);
            }
        }
        return clamped;
    }

    // The targets of one wall's nodes, from the state as it is (the other
    // walls' current contributions count as "others" too).
    void add_targets(const Grid &g, const ControlFields &others, double orient, int side, std::vector<Node> &nodes) const {
        if (!active(g, side)) return;
        // Summed into whole fields only where there is something to sum: with
        // no other term and no other wall's state the background is read at
        // each node (a field per wall and update was a tenth of a straight
        // channel's run).
        ControlFields rest;
        const bool summed = !others.empty() || other_state(side);
        if (summed) {
            rest = others;
            add_background(g, rest);
            for (int o = 0; o < 4; ++o)
                if (o != side) add_side(g, o, rest);
        }
        const double sign = (side == 0 || side == 1) ? orient : -orient;
        const int n = wall_length(g, side);
        for (int k = 0; k < n; ++k) {
            Node nd{side, k, 0.0, 0.0, {}, 1.0};
            if (target(g, side, k, sign, summed ? &rest : nullptr, nd.phi, nd.psi, nd.unit, nd.widen))
                nodes.push_back(nd);
        }
    }

    // Against cycles (the grid converged for the last state): Anderson
    // acceleration of the fixed point "state = target(grid(state))", with
    // the same ramp limit on each change.
    void accelerated_update(const std::vector<Node> &nodes, double omega, double step) {
        std::vector<double> x(2 * nodes.size()), f(2 * nodes.size());
        for (std::size_t n = 0; n < nodes.size(); ++n) {
            const Node &nd = nodes[n];
            x[2 * n] = phi_[nd.side][nd.k];
            x[2 * n + 1] = psi_[nd.side][nd.k];
            f[2 * n] = nd.phi - x[2 * n];
            f[2 * n + 1] = nd.psi - x[2 * n + 1];
        }
        const std::vector<double> next = accel_.next(x, f, omega);
        for (std::size_t n = 0; n < nodes.size(); ++n) {
            const Node &nd = nodes[n];
            // The ramp limit on the change, and the targets' limits on the
            // value (a combination of past states can leave them).
            const double lp = kPhiLimit * nd.widen, lq = kPsiLimit * nd.widen;
            phi_[nd.side][nd.k] = std::clamp(x[2 * n] + std::clamp(next[2 * n] - x[2 * n], -step, step), -lp, lp);
            psi_[nd.side][nd.k] = std::clamp(x[2 * n + 1] + std::clamp(next[2 * n + 1] - x[2 * n + 1], -step, step), -lq, lq);
            lastp_[nd.side][nd.k] = lastq_[nd.side][nd.k] = 0.0;
        }
    }

    // Whether any coefficient of the state is not zero (add_to adds it), of
    // any wall or of the walls other than `side`.
    bool has_state() const { return other_state(-1); }
    bool other_state(int side) const {
        for (int o = 0; o < 4; ++o)
            if (o != side)
                for (const auto *v : {&phi_, &psi_})
                    for (double c : (*v)[static_cast<std::size_t>(o)])
                        if (c != 0.0) return true;
        return false;
    }
    void clear_side(int side) {
        for (auto *v : {&phi_, &psi_, &gain_phi_, &gain_psi_, &lastp_, &lastq_}) (*v)[side].clear();
    }

    bool active(const Grid &g, int side) const {
        return height_[side] >= 0.0 && g.has_side(static_cast<Side>(side)) && depth_count(g, side) >= 3;
    }
    bool periodic(const Grid &g, int side) const { return j_side(side) && g.topology() == Topology::O; }
    // Along-wall indices whose depth-1 node is an unknown of this side: on a
    // single block not the end nodes, and not the ends' neighbours when the
    // side across that corner is a wall too (both would claim that node).
    int k_begin(const Grid &g, int side) const {
        if (periodic(g, side)) return 0;
        const int across = j_side(side) ? 3 : 0;  // the side at k = 0
        return active(g, across) ? 2 : 1;
    }
    int k_end(const Grid &g, int side) const {
        if (periodic(g, side)) return g.ni() - 1;
        const int across = j_side(side) ? 1 : 2;  // the side at k = n-1
        return wall_length(g, side) - (active(g, across) ? 2 : 1);
    }

    // The coefficients that put the depth-1 node at its target.
    // unit: the change of (R_x, R_y)/diag per unit of phi (unit[0..1]) and of
    // psi (unit[2..3]) at that node, for mismatch().
    // rest: the other terms summed (null: the background alone).
    bool target(const Grid &g, int side, int k, double sign, const ControlFields *rest, double &phi,
                double &psi, double unit[4], double &widen_out) const {
        if (k < k_begin(g, side) || k >= k_end(g, side)) return false;
        const Connectivity &conn = g.connectivity();
        const int n = wall_length(g, side);
        auto wrap = [&](int kk) {
            if (periodic(g, side)) return (kk + (n - 1)) % (n - 1);
            return kk;
        };
        const NodeIJ pw = place(g, side, k, 0), pm = place(g, side, wrap(k - 1), 0),
                    pp = place(g, side, wrap(k + 1), 0), pc = place(g, side, k, 1);
        const std::size_t ni = static_cast<std::size_t>(g.ni());
        const std::size_t kw = pw.i + ni * pw.j, km = pm.i + ni * pm.j, kp = pp.i + ni * pp.j;
        double tx = g.x[kp] - g.x[km], ty = g.y[kp] - g.y[km];
        const double tl = std::hypot(tx, ty);
        if (!(tl > 0.0)) return false;
        tx /= tl;
        ty /= tl;
        const double nx = -ty * sign, ny = tx * sign;
        const Stencil s = conn.stencil(pc.i, pc.j);
        // A graded wall's height is its layer's, each node's own (a patch's
        // blend included); until its controls are final (reshape_graded_layer)
        // the updates here would turn its first line to the normal only.
        const std::vector<double> &graded = graded_.heights[static_cast<std::size_t>(side)];
        const bool angle_only = height_[side] == 0.0 || (!graded.empty() && !graded_.frozen);
        double h = angle_only        ? 0.0
                   : !graded.empty() ? graded[static_cast<std::size_t>(k)]
                                     : g.wall_height_at(static_cast<Side>(side), k, height_[side]);
        if (h == 0.0) {  // orthogonality only: keep the current normal height
            h = (g.x[s.c] - g.x[kw]) * nx + (g.y[s.c] - g.y[kw]) * ny;
            if (!(h > 0.0)) h = std::hypot(g.x[s.c] - g.x[kw], g.y[s.c] - g.y[kw]);
            if (!(h > 0.0)) return false;
        }
        // The 3x3 stencil with its centre at the target.
        const std::ptrdiff_t idx[9] = {s.c, s.e, s.w, s.n, s.s, s.ne, s.nw, s.se, s.sw};
        double lx[9], ly[9];
        for (int q = 0; q < 9; ++q) {
            lx[q] = g.x[idx[q]];
            ly[q] = g.y[idx[q]];
        }
        lx[0] = g.x[kw] + h * nx;
        ly[0] = g.y[kw] + h * ny;
        Level L;
        L.x = lx;
        L.y = ly;
        const Stencil ls{0, 1, 2, 3, 4, 5, 6, 7, 8};
        const NodeEquation eq = node_equation(System::Winslow, L, ls);
        Metrics m = node_metrics(L, ls);
        const double xxi = 0.5 * (lx[1] - lx[2]), yxi = 0.5 * (ly[1] - ly[2]);
        const double xeta = 0.5 * (lx[3] - lx[4]), yeta = 0.5 * (ly[3] - ly[4]);
        // The other terms' C_xi, C_eta at this node, at the target (L has no
        // controls, so m.cxi = m.ceta = 0 before).
        if (rest) {
            add_control_terms(*rest, s.c, m);
        } else if (graded_.phi.size() == g.size()) {  // as add_control_terms would add it
            m.cxi += m.alpha * graded_.phi[static_cast<std::size_t>(s.c)];
            m.ceta += m.gamma * graded_.psi[static_cast<std::size_t>(s.c)];
        }
        const double oxi = m.cxi, oeta = m.ceta;
        const double rx = -eq.rx - oxi * xxi - oeta * xeta, ry = -eq.ry - oxi * yxi - oeta * yeta;
        const double det = xxi * yeta - xeta * yxi;
        const double scale = j_side(side) ? m.gamma : m.alpha;
        // A degenerate stencil (r_xi, r_eta parallel to round-off, relative to
        // the metric's size) has no target: a guard, not a tuned value.
        if (!(std::fabs(det) > 1e-12 * (m.alpha + m.gamma)) || !(scale > 0.0)) return false;
        const double cxi = (rx * yeta - xeta * ry) / det, ceta = (xxi * ry - yxi * rx) / det;
        // Along-wall (tangential) and wall-normal parts.
        phi = (j_side(side) ? cxi : ceta) / scale;
        psi = (j_side(side) ? ceta : cxi) / scale;
        // The limits apply to the coefficients relative to the diagonal
        // 2 (alpha + gamma): where the along-wall metric is the larger (the
        // rounded cap round a sharp trailing edge) the node needs more.
        const double widen = std::min((m.alpha + m.gamma) / scale, kWidenLimit);
        phi = std::clamp(phi, -kPhiLimit * widen, kPhiLimit * widen);
        psi = std::clamp(psi, -kPsiLimit * widen, kPsiLimit * widen);
        widen_out = widen;
        if (angle_only) psi = 0.0;  // the normal position is left to the equation
        if (!std::isfinite(phi) || !std::isfinite(psi)) return false;
        const double w = scale / (2.0 * (m.alpha + m.gamma));
        const double ax = j_side(side) ? xxi : xeta, ay = j_side(side) ? yxi : yeta;  // along the wall
        const double cx = j_side(side) ? xeta : xxi, cy = j_side(side) ? yeta : yxi;  // across it
        unit[0] = w * ax;
        unit[1] = w * ay;
        unit[2] = w * cx;
        unit[3] = w * cy;
        return true;
    }

    void add_side(const Grid &g, int side, ControlFields &fields) const {
        if (!active(g, side) || phi_[side].empty() || decay_ < 0.0) return;
        const std::size_t size = g.size();
        const Connectivity &conn = g.connectivity();
        // eta = const walls: tangential -> c_xi, normal -> c_eta; xi = const: a_eta, a_xi.
        std::vector<double> &T = fields.at(j_side(side) ? Term::CXi : Term::AEta, size);
        std::vector<double> &N = fields.at(j_side(side) ? Term::CEta : Term::AXi, size);
        const int depth = depth_count(g, side);
        for (int m = 1; m < depth - 1; ++m) {
            const double f = std::exp(-decay_ * (m - 1));
            if (f < kDecayCutoff) break;
            for (int k = k_begin(g, side); k < k_end(g, side); ++k) {
                const NodeIJ p = place(g, side, k, m);
                const std::size_t c = static_cast<std::size_t>(p.i) + static_cast<std::size_t>(g.ni()) * p.j;
                T[c] += f * phi_[side][k];
                N[c] += f * psi_[side][k];
                conn.sync_node(T.data(), p.i, p.j);
                conn.sync_node(N.data(), p.i, p.j);
            }
        }
    }

    // The graded layer's frozen background (grid/graded_layer.hpp), under the updates.
    void add_background(const Grid &g, ControlFields &fields) const {
        if (graded_.phi.size() != g.size()) return;
        std::vector<double> &phi = fields.at(Term::AXi, g.size()), &psi = fields.at(Term::CEta, g.size());
        for (std::size_t k = 0; k < phi.size(); ++k) {
            phi[k] += graded_.phi[k];
            psi[k] += graded_.psi[k];
        }
    }
    // Walls the hybrid layer does not take: a single block's, or an O-grid's
    // with JMAX a wall; a height on some wall; no interior lines (the lines
    // are re-spaced through them).
    // The hybrid layer's case: an O- or C-grid whose only wall is JMIN.
    // A wall at JMIN alone, with no interior lines (a marched layer
    // rewrites the rows it holds: not through interior lines).
    bool jmin_only(const Grid &g) const {
        return height_[0] > 0.0 && height_[1] < 0.0 && height_[2] < 0.0 && height_[3] < 0.0 &&
               g.interior_lines().empty();
    }
    bool hybrid_candidate(const Grid &g, const Settings &settings) const {
        return (settings.wall_layer == 2.0 || settings.wall_layer == kAutomaticLayer) &&
               g.topology() != Topology::Single && jmin_only(g) && g.wall_node_spacing[0].empty();
    }
    bool graded_applies(const Grid &g) const {
        if (g.topology() == Topology::C || !g.interior_lines().empty()) return false;
        for (int s = 0; s < 4; ++s)
            if (height_[static_cast<std::size_t>(s)] > 0.0 && g.has_side(static_cast<Side>(s))) return true;
        return false;
    }
    std::string graded_note(const Grid &g) const {
        std::string s = format("wall layer (graded): the lines leaving the walls re-spaced from their first cells, "
                               "largest growth %.4g within %d cells of a wall; the solve keeps their spacing%s",
                               graded_.shape.growth, kGradedRows,
                               graded_.kept ? " and their shape (controls inverted from them), turning them to the "
                                              "walls' normals" : "");
        if (graded_.shape.needed_nj > 0)
            s += format("; the growth exceeds %g: nj >= %d would meet it", kGradedGrowth, graded_.shape.needed_nj);
        if (graded_.shape.needed_ni > 0)
            s += format("; the growth exceeds %g: ni >= %d would meet it", kGradedGrowth, graded_.shape.needed_ni);
        (void)g;
        return s;
    }

    std::array<double, 4> height_;

    // A first cell below this share of the wall's coordinates is rounding:
    // its nodes cannot be told from the wall's (1e-20 chords made cells of
    // zero area that the fold count, a sign test, passed).
    static constexpr double kLeastHeight = 1e-13;

    void check(const Grid &g) const override {
        for (int side = 0; side < 4; ++side) {
            const Side s = static_cast<Side>(side);
            if (!(height_[side] > 0.0) || !g.has_side(s)) continue;
            double largest = 0.0;
            for (int p = 0; p < g.side_length(s); ++p) {
                const std::size_t k = side_node(g, s, p);
                largest = std::max({largest, std::fabs(g.x[k]), std::fabs(g.y[k])});
            }
            if (height_[side] < kLeastHeight * largest)
                fail(Failure::Argument,
                     format("the first cell at %s, %g, is below %g of the side's coordinates (up to %g): double "
                            "precision cannot tell its nodes from the wall's (eg2d_set_wall_spacing)",
                            side_name(s), height_[side], kLeastHeight, largest));
        }
    }
    GradedLayer graded_;
    double graded_rel_ = 0.0;  // the last update's relative_gap
    double layer_growth_ = 0.0;  // > 0: a marched layer is held, and this is its growth
    HybridLayer hybrid_;         // the hybrid layer's frozen controls, if it is one
    // The state: tangential (phi) and normal (psi) coefficients at depth 1,
    // per along-wall index, and the decay they were made with.
    std::array<std::vector<double>, 4> phi_, psi_;
    // Per node: the gains on the relaxation of phi and psi and the last
    // update's direction.
    std::array<std::vector<double>, 4> gain_phi_, gain_psi_, lastp_, lastq_;
    double decay_ = 0.0;
    double mismatch_ = 0.0;
    Anderson accel_;
    int calm_ = 0;
    double last_gap_ = kNoGap, best_gap_ = kNoGap;
};
}  // namespace

std::unique_ptr<Control> make_wall_control(const std::array<double, 4> &height) {
    return std::make_unique<WallControl>(height);
}

bool is_wall_control(const Control *c) { return dynamic_cast<const WallControl *>(c) != nullptr; }

}  // namespace eg2d
