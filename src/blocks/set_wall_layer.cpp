#include "blocks/set_wall_layer.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "base/error.hpp"
#include "base/polyline.hpp"
#include "controls/control.hpp"
#include "generator/generator.hpp"
#include "grid/graded_layer.hpp"

namespace eg2d {

namespace {

// Nodes along a wall over which its lines' scale and turn fade out toward
// an end whose own line is not graded (the single block's corner blend,
// graded_layer.cpp's kCornerBlend, is 8 too).
constexpr int kTurnTaper = 8;

// A boundary line's first cell off a wall more than this factor from the
// wall's height is said (the single block's corner_notes use 2 too).
constexpr double kSidesOff = 2.0;

// Where a walk along a line is: a block's node and the direction it goes.
struct Walker {
    int b, i, j, di, dj;
};

Side exit_side(const Walker &w) {
    return w.di > 0 ? Side::IMax : w.di < 0 ? Side::IMin : w.dj > 0 ? Side::JMax : Side::JMin;
}

// A wall's share of a line's cells: 1 at the wall, a smoothstep down to 0
// at 2R cells, R = kGradedRows or a quarter of the line if shorter, so that
// the two walls of a line leave it room between them (the single block's
// wall_shares, 1 over kGradedRows cells, left none on a bump 65 nodes
// high: all its cells were scaled alike and its first cells 70x too tall).
std::vector<double> fade(int cells, bool lo, bool hi) {
    const double span = 2.0 * std::max(1, std::min(kGradedRows, cells / 4));
    std::vector<double> v(static_cast<std::size_t>(cells), 0.0);
    auto share = [&](int k) {
        const double t = std::min(1.0, k / span);
        return 1.0 - t * t * (3.0 - 2.0 * t);
    };
    for (int k = 0; k < cells; ++k)
        v[static_cast<std::size_t>(k)] = std::max(lo ? share(k) : 0.0, hi ? share(cells - 1 - k) : 0.0);
    return v;
}

// Cells over which the second pass re-grades a line from a wall whose
// first cell the first pass left off its height.
constexpr int kRegradeCells = kGradedRows;
// First cells off by less than this factor are moved out (pitzDaily's, up
// to 5%: re-graded, its rows kinked 14 degrees at the joins), by more than
// kRegradeFull re-graded, between the two mixed.
constexpr double kRegradeFrom = 1.1;
constexpr double kRegradeFull = 2.0;

// Positions p along a line re-graded from its start so that its first cell
// is `scale` times what it was: cell k times scale^w exp(b sin^2(pi t)), t =
// k/(span - 1), w a smoothstep from 1 at t = 0 to 0 at t = 1, b such that
// the span keeps its length. The first cell is scaled, the last as it was,
// the nodes beyond the span stay, every cell keeps its sign, and the layer
// stays graded: moving the nodes by the first cell's error instead left the
// second cell as it was (the two-element airfoil's lines off the main
// element's nose: 1e-4 then 2.2e-5). False (p unchanged) where the span is
// shorter than the scaled first cell.
bool regrade(std::vector<double> &p, double scale, int span) {
    span = std::min(span, static_cast<int>(p.size()) - 1);
    if (span < 2 || !(scale > 0.0)) return false;
    std::vector<double> d(static_cast<std::size_t>(span)), w(d.size()), bump(d.size());
    const double pi = std::acos(-1.0);
    for (int k = 0; k < span; ++k) {
        const double t = k / (span - 1.0);
        d[static_cast<std::size_t>(k)] = p[static_cast<std::size_t>(k + 1)] - p[static_cast<std::size_t>(k)];
        w[static_cast<std::size_t>(k)] = 1.0 - t * t * (3.0 - 2.0 * t);
        bump[static_cast<std::size_t>(k)] = std::pow(std::sin(pi * t), 2);
    }
    const double length = p[static_cast<std::size_t>(span)] - p[0], ls = std::log(scale);
    if (!(length > d[0] * scale + d.back())) return false;
    auto cell = [&](std::size_t k, double b) { return d[k] * std::exp(w[k] * ls + bump[k] * b); };
    double lo = -60.0, hi = 60.0;  // b: the span's length increases with it
    for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
        const double mid = 0.5 * (lo + hi);
        double total = 0.0;
        for (std::size_t k = 0; k < d.size(); ++k) total += cell(k, mid);
        (total < length ? lo : hi) = mid;
    }
    for (std::size_t k = 0; k + 1 < d.size(); ++k) p[k + 1] = p[k] + cell(k, 0.5 * (lo + hi));
    return true;
}

// The first-cell heights block b asks of its sides (none: all -1).
std::array<double, 4> block_heights(const BlockSet &set, int b) {
    const Control *wall = set.block(b)->controls().find(ControlKind::Orthogonality);
    return wall ? wall->wall_heights() : std::array<double, 4>{-1.0, -1.0, -1.0, -1.0};
}

}  // namespace

