#include "side_spec.hpp"

#include <eg2d.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "failure.hpp"
#include "piece_curve.hpp"
#include "toml_fields.hpp"

namespace eg2dtool {

// A point file through the library's reader (eg2d_read_points: "x y" per line).
void read_point_file(const std::string &path, const Location &where, std::vector<double> &px,
                     std::vector<double> &py) {
    int n = 0;
    int status = eg2d_read_points(path.c_str(), 0, &n, nullptr, nullptr);
    if (status == EG2D_OK) {
        px.resize(static_cast<std::size_t>(n));
        py.resize(px.size());
        status = eg2d_read_points(path.c_str(), n, &n, px.data(), py.data());
    }
    if (status != EG2D_OK) throw Failure(exit_code_for_status(status), where.str() + ": " + eg2d_last_error(nullptr));
    if (px.size() < 2) throw Failure(EXIT_CASE, where.str() + ": \"" + path + "\" holds fewer than 2 points");
}

namespace {

const std::vector<std::string> piece_keys = {"x",        "y",     "points",       "file",    "naca",  "airfoil",
                                             "curve",    "closed_te", "distribution", "reverse", "share",   "sliding"};

std::string point(double x, double y) {
    std::ostringstream s;
    s.precision(10);
    s << "(" << x << ", " << y << ")";
    return s.str();
}

SidePiece parse_piece(const toml::table &table, const Location &where, const std::string &dir,
                      const Constants &constants) {
    Fields f(table, where, piece_keys);
    f.finish();
    SidePiece p;
    p.where = where;
    const int kinds = (f.has("x") || f.has("y")) + f.has("points") + f.has("file") + f.has("naca") + f.has("airfoil");
    if (kinds != 1)
        throw Failure(EXIT_CASE, where.str() + ": give exactly one of: x and y (formulas in s), points, file, naca, airfoil");
    auto relative = [&](std::string path) { return path.empty() || path[0] == '/' || dir.empty() ? path : dir + "/" + path; };
    if (f.has("x") || f.has("y")) {
        p.x = f.text("x");
        p.y = f.text("y");
        p.x_at = f.at("x");
        p.y_at = f.at("y");
    } else if (f.has("points")) {
        const toml::array &a = f.array("points");
        p.points_at = f.at("points");
        for (std::size_t k = 0; k < a.size(); ++k) {
            double x, y;
            read_pair(*a.get(k), locate(where, "points[" + std::to_string(k) + "]", *a.get(k)), constants, x, y);
            p.px.push_back(x);
            p.py.push_back(y);
        }
        if (p.px.size() < 2) throw Failure(EXIT_CASE, p.points_at.str() + ": at least 2 points are needed");
    } else if (f.has("file")) {
        p.points_at = f.at("file");
        read_point_file(relative(f.text("file")), p.points_at, p.px, p.py);
    } else if (f.has("naca")) {
        p.naca = f.text("naca");
        p.closed_te = f.boolean("closed_te", true);
    } else {
        p.airfoil = relative(f.text("airfoil"));
        p.points_at = f.at("airfoil");
    }
    if (f.has("closed_te") && p.naca.empty()) throw Failure(EXIT_CASE, f.at("closed_te").str() + ": belongs to a naca piece");
    if (f.has("curve")) {
        if (p.px.empty()) throw Failure(EXIT_CASE, f.at("curve").str() + ": belongs to a points or file piece");
        p.curve = f.choice("curve", "", {"polyline", "spline"});
    }
    if (f.has("distribution")) p.distribution = parse_distribution(*f.node("distribution"), f.at("distribution"), constants);
    p.reverse = f.boolean("reverse", false);
    p.sliding = f.boolean("sliding", false);
    if (f.has("share")) {
        p.share = f.number("share", constants);
        if (!(p.share > 0 && p.share < 1)) throw Failure(EXIT_CASE, f.at("share").str() + ": must be in (0, 1)");
    }
    return p;
}

// count nodes of one piece: a library curve with a distribution, a formula at equal
// steps of s, or the points themselves (whose number must be `count`).
void piece_nodes(const SidePiece &p, int count, int side_n, bool alone, const Constants &constants,
                 std::vector<double> &x, std::vector<double> &y) {
    if (needs_curve(p)) {
        curve_nodes(p, count, constants, x, y);
    } else if (!p.x.empty()) {
        const Formula fx(p.x, {"s"}, constants, p.x_at), fy(p.y, {"s"}, constants, p.y_at);
        x.resize(static_cast<std::size_t>(count));
        y.resize(x.size());
        for (int q = 0; q < count; ++q) {
            const double s = static_cast<double>(q) / (count - 1);
            x[static_cast<std::size_t>(q)] = fx({s});
            y[static_cast<std::size_t>(q)] = fy({s});
        }
    } else {
        if (static_cast<int>(p.px.size()) != count) {
            const std::string need = alone ? "this side needs " + std::to_string(side_n) + " (size " + std::to_string(side_n) + ")"
                                           : "this piece has " + std::to_string(count) + " nodes of the side's " +
                                                 std::to_string(side_n);
            throw Failure(EXIT_CASE, p.points_at.str() + ": " + std::to_string(p.px.size()) + " points given, but " + need);
        }
        x = p.px;
        y = p.py;
    }
    if (p.reverse) {
        std::reverse(x.begin(), x.end());
        std::reverse(y.begin(), y.end());
    }
}

double polyline_length(const std::vector<double> &x, const std::vector<double> &y) {
    double len = 0;
    for (std::size_t k = 1; k < x.size(); ++k) len += std::hypot(x[k] - x[k - 1], y[k] - y[k - 1]);
    return len;
}

}  // namespace

const std::vector<std::pair<std::string, int>> &side_names(int topology) {
    static const std::vector<std::pair<std::string, int>> single = {
        {"bottom", EG2D_SIDE_JMIN}, {"right", EG2D_SIDE_IMAX}, {"top", EG2D_SIDE_JMAX}, {"left", EG2D_SIDE_IMIN}};
    static const std::vector<std::pair<std::string, int>> o = {{"inner", EG2D_SIDE_JMIN}, {"outer", EG2D_SIDE_JMAX}};
    // C-grid: inner = lower wake, body, upper wake; outer = far field; the outflow lines
    static const std::vector<std::pair<std::string, int>> c = {{"inner", EG2D_SIDE_JMIN},
                                                               {"outflow_upper", EG2D_SIDE_IMAX},
                                                               {"outer", EG2D_SIDE_JMAX},
                                                               {"outflow_lower", EG2D_SIDE_IMIN}};
    return topology == EG2D_TOPO_O ? o : topology == EG2D_TOPO_C ? c : single;
}

SideSpec parse_side(const toml::node &node, int side, const std::string &name, const Location &where,
                    const std::string &dir, const Constants &constants) {
    SideSpec spec;
    spec.side = side;
    spec.name = name;
    spec.where = where;
    if (const toml::table *t = node.as_table()) {
        spec.pieces.push_back(parse_piece(*t, where, dir, constants));
    } else if (const toml::array *a = node.as_array()) {
        if (a->empty()) throw Failure(EXIT_CASE, where.str() + ": an empty list of pieces");
        for (std::size_t k = 0; k < a->size(); ++k) {
            const toml::node &e = *a->get(k);
            Location l = where;
            l.key += "[" + std::to_string(k) + "]";
            l.line = static_cast<int>(e.source().begin.line);
            l.column = static_cast<int>(e.source().begin.column);
            if (!e.is_table()) throw Failure(EXIT_CASE, l.str() + ": expected a table, found " + type_name(e));
            spec.pieces.push_back(parse_piece(*e.as_table(), l, dir, constants));
        }
    } else {
        throw Failure(EXIT_CASE, where.str() + ": expected a table (or an array of tables), found " + type_name(node));
    }
    for (const auto &p : spec.pieces)
        if (p.sliding && spec.pieces.size() > 1)
            throw Failure(EXIT_CASE, p.where.str() + ": sliding needs a side of one piece (the nodes slide along one curve)");
    int shares = 0;
    double total = 0;
    for (const auto &p : spec.pieces)
        if (p.share > 0) ++shares, total += p.share;
    if (shares != 0 && shares != static_cast<int>(spec.pieces.size()))
        throw Failure(EXIT_CASE, where.str() + ": give 'share' on every piece or on none");
    if (shares && std::fabs(total - 1) > 1e-9)
        throw Failure(EXIT_CASE, where.str() + ": the pieces' shares add up to " + std::to_string(total) + ", not 1");
    return spec;
}

void side_nodes(const SideSpec &spec, int n, bool closed, const Constants &constants, std::vector<double> &x,
                std::vector<double> &y) {
    const std::size_t m = spec.pieces.size();
    // Intervals per piece: by share, else by length, rounded cumulatively (as Petrilli's (1989)
    // listing splits a side: round(nj*k/10)).
    std::vector<double> weight(m);
    double total = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const SidePiece &p = spec.pieces[k];
        if (m == 1) {
            weight[k] = 1;
        } else if (p.share > 0) {
            weight[k] = p.share;
        } else if (!p.px.empty() && !needs_curve(p)) {
            weight[k] = polyline_length(p.px, p.py);
        } else {  // the length of the piece's curve, sampled evenly (whatever its own distribution)
            SidePiece even = p;
            if (needs_curve(even)) {
                even.distribution = Distribution{};  // kind 0: EG2D_DIST_UNIFORM
                even.distribution.given = true;
                even.distribution.where = p.where;
            }
            std::vector<double> sx, sy;
            piece_nodes(even, 257, n, false, constants, sx, sy);
            weight[k] = polyline_length(sx, sy);
        }
        total += weight[k];
    }
    std::vector<int> cut(m + 1, 0);
    double acc = 0;
    for (std::size_t k = 0; k < m; ++k) {
        acc += weight[k];
        cut[k + 1] = k + 1 == m ? n - 1 : static_cast<int>(std::lround((n - 1) * acc / total));
        if (cut[k + 1] <= cut[k])
            throw Failure(EXIT_CASE, spec.pieces[k].where.str() + ": gets no interval of the side's " +
                                         std::to_string(n - 1) + " (a larger size or share is needed)");
    }
    x.assign(static_cast<std::size_t>(n), 0);
    y.assign(static_cast<std::size_t>(n), 0);
    for (std::size_t k = 0; k < m; ++k) {
        const SidePiece &p = spec.pieces[k];
        const std::size_t a = static_cast<std::size_t>(cut[k]);
        std::vector<double> px, py;
        piece_nodes(p, cut[k + 1] - cut[k] + 1, n, m == 1, constants, px, py);
        if (k > 0) {  // the piece must start where the previous one ended
            const double xe = x[a], ye = y[a];
            const double scale = std::max({1.0, std::fabs(xe), std::fabs(ye)});
            if (std::hypot(px[0] - xe, py[0] - ye) > 1e-9 * scale)
                throw Failure(EXIT_CASE, p.where.str() + ": starts at " + point(px[0], py[0]) +
                                             " but the previous piece ends at " + point(xe, ye));
        }
        for (std::size_t q = k > 0 ? 1 : 0; q < px.size(); ++q) {
            x[a + q] = px[q];
            y[a + q] = py[q];
        }
    }
    if (closed) {
        const double scale = std::max({1.0, std::fabs(x[0]), std::fabs(y[0])});
        if (std::hypot(x.back() - x[0], y.back() - y[0]) <= 1e-12 * scale) {
            x.back() = x[0];  // cos(2 pi) is 1 only to roundoff: make the closed curve exactly closed
            y.back() = y[0];
        }
    }
}

}  // namespace eg2dtool
