#include "piece_curve.hpp"

#include <eg2d.h>

#include <limits>
#include <memory>

#include "failure.hpp"
#include "toml_fields.hpp"

namespace eg2dtool {

bool needs_curve(const SidePiece &p) {
    return p.distribution.given || !p.curve.empty() || !p.naca.empty() || !p.airfoil.empty();
}

#ifdef EG2D_DIST_VINOKUR

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

bool curves_available() { return true; }

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
    const std::string kind = Fields(t, where, {"kind"}).choice("kind", "", {"uniform", "exponential", "tanh", "tanh2", "vinokur"});
    if (kind == "uniform") {
        Fields(t, where, {"kind"}).finish();
        d.kind = EG2D_DIST_UNIFORM;
    } else if (kind == "exponential") {  // beta > 0 clusters at the start
        Fields f(t, where, {"kind", "beta"});
        f.finish();
        d.kind = EG2D_DIST_EXPONENTIAL;
        d.p1 = f.number("beta", constants);
    } else if (kind == "tanh") {  // one-sided, clusters at the start
        Fields f(t, where, {"kind", "delta"});
        f.finish();
        d.kind = EG2D_DIST_TANH_ONE;
        d.p1 = f.number("delta", constants);
    } else if (kind == "tanh2") {
        Fields f(t, where, {"kind", "b", "c"});
        f.finish();
        d.kind = EG2D_DIST_TANH_TWO;
        d.p1 = f.number("b", constants);
        d.p2 = f.number("c", constants);
    } else {  // Vinokur: the first and last spacings, in length units
        Fields f(t, where, {"kind", "first", "last"});
        f.finish();
        d.kind = EG2D_DIST_VINOKUR;
        d.p1 = f.number("first", constants);
        d.p2 = f.number("last", constants);
    }
    return d;
}

void curve_nodes(const SidePiece &p, int n, const Constants &constants, std::vector<double> &x,
                 std::vector<double> &y) {
    eg2d_curve *raw = nullptr;
    std::unique_ptr<Formula> fx, fy;
    FormulaCurve user{nullptr, nullptr, nullptr};
    Location at = p.where;
    if (!p.x.empty()) {
        fx = std::make_unique<Formula>(p.x, std::vector<std::string>{"s"}, constants, p.x_at);
        fy = std::make_unique<Formula>(p.y, std::vector<std::string>{"s"}, constants, p.y_at);
        user.fx = fx.get();
        user.fy = fy.get();
        const int status = eg2d_curve_function(&formula_point, &user, &raw);
        if (user.failure) throw *user.failure;
        check(status, p.x_at);
    } else if (!p.naca.empty()) {
        check(eg2d_curve_naca4(p.naca.c_str(), p.closed_te ? EG2D_NACA_CLOSED_TE : 0, &raw), p.where);
    } else if (!p.airfoil.empty()) {
        check(eg2d_curve_read_airfoil(p.airfoil.c_str(), &raw), p.points_at);
    } else {
        const int count = static_cast<int>(p.px.size());
        at = p.points_at;
        check(p.curve == "spline" ? eg2d_curve_spline(count, p.px.data(), p.py.data(), &raw)
                                  : eg2d_curve_polyline(count, p.px.data(), p.py.data(), &raw),
              p.points_at);
    }
    CurvePtr curve(raw);
    const Distribution uniform;
    const Distribution &d = p.distribution.given ? p.distribution : uniform;
    x.assign(static_cast<std::size_t>(n), 0);
    y.assign(x.size(), 0);
    const int status = eg2d_curve_points(curve.get(), n, d.kind, d.p1, d.p2, x.data(), y.data());
    if (user.failure) throw *user.failure;
    check(status, p.distribution.given ? d.where : at);
}

#else  // the library has no curves

namespace {
const char *unavailable = ": is not available in this build of eg2d (it has no curves)";
}

bool curves_available() { return false; }

Distribution parse_distribution(const toml::node &, const Location &where, const Constants &) {
    throw Failure(EXIT_UNSUPPORTED, where.str() + unavailable);
}

void curve_nodes(const SidePiece &p, int, const Constants &, std::vector<double> &, std::vector<double> &) {
    throw Failure(EXIT_UNSUPPORTED, p.where.str() + unavailable);
}

#endif

}  // namespace eg2dtool