bool SetWallLayer::asks_walls(const BlockSet &set) {
    for (int b = 0; b < set.size(); ++b)
        for (double h : block_heights(set, b))
            if (h > 0.0) return true;
    return false;
}

SetWallLayer::SetWallLayer(const BlockSet &set, const Composite &c) {
    const int blocks = c.size();
    for (int b = 0; b < blocks; ++b) {
        ni_.push_back(c.shape(b).ni);
        nj_.push_back(c.shape(b).nj);
    }
    // The walls: each block's heights over its wall sides, their joined
    // nodes too (a wake's first cells given node by node grade the lines
    // that leave it, as the two-element airfoil's sides that hold its wakes).
    heights_.resize(static_cast<std::size_t>(blocks));
    for (int b = 0; b < blocks; ++b) {
        const std::array<double, 4> h = block_heights(set, b);
        for (int s = 0; s < 4; ++s)
            if (h[static_cast<std::size_t>(s)] > 0.0) {
                heights_[static_cast<std::size_t>(b)][static_cast<std::size_t>(s)] =
                    wall_node_heights(set.block(b)->grid(), static_cast<Side>(s), h);
                ++walls_;
            }
    }
    if (walls_ == 0) return;
    // The set's nodes: the blocks' nodes, those a join pairs made one.
    std::vector<std::size_t> first(static_cast<std::size_t>(blocks) + 1, 0);
    for (int b = 0; b < blocks; ++b)
        first[static_cast<std::size_t>(b) + 1] =
            first[static_cast<std::size_t>(b)] + static_cast<std::size_t>(ni_[static_cast<std::size_t>(b)]) *
                                                     static_cast<std::size_t>(nj_[static_cast<std::size_t>(b)]);
    std::vector<std::size_t> parent(first.back());
    for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = k;
    auto root = [&](std::size_t k) {
        while (parent[k] != k) k = parent[k] = parent[parent[k]];
        return k;
    };
    auto flat = [&](const SideRange &r, int t) {
        const std::size_t b = static_cast<std::size_t>(r.block);
        return first[b] + side_node(ni_[b], nj_[b], r.side, r.at(t));
    };
    // Where a walk leaving a block through a joined node goes on.
    std::map<std::tuple<int, int, int>, std::tuple<int, int, int>> across;
    for (const Join &jn : set.joins())
        for (int t = 0; t < jn.a.count(); ++t) {
            const std::size_t a = root(flat(jn.a, t)), b = root(flat(jn.b, t));
            parent[std::max(a, b)] = std::min(a, b);
            across[{jn.a.block, static_cast<int>(jn.a.side), jn.a.at(t)}] = {jn.b.block, static_cast<int>(jn.b.side), jn.b.at(t)};
            across[{jn.b.block, static_cast<int>(jn.b.side), jn.b.at(t)}] = {jn.a.block, static_cast<int>(jn.a.side), jn.a.at(t)};
        }
    std::map<std::size_t, int> number;
    ids_.resize(static_cast<std::size_t>(blocks));
    for (int b = 0; b < blocks; ++b) {
        const std::size_t n = first[static_cast<std::size_t>(b) + 1] - first[static_cast<std::size_t>(b)];
        ids_[static_cast<std::size_t>(b)].resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t r = root(first[static_cast<std::size_t>(b)] + k);
            const auto it = number.emplace(r, static_cast<int>(copies_.size())).first;
            if (it->second == static_cast<int>(copies_.size())) copies_.emplace_back();
            const int ni = ni_[static_cast<std::size_t>(b)];
            copies_[static_cast<std::size_t>(it->second)].push_back(
                NodeRef{b, static_cast<int>(k % static_cast<std::size_t>(ni)), static_cast<int>(k / static_cast<std::size_t>(ni))});
            ids_[static_cast<std::size_t>(b)][k] = it->second;
        }
    }
    // One step along a line: within the block, or across the join of the
    // side it leaves by, into the other block's line off that side.
    // Across the join of the side it leaves by, into the other block's line
    // off that side.
    auto cross = [&](Walker &w) {
        const Side s = exit_side(w);
        const int p = s == Side::JMin || s == Side::JMax ? w.i : w.j;
        const auto it = across.find({w.b, static_cast<int>(s), p});
        if (it == across.end()) return false;
        const int b = std::get<0>(it->second);
        const Side t = static_cast<Side>(std::get<1>(it->second));
        const NodeIJ at = side_ij(ni_[static_cast<std::size_t>(b)], nj_[static_cast<std::size_t>(b)], t, std::get<2>(it->second));
        const NodeIJ in = side_ij(ni_[static_cast<std::size_t>(b)], nj_[static_cast<std::size_t>(b)], t, std::get<2>(it->second), 1);
        w = Walker{b, in.i, in.j, in.i - at.i, in.j - at.j};
        return true;
    };
    auto inside = [&](int b, int i, int j) {
        return i >= 0 && j >= 0 && i < ni_[static_cast<std::size_t>(b)] && j < nj_[static_cast<std::size_t>(b)];
    };
    // One step along a line: within the block, across the join of the side
    // it leaves by, or, where that side is not joined there, on in another
    // block that has the node and the node before it on one line (at a
    // step's corner the join's row beyond it carries on the upstream floor,
    // whichever block's row the walk came along).
    auto step = [&](Walker &w) {
        if (inside(w.b, w.i + w.di, w.j + w.dj)) {
            w.i += w.di;
            w.j += w.dj;
            return true;
        }
        if (cross(w)) return true;
        const int here = id(w.b, w.i, w.j), before = id(w.b, w.i - w.di, w.j - w.dj);
        for (const NodeRef &n : copies_[static_cast<std::size_t>(here)]) {
            if (n.b == w.b) continue;
            for (const NodeIJ d : {NodeIJ{1, 0}, NodeIJ{-1, 0}, NodeIJ{0, 1}, NodeIJ{0, -1}}) {
                if (!inside(n.b, n.i - d.i, n.j - d.j) || id(n.b, n.i - d.i, n.j - d.j) != before) continue;
                Walker v{n.b, n.i, n.j, d.i, d.j};
                if (inside(v.b, v.i + v.di, v.j + v.dj)) {
                    v.i += v.di;
                    v.j += v.dj;
                } else if (!cross(v)) {
                    continue;
                }
                w = v;
                return true;
            }
        }
        return false;
    };
    // The set's lines: from each block line not yet walked, back to the
    // line's end, then forward to its other end. A line along a joined
    // side is walked from one of the two blocks (the join's first).
    std::vector<std::array<std::vector<char>, 2>> walked(static_cast<std::size_t>(blocks));
    for (int b = 0; b < blocks; ++b) {
        walked[static_cast<std::size_t>(b)][0].assign(static_cast<std::size_t>(ni_[static_cast<std::size_t>(b)]), 0);
        walked[static_cast<std::size_t>(b)][1].assign(static_cast<std::size_t>(nj_[static_cast<std::size_t>(b)]), 0);
    }
    for (const Join &jn : set.joins()) {
        const std::size_t b = static_cast<std::size_t>(jn.b.block);
        const bool columns = jn.b.side == Side::IMin || jn.b.side == Side::IMax;
        const NodeIJ n = side_ij(ni_[b], nj_[b], jn.b.side, 0);
        walked[b][columns ? 0 : 1][static_cast<std::size_t>(columns ? n.i : n.j)] = 1;
    }
    const std::size_t most = copies_.size() + 1;  // a line longer than the set's nodes is a ring
    for (int b = 0; b < blocks; ++b)
        for (int family = 0; family < 2; ++family)
            for (int l = 0; l < (family == 0 ? ni_[static_cast<std::size_t>(b)] : nj_[static_cast<std::size_t>(b)]); ++l) {
                if (walked[static_cast<std::size_t>(b)][static_cast<std::size_t>(family)][static_cast<std::size_t>(l)]) continue;
                Walker w = family == 0 ? Walker{b, l, 0, 0, -1} : Walker{b, 0, l, -1, 0};
                std::size_t guard = 0;
                while (step(w) && ++guard < most) {
                }
                if (guard >= most) continue;
                w.di = -w.di;
                w.dj = -w.dj;
                std::vector<int> line{id(w.b, w.i, w.j)};
                for (;;) {
                    walked[static_cast<std::size_t>(w.b)][w.di == 0 ? 0 : 1][static_cast<std::size_t>(w.di == 0 ? w.i : w.j)] = 1;
                    if (!step(w) || line.size() > most) break;
                    line.push_back(id(w.b, w.i, w.j));
                }
                if (line.size() <= most && line.size() >= 3) lines_.push_back(std::move(line));
            }
}

