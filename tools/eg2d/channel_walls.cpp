#include "channel_walls.hpp"

#include <eg2d.h>

#include <cmath>

#include "failure.hpp"
#include "formula.hpp"
#include "piece_curve.hpp"
#include "side_spec.hpp"

namespace eg2dtool {

namespace {

// A curve of the command line as a side piece of the case files' kind (a
// formula pair or a point file's polyline or spline), `where` naming the option.
SidePiece piece_of(const std::string &option, const std::string &text, bool spline) {
    SidePiece p;
    p.where = Location{"channel: " + option, "", 0, 0};
    p.x_at = p.y_at = p.points_at = p.where;
    const std::size_t semicolon = text.find(';');
    if (semicolon != std::string::npos) {
        p.x = text.substr(0, semicolon);
        p.y = text.substr(semicolon + 1);
        if (text.find(';', semicolon + 1) != std::string::npos)
            throw Failure(EXIT_CASE, "channel: " + option + ": \"" + text + "\" holds more than one ';' (\"x(s);y(s)\")");
    } else {
        read_point_file(text, p.where, p.px, p.py);
        p.curve = spline ? "spline" : "polyline";
    }
    return p;
}

// The n nodes of a curve: uniform in arc length, or with the given first and
// last spacings (Vinokur 1983) where either is asked, the other then the
// uniform spacing.
void nodes_of(const std::string &option, const std::string &text, const WallOptions &o, int n, std::vector<double> &x,
              std::vector<double> &y) {
    SidePiece p = piece_of(option, text, o.spline);
    p.distribution.given = true;
    p.distribution.kind = EG2D_DIST_UNIFORM;
    p.distribution.where = p.where;
    curve_nodes(p, n, Constants{}, x, y);
    if (o.inlet_spacing == 0 && o.outlet_spacing == 0) return;
    const double uniform = polyline_length(x, y) / (n - 1);
    p.distribution.kind = EG2D_DIST_VINOKUR;
    p.distribution.p1 = o.inlet_spacing > 0 ? o.inlet_spacing : uniform;
    p.distribution.p2 = o.outlet_spacing > 0 ? o.outlet_spacing : uniform;
    p.distribution.where = Location{"channel: " + option + " with --inlet-spacing, --outlet-spacing", "", 0, 0};
    curve_nodes(p, n, Constants{}, x, y);
}

// The walls either side of a centreline: each node moved by half the width
// along the centreline's normal (its left normal for the upper wall).
Walls offset_walls(const WallOptions &o, int ni) {
    Walls w;
    std::vector<double> cx, cy;
    nodes_of("--centreline", o.centreline, o, ni, cx, cy);
    const Location at{"channel: --width", "", 0, 0};
    const Formula width(o.width, {"s"}, Constants{}, at);
    const double length = polyline_length(cx, cy);
    double along = 0;
    for (std::size_t k = 0; k < cx.size(); ++k) {
        if (k > 0) along += std::hypot(cx[k] - cx[k - 1], cy[k] - cy[k - 1]);
        const std::size_t a = k > 0 ? k - 1 : k, b = k + 1 < cx.size() ? k + 1 : k;
        const double tx = cx[b] - cx[a], ty = cy[b] - cy[a], t = std::hypot(tx, ty);
        const double half = 0.5 * width({along / length});
        if (!(half > 0))
            throw Failure(EXIT_CASE, "channel: --width: \"" + o.width + "\" is " + fmt(2 * half) + " at s = " +
                                         fmt(along / length) + ", not positive");
        if (!(t > 0)) throw Failure(EXIT_GEOMETRY, "channel: --centreline: two nodes coincide at (" + fmt(cx[k]) +
                                                       ", " + fmt(cy[k]) + ")");
        const double nx = -ty / t, ny = tx / t;
        w.lx.push_back(cx[k] - half * nx);
        w.ly.push_back(cy[k] - half * ny);
        w.ux.push_back(cx[k] + half * nx);
        w.uy.push_back(cy[k] + half * ny);
    }
    return w;
}

}  // namespace

double polyline_length(const std::vector<double> &x, const std::vector<double> &y) {
    double length = 0;
    for (std::size_t k = 1; k < x.size(); ++k) length += std::hypot(x[k] - x[k - 1], y[k] - y[k - 1]);
    return length;
}

double centreline_length(const Walls &w) {
    std::vector<double> x, y;
    for (std::size_t k = 0; k < w.lx.size(); ++k) {
        x.push_back(0.5 * (w.lx[k] + w.ux[k]));
        y.push_back(0.5 * (w.ly[k] + w.uy[k]));
    }
    return polyline_length(x, y);
}

Walls channel_walls(const WallOptions &o, int ni) {
    if (!o.centreline.empty()) return offset_walls(o, ni);
    Walls w;
    nodes_of("--lower", o.lower, o, ni, w.lx, w.ly);
    nodes_of("--upper", o.upper, o, ni, w.ux, w.uy);
    return w;
}

}  // namespace eg2dtool
