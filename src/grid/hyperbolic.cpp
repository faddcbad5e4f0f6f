// The hyperbolic march, layer by layer (docs/hyperbolic.md has the
// equations and their sources). Per step from the layer r^l, with
// Dr = r^(l+1) - r^l:
//   [I + C delta_xi - eps_i Dxx] Dr = r_eta0 + eps_e Dxx r^l
// (Steger & Chaussee 1980 eqs 6-9 in delta form; Chan & Steger 1992 for the
// variable dissipation and the area smoothing), C = B0^-1 A0 from the
// linearised orthogonality and area equations: one 2x2 block-tridiagonal
// system per step, cyclic on O-grids.
#include "grid/hyperbolic.hpp"

#include "base/setup_progress.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/block_tridiagonal.hpp"
#include "base/cell.hpp"
#include "base/error.hpp"
#include "base/folds.hpp"
#include "grid/march_schedule.hpp"

namespace eg2d {

namespace {

// sin^2(5 degrees): the concave-corner factor's floor (alpha >= 10 degrees).
const double kMinSin2 = std::pow(std::sin(3.14159265358979323846 / 36), 2);
// Sub-steps (as pyHyp's cMax): the linearisation about the old layer holds
// while a step is at most about the node spacing, so a layer whose height is
// larger than its smallest spacing is marched in up to kMaxSubSteps equal
// parts. Measured on the NACA 0012 O-grid 257x129 to 100 chords: 1 part per
// layer gives 88% of the cells within 5 degrees of orthogonal, 16 parts 98.5%.
// With at most 16 the C-grid 7169x2049 to 500 chords (first cell 1e-7)
// folded at every dissipation, and O-grids 385x97 and 897x257 to 100 chords
// (1e-5) at the default; with 64 they march (docs/hyperbolic.md).
constexpr double kMaxStepRatio = 1.0;
constexpr int kMaxSubSteps = 64;
// A march that folds and may resume (hyperbolic.hpp) saves its state every
// kSaveEvery layers and goes back at least kResumeLayers layers: the fold
// begins a few layers before the layer that shows it.
constexpr int kSaveEvery = 32, kResumeLayers = 64;
const double kLnMin = std::log(0.1), kLnMax = std::log(100.0);  // the clamp of d
// A convex corner of JMIN turning by 45 to 135 degrees (a blunt base's) has
// a second difference of the order of its spacing, not of the spacing
// squared times the curvature, so the explicit dissipation there grows with
// the step: at EG2D_PARAM_MARCH_SMOOTHING 4 (a C-grid's start) it moved the
// base corners of NACA 0012's open section back by their whole step by
// layer 4, the base's cells folded (385x97; O-grids 257x129 too). On those
// columns it moves a node by at most this share of its step. A sharp
// trailing edge turns by more (164 degrees on an O-grid) and keeps the full
// dissipation, which its march needs; the marches with no such corner are
// unchanged.
constexpr double kCornerShare = 0.1;
const double kCornerLeast = 0.25 * 3.14159265358979323846, kCornerMost = 0.75 * 3.14159265358979323846;

double len(double x, double y) { return std::sqrt(x * x + y * y); }

// Signed area of the closed polygon p[first..last] (shoelace).
double loop_area(const std::vector<Vec2> &p, int first, int last) {
    double a = 0.0;
    for (int i = first; i < last; ++i) a += p[i].x * p[i + 1].y - p[i + 1].x * p[i].y;
    a += p[last].x * p[first].y - p[first].x * p[last].y;
    return 0.5 * a;
}

// Which side of JMIN the march goes to: +1 left of the curve as it runs, -1
// right. O- and C-grids march away from the body whichever way it runs.
double march_side(const Grid &g, const std::vector<Vec2> &r0) {
    const int ni = g.ni();
    if (g.topology() == Topology::O) return loop_area(r0, 0, ni - 2) > 0 ? -1.0 : 1.0;
    if (g.topology() == Topology::C) {
        const int w = g.connectivity().wake();
        return loop_area(r0, w, ni - 1 - w) > 0 ? -1.0 : 1.0;
    }
    return 1.0;
}

struct Layer {
    int n = 0;  // distinct nodes (ni-1 on an O-grid)
    bool periodic = false;
    int west(int i) const { return i > 0 ? i - 1 : (periodic ? n - 1 : -1); }
    int east(int i) const { return i < n - 1 ? i + 1 : (periodic ? 0 : -1); }
};

// The local geometry of a layer at node i: unit tangent t (the bisector of
// the two edges, so a sharp edge marches along the bisector of its angle),
// arc length ds per index, the marching normal n, the concave-corner factor
// a (Chan & Steger 1992: 1 / sin^2(alpha/2) for an interior angle alpha < pi
// on the marching side, 1 elsewhere) and the summed length of its edges.
struct NodeFrame {
    Vec2 t, n;
    double ds = 0, a = 1, edges = 0;
};

void frames(const Layer &L, const std::vector<Vec2> &r, double side, std::vector<NodeFrame> &f,
            std::vector<double> &edge) {
    // edge[i]: length of r[i] -> r[east(i)].
    for (int i = 0; i < L.n; ++i) {
        const int e = L.east(i);
        edge[i] = e >= 0 ? len(r[e].x - r[i].x, r[e].y - r[i].y) : 0.0;
    }
    for (int i = 0; i < L.n; ++i) {
        const int w = L.west(i), e = L.east(i);
        NodeFrame &F = f[i];
        const double lw = w >= 0 ? edge[w] : 0.0, le = e >= 0 ? edge[i] : 0.0;
        Vec2 tw{0, 0}, te{0, 0};
        if (w >= 0) {
            const double k = 1.0 / lw;
            tw = {(r[i].x - r[w].x) * k, (r[i].y - r[w].y) * k};
        }
        if (e >= 0) {
            const double k = 1.0 / le;
            te = {(r[e].x - r[i].x) * k, (r[e].y - r[i].y) * k};
        }
        if (w < 0) tw = te;
        if (e < 0) te = tw;
        F.edges = lw + le;
        F.ds = (w >= 0 && e >= 0) ? 0.5 * (lw + le) : (w >= 0 ? lw : le);
        const double tx = tw.x + te.x, ty = tw.y + te.y, tl = len(tx, ty);
        // A cusp (the edges fold back on each other): march straight past
        // the tip, along the incoming edge.
        F.t = tl < 1e-10 ? Vec2{side * tw.y, -side * tw.x} : Vec2{tx * (1.0 / tl), ty * (1.0 / tl)};
        F.n = {-side * F.t.y, side * F.t.x};
        // The curve turns towards the march (concave) when the cross product
        // of its edges has the march side's sign; the interior angle on the
        // marching side is then alpha = pi - turn, and sin^2(alpha/2) =
        // (1 + cos turn)/2 with cos turn = tw.te (alpha at least 10 degrees,
        // so a slit does not make the factor infinite).
        const double cross = tw.x * te.y - tw.y * te.x;
        F.a = 1.0;
        if (side * cross > 0) F.a = 1.0 / std::max(0.5 * (1.0 + tw.x * te.x + tw.y * te.y), kMinSin2);
    }
}

// Area smoothing (Chan & Steger 1992), done on the step lengths area/ds
// (smoothing the areas themselves lets the wide cells of a trailing-edge fan
// lend area to the narrow ones beside them, which bulges the layer there
// and draws the lines of the flat surfaces together): each pass moves a
// value a quarter of the way towards each neighbour.
void smooth(const Layer &L, std::vector<double> &v, int passes, std::vector<double> &tmp) {
    const int n = L.n;
    tmp.resize(v.size());
    for (int p = 0; p < passes; ++p) {
        const double *a = v.data();
        double *b = tmp.data();
        for (int i = 1; i < n - 1; ++i) b[i] = 0.5 * a[i] + 0.25 * (a[i - 1] + a[i + 1]);
        // The ends: across the cut on an O-grid, else a mirror (no flux out).
        b[0] = 0.5 * a[0] + 0.25 * ((L.periodic ? a[n - 1] : a[0]) + a[1]);
        b[n - 1] = 0.5 * a[n - 1] + 0.25 * (a[n - 2] + (L.periodic ? a[0] : a[n - 1]));
        v.swap(tmp);
    }
}

Mat2 scaled_identity(double s) { return {s, 0, 0, s}; }

struct March {
    const Settings &s;
    Layer L;
    double side = 1;
    int layers = 0;
    std::vector<Vec2> r, prev, rhs;
    std::vector<NodeFrame> f;
    std::vector<double> step, edge, prev_edge, wall_edge, tmp, factor, sensor;
    std::vector<Mat2> A, B, C, scratch;
    std::vector<char> corner;  // JMIN's convex corners (kCornerShare)
    MarchEnd ends[2];

