#include "piece_curve.hpp"

#include <eg2d.h>

#include <limits>
#include <memory>

#include "failure.hpp"
#include "features.hpp"
#include "toml_fields.hpp"

namespace eg2dtool {

bool needs_curve(const SidePiece &p) {
    return p.distribution.given || !p.curve.empty() || !p.naca.empty() || !p.airfoil.empty() || p.sliding;
}


namespace {

struct CurveDeleter {
    void operator()(eg2d_curve *c) const { eg2d_curve_destroy(c); }
};
using CurvePtr = std::unique_ptr<eg2d_curve, CurveDeleter>;

// The formula curve's callback: C code calls it, so nothing may be thrown through it;
// a failure is kept and rethrown after the library call returns.
struct FormulaCurve {
    const Formula *fx, *fy;
    std::unique_ptr<Failure> failure;
};

extern "C" void formula_point(void *user, double t, double *x, double *y) {
    FormulaCurve &c = *static_cast<FormulaCurve *>(user);
    try {
        *x = (*c.fx)({t});
        *y = (*c.fy)({t});
    } catch (const Failure &f) {
        if (!c.failure) c.failure = std::make_unique<Failure>(f);
        *x = *y = std::numeric_limits<double>::quiet_NaN();  // fails the library call
    }
}

void check(int status, const Location &at) {
    if (status != EG2D_OK) throw Failure(exit_code_for_status(status), at.str() + ": " + eg2d_last_error(nullptr));
}

}  // namespace

namespace {

// The stretching parameter `key`, or first_spacing = ... in its place (> 0,
// in the curve's length units; the parameter is solved for in curve_nodes).
void read_stretching(const Fields &f, const char *key, const Constants &constants, Distribution &d) {
    if (f.has(key) && f.has("first_spacing"))
        throw Failure(EXIT_CASE, f.at("first_spacing").str() + ": give " + key + " or first_spacing, not both");
    if (!f.has("first_spacing")) {
        if (!f.has(key)) throw Failure(EXIT_CASE, f.at(key).str() + ": missing: give " + key + " or first_spacing");
        d.p1 = f.number(key, constants);
        return;
    }
    d.first_spacing = f.number("first_spacing", constants);
    d.first_spacing_at = f.at("first_spacing");
    if (!(d.first_spacing > 0))
        throw Failure(EXIT_CASE, d.first_spacing_at.str() + ": must be > 0 (a length, in the curve's units)");
}

}  // namespace

Distribution parse_distribution(const toml::node &node, const Location &where, const Constants &constants) {
    Distribution d;
    d.given = true;
    d.where = where;
    if (node.is_string()) {
        if (*node.value<std::string>() != "uniform")
            throw Failure(EXIT_CASE, where.str() + ": \"" + *node.value<std::string>() +
                                         "\" needs parameters: write a table {kind = ..., ...} (or \"uniform\")");
        d.kind = EG2D_DIST_UNIFORM;
        return d;
    }
    if (!node.is_table()) throw Failure(EXIT_CASE, where.str() + ": expected a string or a table, found " + type_name(node));
    const toml::table &t = *node.as_table();
    // kind: a name of the library's list (eg2d_list_find), each with its own keys
    const std::string kind = Fields(t, where, {"kind"}).choice("kind", "", names(distributions()));
    eg2d_list_find(EG2D_LIST_DISTRIBUTIONS, kind.c_str(), &d.kind);
    if (d.kind == EG2D_DIST_UNIFORM) {
        Fields(t, where, {"kind"}).finish();
    } else if (d.kind == EG2D_DIST_EXPONENTIAL) {  // beta > 0 clusters at the start
        Fields f(t, where, {"kind", "beta", "first_spacing"});
        f.finish();
        read_stretching(f, "beta", constants, d);
    } else if (d.kind == EG2D_DIST_TANH_ONE) {  // one-sided, clusters at the start
        Fields f(t, where, {"kind", "delta", "first_spacing"});
        f.finish();
        read_stretching(f, "delta", constants, d);
    } else if (d.kind == EG2D_DIST_TANH_TWO) {
        Fields f(t, where, {"kind", "b", "c", "first_spacing"});
        f.finish();
        read_stretching(f, "b", constants, d);
        d.p2 = f.number("c", constants);
    } else if (d.kind == EG2D_DIST_VINOKUR) {  // the first and last spacings, in length units
        Fields f(t, where, {"kind", "first", "last"});
        f.finish();
        d.p1 = f.number("first", constants);
        d.p2 = f.number("last", constants);
    } else {
        throw Failure(EXIT_UNSUPPORTED, where.str() + ": kind \"" + kind + "\" has no case-file keys in this eg2d command");
    }
    return d;
}

namespace {

// The library curve of a piece, with what its callback needs kept alive beside it.
struct PieceCurve {
    std::unique_ptr<Formula> fx, fy;
    FormulaCurve user{nullptr, nullptr, nullptr};
    CurvePtr curve;
    Location at;
};

std::unique_ptr<PieceCurve> make_curve(const SidePiece &p, const Constants &constants) {
    auto c = std::make_unique<PieceCurve>();
    eg2d_curve *raw = nullptr;
    c->at = p.where;
    if (!p.x.empty()) {
        c->fx = std::make_unique<Formula>(p.x, std::vector<std::string>{"s"}, constants, p.x_at);
        c->fy = std::make_unique<Formula>(p.y, std::vector<std::string>{"s"}, constants, p.y_at);
        c->user.fx = c->fx.get();
        c->user.fy = c->fy.get();
        const int status = eg2d_curve_function(&formula_point, &c->user, &raw);
        c->curve.reset(raw);  // owned before anything can throw
        raw = nullptr;
        if (c->user.failure) throw *c->user.failure;
        check(status, p.x_at);
    } else if (!p.naca.empty()) {
        check(eg2d_curve_naca4(p.naca.c_str(), p.closed_te ? EG2D_NACA_CLOSED_TE : 0, &raw), p.where);
    } else if (!p.airfoil.empty()) {
        check(eg2d_curve_read_airfoil(p.airfoil.c_str(), &raw), p.points_at);
    } else {
        const int count = static_cast<int>(p.px.size());
        c->at = p.points_at;
        check(p.curve == "spline" ? eg2d_curve_spline(count, p.px.data(), p.py.data(), &raw)
                                  : eg2d_curve_polyline(count, p.px.data(), p.py.data(), &raw),
              p.points_at);
    }
    if (raw) c->curve.reset(raw);
    return c;
}

// The piece's distribution for n nodes on curve c: first_spacing = ... becomes
// the parameter that gives it (eg2d_distribution_parameter, in fractions of
// the curve's length).
Distribution distribution_of(const SidePiece &p, const PieceCurve &c, int n) {
    if (!p.distribution.given) return Distribution{};  // kind 0: EG2D_DIST_UNIFORM
    Distribution d = p.distribution;
    if (d.first_spacing > 0) {
        double length = 0;
        check(eg2d_curve_length(c.curve.get(), &length), c.at);
        check(eg2d_distribution_parameter(d.kind, n, d.first_spacing / length, d.p2, &d.p1), d.first_spacing_at);
    }
    return d;
}

}  // namespace

void curve_nodes(const SidePiece &p, int n, const Constants &constants, std::vector<double> &x,
                 std::vector<double> &y) {
    const auto c = make_curve(p, constants);
    const Distribution d = distribution_of(p, *c, n);
    x.assign(static_cast<std::size_t>(n), 0);
    y.assign(x.size(), 0);
    const int status = eg2d_curve_points(c->curve.get(), n, d.kind, d.p1, d.p2, x.data(), y.data());
    if (c->user.failure) throw *c->user.failure;
    check(status, p.distribution.given ? d.where : c->at);
}

SlidingSide::SlidingSide(eg2d_grid *grid, const SideSpec &spec, const Constants &constants) {
    const SidePiece &p = spec.pieces.front();
    auto c = make_curve(p, constants);
    int ni = 0, nj = 0;
    eg2d_get_size(grid, &ni, &nj);
    const Distribution d = distribution_of(p, *c, spec.side == EG2D_SIDE_JMIN || spec.side == EG2D_SIDE_JMAX ? ni : nj);
    const int flags = EG2D_CURVE_SLIDING | (p.reverse ? EG2D_CURVE_REVERSE : 0);
    const int status = eg2d_set_side_curve(grid, spec.side, c->curve.get(), d.kind, d.p1, d.p2, flags);
    if (c->user.failure) throw *c->user.failure;
    if (status != EG2D_OK) throw Failure(exit_code_for_status(status), spec.where.str() + ": " + eg2d_last_error(grid));
    keep_ = std::shared_ptr<void>(c.release(), [](void *q) { delete static_cast<PieceCurve *>(q); });
}


}  // namespace eg2dtool