// The height block b asks of its side `side` at its node (i, j) (0: the
// node is not on that side, or the side is no wall there).
double SetWallLayer::height_on(int b, Side side, int i, int j) const {
    const std::size_t k = static_cast<std::size_t>(b);
    const std::vector<double> &v = heights_[k][static_cast<std::size_t>(side)];
    if (v.empty()) return 0.0;
    const int p = side == Side::JMin || side == Side::JMax ? i : j;
    const NodeIJ on = side_ij(ni_[k], nj_[k], side, p);
    return on.i == i && on.j == j && v[static_cast<std::size_t>(p)] > 0.0 ? v[static_cast<std::size_t>(p)] : 0.0;
}

// The first cell asked where a line leaves node `at` toward node `next`:
// the least height of a wall side through `at` whose block's line off the
// side is that line (0: none).
double SetWallLayer::height_leaving(const Composite &c, int at, int next, WallAt &wall) const {
    double h = 0.0;
    for (const NodeRef &n : copies_[static_cast<std::size_t>(at)]) {
        const std::size_t b = static_cast<std::size_t>(n.b);
        for (int s = 0; s < 4; ++s) {
            const Side side = static_cast<Side>(s);
            const double hs = height_on(n.b, side, n.i, n.j);
            if (!(hs > 0.0)) continue;
            const bool along_i = side == Side::JMin || side == Side::JMax;
            const int p = along_i ? n.i : n.j;
            const NodeIJ in = side_ij(ni_[b], nj_[b], side, p, 1);
            if (id(n.b, in.i, in.j) != next) continue;
            if (h > 0.0 && h <= hs) continue;
            h = hs;
            // The normal: perpendicular to the side's central difference
            // (one-sided at its ends), toward the node one line in.
            const int length = along_i ? ni_[b] : nj_[b];
            const NodeIJ lo = side_ij(ni_[b], nj_[b], side, std::max(0, p - 1));
            const NodeIJ hi = side_ij(ni_[b], nj_[b], side, std::min(length - 1, p + 1));
            const Vec2 a = c.point(n.b, lo.i, lo.j), z = c.point(n.b, hi.i, hi.j), o = c.point(n.b, n.i, n.j);
            const Vec2 inward = c.point(n.b, in.i, in.j);
            const double tx = z.x - a.x, ty = z.y - a.y, t = std::hypot(tx, ty);
            Vec2 normal{-ty / t, tx / t};
            if (normal.x * (inward.x - o.x) + normal.y * (inward.y - o.y) < 0.0) normal = Vec2{-normal.x, -normal.y};
            wall = WallAt{n.b, side, p, normal};
        }
    }
    return h;
}

