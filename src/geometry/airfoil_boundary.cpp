#include "geometry/airfoil_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/error.hpp"
#include "geometry/distribution.hpp"
#include "grid/march_schedule.hpp"

namespace eg2d {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A trailing-edge gap below this many chords is a sharp trailing edge.
constexpr double kClosedGap = 1e-7;
// Automatic spacings as fractions of the section's mean spacing: the
// trailing edge a quarter of it, the leading edge a tenth (NACA 0012 with
// 225 section nodes: 0.0023 and 0.0009 chords; Construct2D's defaults for
// 250: 0.003 and 0.00075).
constexpr double kTeShare = 0.25, kLeShare = 0.1;

struct P {
    double x = 0, y = 0;
};

P point(const ArcLength &c, double s) {
    P p;
    c.point(s, p.x, p.y);
    return p;
}

double dist(P a, P b) { return std::hypot(b.x - a.x, b.y - a.y); }

// The leading edge: the point farthest from the trailing edge's midpoint,
// sampled then refined by golden-section search.
double leading_edge(const ArcLength &c, P te) {
    const int samples = 400;
    int best = 1;
    for (int k = 1; k < samples; ++k)
        if (dist(point(c, double(k) / samples), te) > dist(point(c, double(best) / samples), te)) best = k;
    double a = double(best - 1) / samples, b = double(best + 1) / samples;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int it = 0; it < 100; ++it) {
        const double m1 = b - g * (b - a), m2 = a + g * (b - a);
        if (dist(point(c, m1), te) > dist(point(c, m2), te)) b = m2;
        else a = m1;
    }
    return 0.5 * (a + b);
}

// The least end spacing of a surface, as a share of its length: Vinokur's
// function (distribution.cpp) refuses less.
constexpr double kLeastShare = 1e-14;

// n points of the section between normalized arc lengths s0 and s1 by
// Vinokur's distribution with end spacings d0, d1 (chords, scaled to the
// piece's length).
std::vector<P> surface(const ArcLength &c, double s0, double s1, int n, double d0, double d1) {
    const double length = (s1 - s0) * c.length();
    std::vector<double> s(static_cast<std::size_t>(n));
    if (d0 + d1 >= length)
        fail(Failure::Argument,
             format("eg2d_set_airfoil: end spacings %g and %g do not fit a surface %g long: lower "
                    "EG2D_PARAM_AIRFOIL_LE_SPACING or EG2D_PARAM_AIRFOIL_TE_SPACING", d0, d1, length));
    if (std::min(d0, d1) < kLeastShare * length)
        fail(Failure::Argument,
             format("eg2d_set_airfoil: end spacings %g and %g on a surface %g long: below %g of it, finer than "
                    "double precision resolves: raise EG2D_PARAM_AIRFOIL_LE_SPACING or EG2D_PARAM_AIRFOIL_TE_SPACING",
                    d0, d1, length, kLeastShare));
    distribute(4 /* EG2D_DIST_VINOKUR */, n, d0, d1, length, s.data());
    std::vector<P> out;
    for (double v : s) out.push_back(point(c, s0 + (s1 - s0) * v));
    return out;
}

// An O-grid's sharp trailing edge is a single wall node with two cells:
// its 344 degrees (NACA 0012) outside the section are split into two
// corners of about 172 degrees, and every ring of the march carries that V
// out along the edge's line. OpenFOAM's checkMesh read NACA 0012 257x129 at
// y+ 1 with skewness 17.1 (limit 4) there. Cut back to a base 5e-5 chords
// thick (two corners of about 98 degrees, as an open section's base) the
// same grid passed: skewness 2.08, non-orthogonality 20.7. The cut is
// searched along the chord, at most this far back (a cusped edge that
// stays thinner than the base is cut there).
constexpr double kMaxTeCut = 0.005;

// The normalized arc length between s_from and s_to (the trailing edge's end
// first) at which the section is `back` chords before the trailing edge te
// along the direction b (te - p).b = back: the first crossing from the
// trailing edge, by sampling, then bisection.
double cut_at(const ArcLength &c, double s_from, double s_to, P te, P b, double chord, double back) {
    auto along = [&](double s) {
        const P p = point(c, s);
        return ((te.x - p.x) * b.x + (te.y - p.y) * b.y) / chord;
    };
    const int samples = 2000;
    double a = s_from, z = s_to;
    for (int k = 1; k <= samples; ++k) {
        const double s = s_from + (s_to - s_from) * k / samples;
        if (along(s) >= back) {
            z = s;
            break;
        }
        a = s;
    }
    for (int it = 0; it < 100; ++it) {
        const double m = 0.5 * (a + z);
        (along(m) < back ? a : z) = m;
    }
    return 0.5 * (a + z);
}