    March(const Settings &settings, const Layer &layer) : s(settings), L(layer) {
        const std::size_t n = static_cast<std::size_t>(L.n);
        rhs.resize(n); f.resize(n); step.resize(n); edge.resize(n); prev_edge.resize(n); sensor.resize(n);
        A.resize(n); B.resize(n); C.resize(n);
        ends[0] = static_cast<MarchEnd>(static_cast<int>(s.march_end_imin));
        ends[1] = static_cast<MarchEnd>(static_cast<int>(s.march_end_imax));
    }

    // The step length per unit height at each node, factor[i]: cell area =
    // height x local arc length (Chan & Steger 1992), the arc length taken
    // on the layer a plain normal step of hl would make: the implicit solve
    // spreads the area over the new layer's width, so with the old width a
    // convex layer of radius R would step only h/(1 + h/R), 12% short per
    // far-field layer of an airfoil O-grid. Where the predicted layer
    // converges (concave) its width is kept above half the old one. Then
    // the area smoothing.
    void step_factors(double hl) {
        for (int i = 0; i < L.n; ++i) {
            const int w = L.west(i), e = L.east(i);
            const Vec2 pc{r[i].x + hl * f[i].n.x, r[i].y + hl * f[i].n.y};
            double width = 0.0;
            int count = 0;
            for (int k : {w, e}) {
                if (k < 0) continue;
                width += len(r[k].x + hl * f[k].n.x - pc.x, r[k].y + hl * f[k].n.y - pc.y);
                ++count;
            }
            step[i] = std::max(width / count, 0.5 * f[i].ds) / f[i].ds;
        }
        smooth(L, step, static_cast<int>(s.march_area_smoothing), tmp);
        factor = step;
    }