std::vector<SetWallLayer::Stretch> SetWallLayer::stretches(const Composite &c, bool vertices) const {
    std::vector<Stretch> out;
    auto held = [&](int id) {
        const NodeRef &n = copies_[static_cast<std::size_t>(id)][0];
        return !c.moves(n.b, n.i, n.j, vertices);
    };
    // A line also ends where it crosses a join (a joined node between two
    // that are not): each block grades its own stretch, as blockMesh's
    // gradings do. Graded through, a pitzDaily column moved its node on the
    // join under the step's corner 7.5 mm (its floor's first cell scaled by
    // 3), and the join's row folded against the corner, which is held.
    auto joined = [&](int id) { return copies_[static_cast<std::size_t>(id)].size() > 1; };
    auto ends = [&](const std::vector<int> &line, std::size_t k) {
        if (held(line[k])) return true;
        return k > 0 && k + 1 < line.size() && joined(line[k]) && (!joined(line[k - 1]) || !joined(line[k + 1]));
    };
    for (const std::vector<int> &line : lines_) {
        std::size_t a = 0;
        while (a < line.size() && !ends(line, a)) ++a;
        for (std::size_t z = a + 1; z < line.size(); ++z) {
            if (!ends(line, z)) continue;
            if (z - a >= 2) {
                Stretch s;
                s.ids.assign(line.begin() + static_cast<std::ptrdiff_t>(a), line.begin() + static_cast<std::ptrdiff_t>(z) + 1);
                // A stretch that carries on a held line through its held
                // end (the join's row beyond a step's corner, after the
                // upstream floor) leaves no wall there: its cells follow
                // the blocks' sides. Graded and turned off the step's face,
                // that row bent against the rows above it, which leave no
                // wall (pitzDaily: controls up to 4.7, and the run diverged).
                s.first = a > 0 && held(line[a - 1]) ? 0.0 : height_leaving(c, line[a], line[a + 1], s.first_wall);
                s.last = z + 1 < line.size() && held(line[z + 1]) ? 0.0 : height_leaving(c, line[z], line[z - 1], s.last_wall);
                if (s.first > 0.0 || s.last > 0.0) out.push_back(std::move(s));
            }
            a = z;
        }
    }
    return out;
}

