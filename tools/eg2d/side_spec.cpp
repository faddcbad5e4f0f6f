#include "side_spec.hpp"

#include <eg2d.h>

#include <cerrno>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "failure.hpp"
#include "toml_fields.hpp"

namespace eg2dtool {

namespace {

const std::vector<std::string> piece_keys = {"x", "y", "points", "file", "share"};

std::string point(double x, double y) {
    std::ostringstream s;
    s.precision(10);
    s << "(" << x << ", " << y << ")";
    return s.str();
}

// A two-column text file "x y" per line ('#' starts a comment; commas allowed).
void read_point_file(const std::string &path, const Location &where, std::vector<double> &px,
                     std::vector<double> &py) {
    std::ifstream in(path);
    if (!in) throw Failure(EXIT_IO, where.str() + ": cannot read \"" + path + "\": " + std::strerror(errno));
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        line = line.substr(0, line.find('#'));
        for (char &ch : line)
            if (ch == ',' || ch == '\t' || ch == '\r') ch = ' ';
        std::istringstream s(line);
        double x, y;
        std::string rest;
        if (!(s >> x)) {
            if (line.find_first_not_of(' ') == std::string::npos) continue;  // blank
            throw Failure(EXIT_CASE, path + ":" + std::to_string(number) + ": expected two numbers \"x y\" (file named by " +
                                         where.str() + ")");
        }
        if (!(s >> y) || (s >> rest) || !std::isfinite(x) || !std::isfinite(y))
            throw Failure(EXIT_CASE, path + ":" + std::to_string(number) + ": expected two numbers \"x y\" (file named by " +
                                         where.str() + ")");
        px.push_back(x);
        py.push_back(y);
    }
    if (px.size() < 2) throw Failure(EXIT_CASE, where.str() + ": \"" + path + "\" holds fewer than 2 points");
}

SidePiece parse_piece(const toml::table &table, const Location &where, const std::string &dir,
                      const Constants &constants) {
    Fields f(table, where, piece_keys);
    f.finish();
    SidePiece p;
    p.where = where;
    const int kinds = (f.has("x") || f.has("y")) + f.has("points") + f.has("file");
    if (kinds != 1)
        throw Failure(EXIT_CASE, where.str() + ": give exactly one of: x and y (formulas in s), points, file");
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
    } else {
        std::string path = f.text("file");
        if (!path.empty() && path[0] != '/' && !dir.empty()) path = dir + "/" + path;
        p.points_at = f.at("file");
        read_point_file(path, p.points_at, p.px, p.py);
    }
    if (f.has("share")) {
        p.share = f.number("share", constants);
        if (!(p.share > 0 && p.share < 1)) throw Failure(EXIT_CASE, f.at("share").str() + ": must be in (0, 1)");
    }
    return p;
}

// Sampled length of a piece (to split a side's intervals in proportion when no share is given).
double piece_length(const SidePiece &p, const Formula *fx, const Formula *fy) {
    double len = 0;
    if (fx) {
        double x0 = (*fx)({0.0}), y0 = (*fy)({0.0});
        for (int k = 1; k <= 256; ++k) {
            const double s = k / 256.0, x1 = (*fx)({s}), y1 = (*fy)({s});
            len += std::hypot(x1 - x0, y1 - y0);
            x0 = x1;
            y0 = y1;
        }
    } else {
        for (std::size_t k = 1; k < p.px.size(); ++k) len += std::hypot(p.px[k] - p.px[k - 1], p.py[k] - p.py[k - 1]);
    }
    return len;
}

}  // namespace

const std::vector<std::pair<std::string, int>> &side_names(int topology) {
    static const std::vector<std::pair<std::string, int>> single = {
        {"bottom", EG2D_SIDE_JMIN}, {"right", EG2D_SIDE_IMAX}, {"top", EG2D_SIDE_JMAX}, {"left", EG2D_SIDE_IMIN}};
    static const std::vector<std::pair<std::string, int>> o = {{"inner", EG2D_SIDE_JMIN}, {"outer", EG2D_SIDE_JMAX}};
    return topology == EG2D_TOPO_O ? o : single;
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
    std::vector<Formula> fx, fy;
    std::vector<double> weight(m);
    for (std::size_t k = 0; k < m; ++k) {
        const SidePiece &p = spec.pieces[k];
        if (!p.x.empty()) {
            fx.emplace_back(p.x, std::vector<std::string>{"s"}, constants, p.x_at);
            fy.emplace_back(p.y, std::vector<std::string>{"s"}, constants, p.y_at);
        }
    }
    // Intervals per piece: by share, else by length, rounded cumulatively (as seed 000's
    // listing splits a side: round(nj*k/10)).
    std::size_t f = 0;
    double total = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const SidePiece &p = spec.pieces[k];
        const bool formula = !p.x.empty();
        weight[k] = p.share > 0 ? p.share : piece_length(p, formula ? &fx[f] : nullptr, formula ? &fy[f] : nullptr);
        if (formula) ++f;
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
    f = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const SidePiece &p = spec.pieces[k];
        const int a = cut[k], intervals = cut[k + 1] - cut[k];
        double x0 = 0, y0 = 0;  // the piece's first point, which must meet the previous piece's last
        if (!p.x.empty()) {
            for (int q = 0; q <= intervals; ++q) {
                const double s = static_cast<double>(q) / intervals;
                const double xv = fx[f]({s}), yv = fy[f]({s});
                if (q == 0) {
                    x0 = xv;
                    y0 = yv;
                    if (k > 0) continue;
                }
                x[static_cast<std::size_t>(a + q)] = xv;
                y[static_cast<std::size_t>(a + q)] = yv;
            }
            ++f;
        } else {
            if (static_cast<int>(p.px.size()) != intervals + 1) {
                std::string need = m == 1 ? "this side needs " + std::to_string(n) + " (size " + std::to_string(n) + ")"
                                          : "this piece has " + std::to_string(intervals + 1) + " nodes of the side's " +
                                                std::to_string(n);
                throw Failure(EXIT_CASE, p.points_at.str() + ": " + std::to_string(p.px.size()) + " points given, but " + need);
            }
            x0 = p.px[0];
            y0 = p.py[0];
            for (int q = k > 0 ? 1 : 0; q <= intervals; ++q) {
                x[static_cast<std::size_t>(a + q)] = p.px[static_cast<std::size_t>(q)];
                y[static_cast<std::size_t>(a + q)] = p.py[static_cast<std::size_t>(q)];
            }
        }
        if (k > 0) {
            const double xe = x[static_cast<std::size_t>(a)], ye = y[static_cast<std::size_t>(a)];
            const double scale = std::max({1.0, std::fabs(xe), std::fabs(ye)});
            if (std::hypot(x0 - xe, y0 - ye) > 1e-9 * scale)
                throw Failure(EXIT_CASE, p.where.str() + ": starts at " + point(x0, y0) + " but the previous piece ends at " +
                                             point(xe, ye));
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