    // One implicit step of height hl from r (whose frames f are current);
    // Sl is Chan & Steger's layer scaling, ratio the layer's height growth.
    // The sub-steps after a layer's first (same_layer) reuse its step
    // factors: the area smoothing was most of the cost, and redoing it per
    // sub-step changed no measured figure by more than 0.01% (NACA 0012
    // 257x129: 25 -> 15-18 ms). They reuse its sensor d too, taken once per
    // layer at its first sub-step: its log and exp per node and sub-step
    // were a quarter of the march of 7169x2049, and between sub-steps of a
    // layer its convergence ratio moves only by the sub-step's change.
    void advance(double hl, double Sl, double ratio, bool first, bool same_layer) {
        if (!same_layer) step_factors(hl);
        for (int i = 0; i < L.n; ++i) step[i] = factor[i] * hl;

        for (int i = 0; i < L.n; ++i) {
            const NodeFrame &F = f[i];
            const Vec2 rx{F.ds * F.t.x, F.ds * F.t.y};          // r_xi0
            const Vec2 re{step[i] * F.n.x, step[i] * F.n.y};    // r_eta0: orthogonal, the area asked
            // A0 = [[x_eta, y_eta], [y_eta, -x_eta]], B0 = [[x_xi, y_xi],
            // [-y_xi, x_xi]] (Steger & Chaussee eq 7; the march side enters
            // through r_eta0); C = B0^-1 A0.
            const double iq = 1.0 / (rx.x * rx.x + rx.y * rx.y);
            const Mat2 Cm{(rx.x * re.x - rx.y * re.y) * iq, (rx.x * re.y + rx.y * re.x) * iq,
                          (rx.y * re.x + rx.x * re.y) * iq, (rx.y * re.y - rx.x * re.x) * iq};
            // Chan & Steger's grid-convergence sensor D: the spacing of the
            // layer before over this one's, > 1 where lines converge; it
            // enters as d = D^(2/Sl), kept within [0.1, 100]. eg2d takes the
            // larger of that and the wall's spacing over this one's: at a
            // concave right angle the lines from the two sides converge a
            // little per layer but a lot in total, and with the per-layer
            // ratio alone the two cells beside the corner's line folded
            // (L-shaped body, 129x65 and 257x129); the wall ratio is < 1
            // wherever the march spreads, so it changes nothing there.
            const int w = L.west(i), e = L.east(i);
            double &d = sensor[i];
            if (same_layer) {
                // as the layer's first sub-step
            } else if (first || w < 0 || e < 0 || !(Sl > 0)) {
                d = 1.0;
            } else {
                const double D = std::max(prev_edge[w] + prev_edge[i], wall_edge[w] + wall_edge[i]) / F.edges;
                // d = D^(2/Sl) clamped: compare the exponent with ln 0.1 and
                // ln 100 first, so exp runs only when the clamp does not decide.
                const double lnd = (2.0 / Sl) * std::log(D);
                d = lnd <= kLnMin ? 0.1 : (lnd >= kLnMax ? 100.0 : std::exp(lnd));
            }
            // eps_e = eps_c N Sl d a, N = |r_eta| / |r_xi| (Chan & Steger 1992).
            double eps_e = s.march_smoothing * (step[i] / F.ds) * Sl * d * F.a;
            if (corner[i] && w >= 0 && e >= 0) {
                const double dxx = len(r[e].x - 2 * r[i].x + r[w].x, r[e].y - 2 * r[i].y + r[w].y);
                if (eps_e * dxx > kCornerShare * step[i]) eps_e = kCornerShare * step[i] / dxx;
            }
            const double eps_i = 2.0 * eps_e;
            A[i] = {-0.5 * Cm.a - eps_i, -0.5 * Cm.b, -0.5 * Cm.c, -0.5 * Cm.d - eps_i};
            B[i] = scaled_identity(1.0 + 2.0 * eps_i);
            C[i] = {0.5 * Cm.a - eps_i, 0.5 * Cm.b, 0.5 * Cm.c, 0.5 * Cm.d - eps_i};
            rhs[i] = re;
            if (w >= 0 && e >= 0) {
                rhs[i].x += eps_e * (r[e].x - 2 * r[i].x + r[w].x);
                rhs[i].y += eps_e * (r[e].y - 2 * r[i].y + r[w].y);
            }
        }
        if (L.periodic) {
            solve_cyclic_block_tridiagonal2(static_cast<std::size_t>(L.n), A.data(), B.data(), C.data(), rhs.data());
        } else {
            open_ends(ratio);
            solve_block_tridiagonal2(static_cast<std::size_t>(L.n), A.data(), B.data(), C.data(), rhs.data(), scratch);
        }
        // The dissipation pulls a convex layer back towards its centre of
        // curvature (5-10% of the distance of a circle's O-grid, summed over
        // the layers): scale the step so that its mean along the normals,
        // weighted by arc length, is the height asked. The scaling keeps
        // every direction, so it keeps the orthogonality.
        double along = 0.0, weight = 0.0;
        for (int i = 0; i < L.n; ++i) {
            along += f[i].ds * (rhs[i].x * f[i].n.x + rhs[i].y * f[i].n.y);
            weight += f[i].ds;
        }
        if (along > 0.0) {
            const double scale = hl * weight / along;
            for (int i = 0; i < L.n; ++i) rhs[i] = {scale * rhs[i].x, scale * rhs[i].y};
        }
        if (first) wall_edge = edge;  // JMIN's edge lengths
        prev.swap(r);
        prev_edge.swap(edge);
        r.resize(prev.size());
        for (int i = 0; i < L.n; ++i) r[i] = {prev[i].x + rhs[i].x, prev[i].y + rhs[i].y};
    }