void SetWallLayer::respace(Composite &c, bool vertices) const {
    const std::vector<Stretch> all = stretches(c, vertices);
    const Graded graded = graded_starts(all);
    for (const Stretch &s : all) {
        std::vector<Vec2> points;
        for (int id : s.ids) {
            const NodeRef &n = copies_[static_cast<std::size_t>(id)][0];
            points.push_back(c.point(n.b, n.i, n.j));
        }
        const std::vector<double> arc = arc_lengths(points);
        const int cells = static_cast<int>(points.size()) - 1;
        if (!vertices) {  // the second pass
            move_along(c, s, points, arc, corrected(s, arc, graded, c));
            continue;
        }
        std::vector<double> mixed(static_cast<std::size_t>(cells));
        for (std::size_t q = 0; q < mixed.size(); ++q) mixed[q] = arc[q + 1] - arc[q];
        if (!(mixed.front() > 0.0) || !(mixed.back() > 0.0)) continue;
        // Each wall's first cell scaled to its height, the scale fading out
        // (fade): the line keeps the shape its blocks' sides gave it (a set's lines run between sides the solve
        // holds; a target of the layer's own, geometric, beside a side
        // spaced otherwise sheared the cells at a step's face by 80
        // degrees).
        const std::vector<double> lo = fade(cells, s.first > 0.0, false), hi = fade(cells, false, s.last > 0.0);
        const double a = s.first > 0.0 ? taper(c, s.first_wall, graded) * std::log(s.first / mixed.front()) : 0.0;
        const double z = s.last > 0.0 ? taper(c, s.last_wall, graded) * std::log(s.last / mixed.back()) : 0.0;
        std::vector<double> share(mixed.size());
        for (std::size_t q = 0; q < mixed.size(); ++q) {
            mixed[q] *= std::exp(lo[q] * a + hi[q] * z);
            share[q] = std::max(lo[q], hi[q]);
        }
        mixed = fit_length(std::move(mixed), share, arc.back());
        std::vector<double> want(points.size(), 0.0);
        for (std::size_t k = 1; k < want.size(); ++k) want[k] = want[k - 1] + mixed[k - 1];
        want.back() = arc.back();
        move_along(c, s, points, arc, want);
    }
    c.sync();
}