// The n points after a on the straight line to b, uniform (b the last).
void segment(std::vector<P> &out, P a, P b, int n) {
    for (int k = 1; k <= n; ++k) out.push_back({a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n});
}

}  // namespace

int automatic_wake(int ni) {
    int step = 1;
    while (step < 64 && (ni - 1) % (2 * step) == 0) step *= 2;
    // The largest such step that rounds to within 2% of the nodes (a tenth
    // of the cut): 64 alone gave 64 at 385 (0.167 (ni-1)), where `eg2d
    // airfoil`'s family of three levels had 80.
    const double want = 0.21 * (ni - 1);
    auto round_to = [&](int s) { return s * static_cast<int>(std::lround(want / s)); };
    while (step > 1 && std::fabs(round_to(step) - want) > 0.02 * (ni - 1)) step /= 2;
    return std::max(2, round_to(step));
}

void airfoil_boundary(const ArcLength &c, const AirfoilSpec &spec, int ni, int nj, std::vector<double> &x,
                      std::vector<double> &y) {
    const bool cgrid = spec.topology == Topology::C;
    if (!cgrid && spec.topology != Topology::O)
        fail(Failure::Argument, "eg2d_set_airfoil: topology must be EG2D_TOPO_O or EG2D_TOPO_C");
    P lower = point(c, 0.0), upper = point(c, 1.0);
    const P te{0.5 * (lower.x + upper.x), 0.5 * (lower.y + upper.y)};
    const double s_le = leading_edge(c, te);
    const P le = point(c, s_le);
    const double chord = dist(le, te);
    if (!(chord > 0.0)) fail(Failure::Argument, "eg2d_set_airfoil: the section has no chord (its leading edge is its trailing edge)");
    const P e{(te.x - le.x) / chord, (te.y - le.y) / chord}, n{-e.y, e.x};
    auto frame = [&](double u, double v) { return P{le.x + chord * (u * e.x + v * n.x), le.y + chord * (u * e.y + v * n.y)}; };
    double gap = dist(lower, upper) / chord;
    bool blunt = gap > kClosedGap && spec.trailing_edge == TrailingEdge::Blunt;
    // An O-grid's sharp trailing edge cut back to a base (kMaxTeCut): the
    // surfaces from s0 and to s1, the least cut along the chord at which
    // they are spec.o_te_base apart (after sharpening, for a section
    // sharpened), by bisection on the cut.
    double s0 = 0.0, s1 = 1.0;
    const P lower_corner = lower, upper_corner = upper;  // what sharpening moves towards te
    const bool open = gap > kClosedGap;
    auto sharpened = [&](P p, P corner) {
        if (!open) return p;
        const double u = std::clamp(((p.x - le.x) * e.x + (p.y - le.y) * e.y) / chord, 0.0, 1.0);
        return P{p.x + u * (te.x - corner.x), p.y + u * (te.y - corner.y)};
    };
    const bool cut = !cgrid && !blunt && spec.o_te_base > 0.0;
    if (cut) {
        // Across the edge's bisector (the surfaces' directions over the
        // last kMaxTeCut chords), so that its two corners turn alike: cut
        // across the chord, S1223's base (its edge 25 degrees below the
        // chord) left corners of unequal turn, and checkMesh's skewness at
        // the sharper one was 4.14.
        const double ds = kMaxTeCut * chord / c.length();
        const P pl = point(c, ds), pu = point(c, 1.0 - ds);
        const double ll = dist(pl, te), lu = dist(pu, te);
        P b{(te.x - pl.x) / ll + (te.x - pu.x) / lu, (te.y - pl.y) / ll + (te.y - pu.y) / lu};
        const double lb = std::hypot(b.x, b.y);
        b = lb > 0.0 ? P{b.x / lb, b.y / lb} : e;
        auto ends = [&](double back, double &a, double &z) {
            a = cut_at(c, 0.0, s_le, te, b, chord, back);
            z = cut_at(c, 1.0, s_le, te, b, chord, back);
            return dist(sharpened(point(c, a), lower_corner), sharpened(point(c, z), upper_corner)) / chord;
        };
        double lo_back = 0.0, hi_back = kMaxTeCut;
        if (ends(hi_back, s0, s1) > spec.o_te_base)
            for (int it = 0; it < 60; ++it) {
                const double m = 0.5 * (lo_back + hi_back);
                (ends(m, s0, s1) < spec.o_te_base ? lo_back : hi_back) = m;
            }
        gap = ends(hi_back, s0, s1);
        lower = sharpened(point(c, s0), lower_corner);
        upper = sharpened(point(c, s1), upper_corner);
        blunt = true;
    }

    // Cut nodes a side; base cells (the whole base on an O-grid, each half on a C-grid).
    const int wake = cgrid ? (spec.wake > 0 ? spec.wake : automatic_wake(ni)) : 0;
    const double perimeter = c.length() / chord;
    const double mean = perimeter / std::max(1, ni - 2 * wake);
    double te_ds = spec.te_spacing > 0 ? spec.te_spacing : kTeShare * mean;
    const double le_ds = spec.le_spacing > 0 ? spec.le_spacing : kLeShare * mean;
    if (std::min(te_ds, le_ds) < kLeastShare * perimeter)
        fail(Failure::Argument,
             format("eg2d_set_airfoil: EG2D_PARAM_AIRFOIL_TE_SPACING = %g, EG2D_PARAM_AIRFOIL_LE_SPACING = %g chords: "
                    "below %g of the section's perimeter, finer than double precision resolves",
                    te_ds, le_ds, kLeastShare));
    int base = 0;
    if (blunt)  // at most ni cells: more leave no section, which the count below refuses
        base = static_cast<int>(std::max<double>(cgrid ? 1 : 2, std::min<double>(ni, std::round((cgrid ? 0.5 : 1.0) * gap / te_ds))));
    // A base: the surfaces (and a C-grid's cut) start at the base's own
    // spacing, so that each of its corners has equal edges and the march's
    // dissipation (a second difference) pulls it along the corner's
    // bisector. With the cut's first cell 1.8 times the base's (NACA 0012
    // C-grid 385x97) it bent the line from the base's midpoint 9 degrees
    // off the bisector after one layer, and OpenFOAM's non-orthogonality
    // beside it reached 83 degrees; 53.5 with the spacings equal. O-grids
    // 257x129: NACA 4412 thinned to a 0.03% base 70.5 -> 29.3 degrees,
    // NACA 0012 40.1 -> 21.0.
    if (blunt) te_ds = (cgrid ? 0.5 : 1.0) * gap / base;
    // Section nodes, corner to corner.
    const int nb = cgrid ? ni - 2 * wake - (blunt ? 2 * base : 0) : ni - base;
    if (nb < 9 || (cgrid && (wake < 2 || nj < 3)))
        fail(Failure::Argument,
             format("eg2d_set_airfoil: %dx%d leaves %d nodes on the section%s: at least 9 are needed (raise ni%s)",
                    ni, nj, nb, cgrid ? format(" with %d cut nodes a side", wake).c_str() : "",
                    cgrid ? " or lower EG2D_PARAM_AIRFOIL_WAKE_NODES" : ""));
    const int nl = (nb + 1) / 2, nu = nb + 1 - nl;  // the leading edge in both
    std::vector<P> lo = surface(c, s0, s_le, nl, te_ds * chord, le_ds * chord);
    std::vector<P> up = surface(c, s_le, s1, nu, le_ds * chord, te_ds * chord);
    if (cut) {  // a section sharpened, then cut: its surfaces as sharpened
        for (P &p : lo) p = sharpened(p, lower_corner);
        for (P &p : up) p = sharpened(p, upper_corner);
        lo.front() = lower;
        up.back() = upper;
    } else if (!blunt) {  // a sharp trailing edge, or one sharpened: the surfaces end at its midpoint
        for (std::vector<P> *side : {&lo, &up}) {
            const P corner = side == &lo ? lower : upper;
            for (P &p : *side) {
                const double u = ((p.x - le.x) * e.x + (p.y - le.y) * e.y) / chord;
                const double t = std::clamp(u, 0.0, 1.0);
                p = {p.x + t * (te.x - corner.x), p.y + t * (te.y - corner.y)};
            }
        }
        lo.front() = up.back() = te;
        lower = upper = te;
    }
    std::vector<P> body(lo);
    body.insert(body.end(), up.begin() + 1, up.end());

    std::vector<P> jmin, jmax;
    const P start = te;  // where the cut starts: the trailing edge (a base's midpoint)
    // A C-grid's cut, outflow and far field are laid out from the trailing
    // edge along the chord, or along a blunt base's normal, so that the
    // base's midpoint is a right angle on both sides of the cut: along the
    // chord, NACA 4412's base (7.6 degrees off normal to it) made angles of
    // 82 and 98 degrees there, and OpenFOAM's non-orthogonality across the
    // cut's first face was 74 degrees.
    P ax = e;
    if (blunt && cgrid) {
        const double bx = upper.x - lower.x, by = upper.y - lower.y, bl = std::hypot(bx, by);
        ax = {by / bl, -bx / bl};
        if (ax.x * e.x + ax.y * e.y < 0.0) ax = {-ax.x, -ax.y};
    }
    const P an{-ax.y, ax.x};
    auto wake_frame = [&](double u, double v) {  // frame() when ax is the chord's direction
        return P{te.x + chord * ((u - 1.0) * ax.x + v * an.x), te.y + chord * ((u - 1.0) * ax.y + v * an.y)};
    };
    if (cgrid) {
        // The cut along ax, its first cell the trailing edge's spacing.
        const double r = covering_ratio(wake, te_ds, spec.farfield);
        std::vector<double> u(static_cast<std::size_t>(wake));  // cut node k (0 = outflow) at 1 + u[k]
        double cell = te_ds, at = 0.0;
        for (int k = wake - 1; k >= 0; --k, cell *= r) u[static_cast<std::size_t>(k)] = (at += cell);
        u[0] = spec.farfield;
        for (int k = 0; k < wake; ++k) jmin.push_back(wake_frame(1.0 + u[static_cast<std::size_t>(k)], 0.0));
        if (blunt) {  // the base's lower half, from its midpoint, is wall
            jmin.push_back(start);
            segment(jmin, start, lower, base);
            jmin.insert(jmin.end(), body.begin() + 1, body.end());
            segment(jmin, upper, start, base);
        } else {
            jmin.insert(jmin.end(), body.begin(), body.end());
        }
        for (int k = wake - 1; k >= 0; --k) jmin.push_back(wake_frame(1.0 + u[static_cast<std::size_t>(k)], 0.0));
        // The far field: lines v = -R, R above the cut, a half circle about
        // the trailing edge between, its nodes by Vinokur's distribution
        // from the trailing edge's spacing at both ends.
        // Its radius R + 1 about the trailing edge keeps the leading edge R
        // away; the outflow is R downstream of the trailing edge.
        // The polygon through its nodes cuts inside the circle by at most
        // the sagitta of its widest angle: the radius grows by that.
        const int na = ni - 2 * wake;
        std::vector<double> s(static_cast<std::size_t>(na));
        distribute(4, na, te_ds, te_ds, kPi * (spec.farfield + 1.0), s.data());
        double widest = 0.0;
        for (int k = 1; k < na; ++k) widest = std::max(widest, kPi * (s[static_cast<std::size_t>(k)] - s[static_cast<std::size_t>(k - 1)]));
        const double far = (spec.farfield + 1.0) / std::cos(0.5 * widest);
        for (int k = 0; k < wake; ++k) jmax.push_back(wake_frame(1.0 + u[static_cast<std::size_t>(k)], -far));
        for (int k = 0; k < na; ++k) {
            const double a = -0.5 * kPi - kPi * s[static_cast<std::size_t>(k)];
            jmax.push_back(wake_frame(1.0 + far * std::cos(a), far * std::sin(a)));
        }
        for (int k = wake - 1; k >= 0; --k) jmax.push_back(wake_frame(1.0 + u[static_cast<std::size_t>(k)], far));
        jmax[static_cast<std::size_t>(wake)] = wake_frame(1.0, -far);
        jmax[static_cast<std::size_t>(ni - 1 - wake)] = wake_frame(1.0, far);
    } else {
        jmin = body;
        if (blunt) segment(jmin, upper, lower, base);  // closes the loop at the lower corner
        // The far field: a circle about the mid-chord, from the trailing
        // edge's direction, turning the way the section does.
        double area = 0.0;
        for (std::size_t k = 0; k + 1 < jmin.size(); ++k) area += jmin[k].x * jmin[k + 1].y - jmin[k + 1].x * jmin[k].y;
        const double turn = area < 0.0 ? -1.0 : 1.0;
        const double far = (spec.farfield + 0.5) / std::cos(kPi / (ni - 1));  // R from the section, between nodes too
        for (int k = 0; k < ni; ++k) {
            const double a = turn * 2.0 * kPi * k / (ni - 1);
            jmax.push_back(frame(0.5 + far * std::cos(a), far * std::sin(a)));
        }
        jmax.back() = jmax.front();
    }
    // The ring: JMIN, JMAX; a C-grid's outflow sides IMIN (lower) and IMAX.
    x.assign(static_cast<std::size_t>(ni) * static_cast<std::size_t>(nj), 0.0);
    y.assign(x.size(), 0.0);
    auto put = [&](int i, int j, P p) {
        x[static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j] = p.x;
        y[static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j] = p.y;
    };
    for (int i = 0; i < ni; ++i) {
        put(i, 0, jmin[static_cast<std::size_t>(i)]);
        put(i, nj - 1, jmax[static_cast<std::size_t>(i)]);
    }
    if (cgrid)
        for (int j = 1; j < nj - 1; ++j) {
            const double v = (spec.farfield + 1.0) * j / (nj - 1);
            put(0, j, wake_frame(1.0 + spec.farfield, -v));
            put(ni - 1, j, wake_frame(1.0 + spec.farfield, v));
        }
}

}  // namespace eg2d