    // Rows 0 and n-1 of an open layer (docs/hyperbolic.md).
    void open_ends(double ratio) {
        for (int end = 0; end < 2; ++end) {
            const int i = end == 0 ? 0 : L.n - 1, nb = end == 0 ? 1 : L.n - 2;
            Mat2 &toward = end == 0 ? C[i] : A[i];
            (end == 0 ? A[i] : C[i]) = Mat2{};
            B[i] = scaled_identity(1.0);
            toward = Mat2{};
            switch (ends[end]) {
            case MarchEnd::Free:  // the end node's own orthogonal step (its row's r_eta0)
                break;
            case MarchEnd::ConstantX:  // x kept, y as its neighbour's: a symmetry plane x = const
                toward = {0, 0, 0, -1};
                rhs[i] = {0, 0};
                break;
            case MarchEnd::ConstantY:
                toward = {-1, 0, 0, 0};
                rhs[i] = {0, 0};
                break;
            case MarchEnd::Splay:  // the end cell widens as the layer heights grow
                toward = scaled_identity(-1.0);
                rhs[i] = {(ratio - 1.0) * (r[i].x - r[nb].x), (ratio - 1.0) * (r[i].y - r[nb].y)};
                break;
            }
        }
    }
};

// 1 at the nodes of JMIN that are convex corners on the march's side:
// turning by kCornerLeast to kCornerMost, their neighbours by less than a
// quarter of that (a coarse leading edge turns over several nodes: the
// gallery's NACA 0012 O-grid by 51 degrees at the edge, 29 beside it).
std::vector<char> convex_corners(const Layer &L, const std::vector<Vec2> &r, double side) {
    std::vector<double> turn(static_cast<std::size_t>(L.n), 0.0);  // convex > 0
    for (int i = 0; i < L.n; ++i) {
        const int w = L.west(i), e = L.east(i);
        if (w < 0 || e < 0) continue;
        const Vec2 a{r[i].x - r[w].x, r[i].y - r[w].y}, b{r[e].x - r[i].x, r[e].y - r[i].y};
        turn[static_cast<std::size_t>(i)] = -side * std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
    }
    std::vector<char> corner(turn.size(), 0);
    for (int i = 0; i < L.n; ++i) {
        const int w = L.west(i), e = L.east(i);
        const double t = turn[static_cast<std::size_t>(i)];
        if (w < 0 || e < 0 || t <= kCornerLeast || t >= kCornerMost) continue;
        corner[static_cast<std::size_t>(i)] = turn[static_cast<std::size_t>(w)] < 0.25 * t && turn[static_cast<std::size_t>(e)] < 0.25 * t;
    }
    return corner;
}

// +1 if the cells between rows j and j+1 have positive area in total.
int layer_orientation(const Grid &g, int j) {
    double total = 0.0;
    for (int i = 0; i < g.ni() - 1; ++i) total += Cell::at(g, i, j).area();
    return total < 0.0 ? -1 : 1;
}

struct FoldedRow {
    int count = 0, first = -1;
};

// The folded cells between rows j and j+1 (base/folds.hpp's test).
FoldedRow folded_cells(const Grid &g, int j, int orientation) {
    FoldedRow f;
    for (int i = 0; i < g.ni() - 1; ++i)
        if (is_folded(Cell::at(g, i, j), orientation) && f.count++ == 0) f.first = i;
    return f;
}

// The state a march goes back to when it resumes (kResumeLayers): the layer
// about to be made and what its step reads.
struct Resume {
    int layer = 1;
    std::vector<Vec2> r, prev;
    std::vector<double> prev_edge;
    bool first = true;
};

// The state a fold at `layer` goes back to: the newest at least
// kResumeLayers before it, else the oldest.
std::vector<Resume>::iterator resume_point(std::vector<Resume> &saved, int layer) {
    auto back = saved.begin();
    for (auto k = saved.begin(); k != saved.end(); ++k)
        if (k->layer <= layer - kResumeLayers) back = k;
    return back;
}

void march(Grid &g, const Settings &settings, const std::vector<double> &raised, std::string *note) {
    const int ni = g.ni(), layers = g.nj() - 1;
    Settings s = settings;  // the smoothing rises on a resumption; March reads it through its reference
    Layer L;
    L.periodic = g.topology() == Topology::O;
    L.n = L.periodic ? ni - 1 : ni;
    March m(s, L);
    m.r.resize(static_cast<std::size_t>(ni));
    for (int i = 0; i < ni; ++i) m.r[i] = {g.x[i], g.y[i]};
    m.side = march_side(g, m.r);
    m.r.resize(static_cast<std::size_t>(L.n));
    m.prev = m.r;
    m.corner = convex_corners(L, m.r, m.side);

    double xmin = m.r[0].x, xmax = xmin, ymin = m.r[0].y, ymax = ymin;
    for (const Vec2 &p : m.r) {
        xmin = std::min(xmin, p.x); xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y); ymax = std::max(ymax, p.y);
    }
    const double size = len(xmax - xmin, ymax - ymin);
    const double distance = s.march_distance > 0.0 ? s.march_distance : 10.0 * size;
    // Layers thinner than this are rounding in the coordinates (and their
    // heights' ratios 0/0 when they underflow).
    if (!(distance >= 1e-10 * size))
        fail(Failure::Argument, format("march_distance = %g: below 1e-10 of the curve's size %g, too thin for its "
                                       "layers to be told apart in double precision", distance, size));
    const std::vector<double> h = march_schedule(layers, distance, s.march_first_height, s.march_growth);
    // Chan & Steger's scaling of the dissipation with the layer index l:
    // Sl = sqrt((l-1)/(lmax-1)) up to 3/4 of the layers, constant beyond.
    const int transition = std::max(2, (3 * layers) / 4);
    bool first = true;
    int orientation = 1;
    std::size_t next_raise = 0;
    std::vector<Resume> saved;  // every kSaveEvery layers, while a resumption is left
    for (int l = 1; l <= layers; ++l) {
        setup_tick();  // the monitor, layer by layer (base/setup_progress.hpp)
        if (next_raise < raised.size() && (l - 1) % kSaveEvery == 0) {
            saved.push_back({l, m.r, m.prev, m.prev_edge, first});
            // With one resumption left, the next fold is at this layer or
            // above and goes back to the newest state at least kResumeLayers
            // before it: older states are never read (a C-grid's, which has
            // one, kept 64 of them at 7169x2049, 18 MB). With more left a
            // resumption moves the march back below this layer, and a later
            // fold may need them.
            if (raised.size() - next_raise == 1) saved.erase(saved.begin(), resume_point(saved, l));
        }
        const double Sl = layers > 1 ? std::sqrt(static_cast<double>(std::min(l, transition) - 1) / (layers - 1)) : 0;
        const double ratio = l > 1 ? h[l - 1] / h[l - 2] : (layers > 1 ? h[1] / h[0] : 1.0);
        frames(L, m.r, m.side, m.f, m.edge);
        double ds_min = m.f[0].ds;
        for (const NodeFrame &F : m.f) ds_min = std::min(ds_min, F.ds);
        const int parts = static_cast<int>(
            std::min<double>(kMaxSubSteps, std::max(1.0, std::ceil(h[l - 1] / ds_min / kMaxStepRatio))));
        for (int part = 0; part < parts; ++part) {
            if (part > 0) frames(L, m.r, m.side, m.f, m.edge);
            m.advance(h[l - 1] / parts, Sl, part == 0 ? ratio : 1.0, first, part > 0);
            first = false;
        }
        const std::size_t row = static_cast<std::size_t>(ni) * static_cast<std::size_t>(l);
        for (int i = 0; i < L.n; ++i) {
            if (!std::isfinite(m.r[i].x) || !std::isfinite(m.r[i].y))
                fail(Failure::Diverged,
                     format("march: layer %d, node %d is not finite (a singular layer system: repeated points "
                            "on JMIN?)", l, i));
            g.x[row + i] = m.r[i].x;
            g.y[row + i] = m.r[i].y;
        }
        if (L.periodic) {
            g.x[row + ni - 1] = m.r[0].x;
            g.y[row + ni - 1] = m.r[0].y;
        }
        // A layer that folds ends the march: the grid beyond is not usable
        // (NACA 0012 385x97 to 100 chords folded 82 cells at layer 84 and
        // was handed back as a grid). The first layer's turn is the sign.
        if (l == 1) orientation = layer_orientation(g, 0);
        const FoldedRow folded = folded_cells(g, l - 1, orientation);
        if (folded.count == 0) continue;
        const std::string what = format("march: layer %d folds %d cell(s), the first at i = %d", l, folded.count,
                                        folded.first);
        if (next_raise < raised.size()) {
            const auto back = resume_point(saved, l);
            const double from = s.march_smoothing;
            s.march_smoothing = raised[next_raise++];
            if (note)
                *note += format("%s%s at EG2D_PARAM_MARCH_SMOOTHING %g; marched on from layer %d with %g",
                                note->empty() ? "" : "; ", what.c_str(), from, back->layer, s.march_smoothing);
            m.r = back->r;
            m.prev = back->prev;
            m.prev_edge = back->prev_edge;
            first = back->first;
            l = back->layer - 1;
            saved.erase(std::next(back), saved.end());
            continue;
        }
        fail(Failure::Folded, what + ": lower EG2D_PARAM_MARCH_GROWTH or the distance, raise nj, or raise "
                                     "EG2D_PARAM_MARCH_SMOOTHING");
    }
}

}  // namespace

void hyperbolic_march(Grid &g, const Settings &s) { march(g, s, {}, nullptr); }

void hyperbolic_march(Grid &g, const Settings &s, const std::vector<double> &raised, std::string &note) {
    march(g, s, raised, &note);
}

}  // namespace eg2d