// The second pass's correction (Stretch: after the first pass, the first
// cells off their heights by what that solve left, a few per cent on
// pitzDaily, up to 4.6 times where lines meet held joins). A first cell
// less than kRegradeFrom off: the node one in moved along the line by the
// error, those beyond by that times the wall's fade, so no node moves
// further than the error (scaling the whole line instead, as the first
// pass does, moved pitzDaily's join column 0.5 mm for a first cell 0.1 mm
// off, and the rows kinked there by 13 degrees). More than kRegradeFull
// off: the cells within kRegradeCells of the wall re-graded (regrade), no
// node beyond them moved. Between, the two mixed; a line too short to
// re-grade is moved.
std::vector<double> SetWallLayer::corrected(const Stretch &s, const std::vector<double> &arc, const Graded &graded,
                                            const Composite &c) const {
    const int cells = static_cast<int>(arc.size()) - 1;
    const std::vector<double> fading = fade(cells, true, false);
    const int span = std::min(kRegradeCells, cells / (s.first > 0.0 && s.last > 0.0 ? 2 : 1));
    // Positions p from a wall end (increasing), its first cell brought to
    // `height` (tapered): moved alone below kRegradeFrom, re-graded alone
    // from kRegradeFull, the two mixed between, so that neighbouring lines a
    // little off alike are moved alike.
    auto from_wall = [&](const std::vector<double> &p, double height, const WallAt &wall) {
        const double first = p[1] - p[0], scale = std::pow(height / first, taper(c, wall, graded));
        const double error = first * (1.0 - scale);
        std::vector<double> moved = p, graded_p = p;
        for (int k = 1; k < cells; ++k) moved[static_cast<std::size_t>(k)] -= error * fading[static_cast<std::size_t>(k - 1)];
        const double t = std::clamp((std::abs(std::log(scale)) - std::log(kRegradeFrom)) /
                                        (std::log(kRegradeFull) - std::log(kRegradeFrom)), 0.0, 1.0);
        const double m = t * t * (3.0 - 2.0 * t);
        if (m == 0.0 || !regrade(graded_p, scale, span)) return moved;
        for (std::size_t k = 0; k < moved.size(); ++k) moved[k] = (1.0 - m) * moved[k] + m * graded_p[k];
        return moved;
    };
    std::vector<double> want = arc;
    if (s.first > 0.0) want = from_wall(want, s.first, s.first_wall);
    if (s.last > 0.0) {
        // The line from its far end: reversed and negated, corrected from its start.
        std::vector<double> back(want.rbegin(), want.rend());
        for (double &v : back) v = -v;
        back = from_wall(back, s.last, s.last_wall);
        for (std::size_t k = 0; k < back.size(); ++k) want[want.size() - 1 - k] = -back[k];
    }
    return want;
}

// Stretch s's inner nodes to arc lengths `want` along its polyline (points,
// arc), every copy with them.
void SetWallLayer::move_along(Composite &c, const Stretch &s, const std::vector<Vec2> &points,
                              const std::vector<double> &arc, const std::vector<double> &want) const {
    const std::vector<Vec2> p = points_along(points, arc, want);
    for (std::size_t k = 1; k + 1 < p.size(); ++k)
        for (const NodeRef &n : copies_[static_cast<std::size_t>(s.ids[k])]) c.put(n.b, n.i, n.j, p[k]);
}

SetWallLayer::Graded SetWallLayer::graded_starts(const std::vector<Stretch> &all) {
    Graded g;
    for (const Stretch &s : all) {
        if (s.first > 0.0) g.insert({s.ids[0], s.ids[1]});
        if (s.last > 0.0) g.insert({s.ids.back(), s.ids[s.ids.size() - 2]});
    }
    return g;
}

// Toward an end of its wall whose own line the solve moves but is not
// graded (the join's row that carries on a floor past a step's corner), a line is
// scaled and turned less: fully from kTurnTaper nodes off, a smoothstep
// down to not at all at the end. Scaled and turned alike up to it, the
// step's face's rows sheared against the join's row above them (pitzDaily:
// controls of 1.6 along it, and multigrid diverged).
// `turning`: the turn fades out so too toward an end where another wall of
// the block meets it: the lines beside that wall keep its first cells,
// which a line turned to this wall's normal would move (the walled step's
// floor, its first cells node by node rising 2.4% a node off the face:
// the face's rows turned level over 60 cells held them 24% low).
double SetWallLayer::taper(const Composite &c, const WallAt &w, const Graded &graded, bool turning) const {
    const std::size_t b = static_cast<std::size_t>(w.b);
    const int length = w.side == Side::JMin || w.side == Side::JMax ? ni_[b] : nj_[b];
    double f = 1.0;
    for (int e : {0, length - 1}) {
        const NodeIJ on = side_ij(ni_[b], nj_[b], w.side, e), in = side_ij(ni_[b], nj_[b], w.side, e, 1);
        // (a held side is no line the solve moves: kept_sides says how far
        // it is from the layer)
        const bool ungraded =
            !graded.count({id(w.b, on.i, on.j), id(w.b, in.i, in.j)}) && c.moves(w.b, in.i, in.j, true);
        bool wall = false;  // the node one in from the corner is on another wall of the block
        for (int s = 0; turning && s < 4 && !wall; ++s)
            wall = static_cast<Side>(s) != w.side && height_on(w.b, static_cast<Side>(s), in.i, in.j) > 0.0;
        if (!ungraded && !wall) continue;
        const double t = std::min(1.0, std::abs(w.p - e) / static_cast<double>(kTurnTaper));
        f = std::min(f, t * t * (3.0 - 2.0 * t));
    }
    return f;
}

void SetWallLayer::turn_to_normals(Composite &c) const {
    const std::vector<Stretch> all = stretches(c, false);
    const Graded graded = graded_starts(all);
    for (const Stretch &s : all) {
        const int cells = static_cast<int>(s.ids.size()) - 1;
        auto at = [&](std::size_t k) {
            const NodeRef &n = copies_[static_cast<std::size_t>(s.ids[k])][0];
            return c.point(n.b, n.i, n.j);
        };
        std::vector<Vec2> p(s.ids.size());
        for (std::size_t k = 0; k < p.size(); ++k) p[k] = at(k);
        const std::vector<double> arc = arc_lengths(p);
        std::vector<Vec2> q = p;
        for (int end = 0; end < 2; ++end) {
            const double h = end == 0 ? s.first : s.last;
            if (!(h > 0.0)) continue;
            const WallAt &wall = end == 0 ? s.first_wall : s.last_wall;
            const Vec2 n = wall.normal;
            const double lateral = taper(c, wall, graded, true);
            const std::vector<double> w = fade(cells, end == 0, end == 1);
            const Vec2 o = end == 0 ? p.front() : p.back();
            for (int k = 1; k < cells; ++k) {
                const std::size_t m = static_cast<std::size_t>(k);
                const double share = lateral * (end == 0 ? w[m] : w[m - 1]), d = end == 0 ? arc[m] : arc.back() - arc[m];
                if (share <= 0.0) continue;
                q[m].x += share * (o.x + n.x * d - p[m].x);
                q[m].y += share * (o.y + n.y * d - p[m].y);
            }
        }
        for (std::size_t k = 1; k + 1 < q.size(); ++k)
            for (const NodeRef &n : copies_[static_cast<std::size_t>(s.ids[k])]) c.put(n.b, n.i, n.j, q[k]);
    }
    c.sync();
}

std::string SetWallLayer::kept_sides(const Composite &c) const {
    int count = 0;
    double worst = 1.0, cell = 0.0, height = 0.0;
    NodeRef where{0, 0, 0};
    auto held = [&](int id) {
        const NodeRef &n = copies_[static_cast<std::size_t>(id)][0];
        return !c.moves(n.b, n.i, n.j, true);
    };
    for (const std::vector<int> &line : lines_)
        for (int end = 0; end < 2; ++end) {
            const int at = end == 0 ? line.front() : line.back(), next = line[end == 0 ? 1 : line.size() - 2];
            if (!held(at) || !held(next)) continue;
            WallAt wall;
            const double h = height_leaving(c, at, next, wall);
            if (!(h > 0.0)) continue;
            const NodeRef &a = copies_[static_cast<std::size_t>(at)][0], &b = copies_[static_cast<std::size_t>(next)][0];
            const Vec2 p = c.point(a.b, a.i, a.j), q = c.point(b.b, b.i, b.j);
            const double d = std::hypot(q.x - p.x, q.y - p.y), off = std::max(d / h, h / d);
            if (!(off > kSidesOff)) continue;
            ++count;
            if (off > worst) {
                worst = off;
                cell = d;
                height = h;
                where = a;
            }
        }
    if (count == 0) return "";
    return format("wall layer (graded, set of blocks): %d line(s) of the boundary leave a wall with a first cell more "
                  "than %g times off its height, the worst from block %d's node (%d, %d): %.3g where the wall asks "
                  "%.3g; the set keeps the boundary's points and the lines beside them follow them: space those "
                  "sides for the wall", count, kSidesOff, where.b, where.i, where.j, cell, height);
}

SetLayerFigures SetWallLayer::measure(const Composite &c) const {
    SetLayerFigures f;
    for (const Stretch &s : stretches(c, false)) {
        std::vector<double> cells;
        for (std::size_t k = 0; k + 1 < s.ids.size(); ++k) {
            const NodeRef &a = copies_[static_cast<std::size_t>(s.ids[k])][0], &b = copies_[static_cast<std::size_t>(s.ids[k + 1])][0];
            const Vec2 p = c.point(a.b, a.i, a.j), q = c.point(b.b, b.i, b.j);
            cells.push_back(std::hypot(q.x - p.x, q.y - p.y));
        }
        ++f.lines;
        f.growth = std::max(f.growth, graded_end_growth(cells, s.first > 0.0, s.last > 0.0));
        if (s.first > 0.0) f.first_off = std::max(f.first_off, std::fabs(cells.front() / s.first - 1.0));
        if (s.last > 0.0) f.first_off = std::max(f.first_off, std::fabs(cells.back() / s.last - 1.0));
    }
    return f;
}

}  // namespace eg2d
