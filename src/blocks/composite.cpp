#include "blocks/composite.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "base/error.hpp"
#include "generator/generator.hpp"

namespace eg2d {

Level Composite::Block::level() const {
    Level L;
    L.conn = &conn;
    L.x = const_cast<double *>(x.data());  // the kernels that only read take a const Composite
    L.y = const_cast<double *>(y.data());
    if (!fx.empty()) {
        L.fx = fx.data();
        L.fy = fy.data();
    }
    if (!controls.empty()) L.controls = &controls;
    return L;
}

Composite::Composite(const std::vector<BlockShape> &shapes, const std::vector<Join> &joins)
    : joins_(joins) {
    blocks_.reserve(shapes.size());
    for (const BlockShape &sh : shapes) {
        Block blk{sh.ni, sh.nj, Connectivity(sh.ni + 2, sh.nj + 2, Topology::Single), {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
        const std::size_t n = static_cast<std::size_t>(sh.ni + 2) * static_cast<std::size_t>(sh.nj + 2);
        for (auto *v : {&blk.x, &blk.y, &blk.rx, &blk.ry}) v->assign(n, 0.0);
        blk.role.assign(n, kHeld);
        for (int j = 1; j < sh.nj - 1; ++j)
            for (int i = 1; i < sh.ni - 1; ++i) blk.role[blk.at(i, j)] = kUnknown;
        blocks_.push_back(std::move(blk));
    }
    for (const Join &j : joins) {
        Block &A = blocks_[static_cast<std::size_t>(j.a.block)];
        Block &B = blocks_[static_cast<std::size_t>(j.b.block)];
        if (j.a.block == j.b.block) A.self_joined = true;
        auto node = [](const Block &blk, const SideRange &r, int t, int depth) {
            const NodeIJ n = side_ij(blk.ni, blk.nj, r.side, r.at(t), depth);
            return blk.at(n.i, n.j);
        };
        const int count = j.a.count();
        for (int t = 0; t < count; ++t) {
            // The halo one line beyond each side holds the node one line into the other block.
            halos_.push_back(Link{j.b.block, node(B, j.b, t, 1), j.a.block, node(A, j.a, t, -1)});
            halos_.push_back(Link{j.a.block, node(A, j.a, t, 1), j.b.block, node(B, j.b, t, -1)});
            A.role[node(A, j.a, t, -1)] = kHalo;
            B.role[node(B, j.b, t, -1)] = kHalo;
            if (t == 0 || t == count - 1 || j.held) continue;  // a vertex, a held join: held
            A.role[node(A, j.a, t, 0)] = kUnknown;
            B.role[node(B, j.b, t, 0)] = kCopy;
            copies_.push_back(Link{j.a.block, node(A, j.a, t, 0), j.b.block, node(B, j.b, t, 0)});
        }
    }
    find_vertices();
    for (Block &blk : blocks_) {
        unknowns_ += std::count(blk.role.begin(), blk.role.end(), kUnknown);
        std::vector<char> held(blk.role.size());
        for (std::size_t k = 0; k < held.size(); ++k) held[k] = blk.role[k] != kUnknown;
        blk.conn = blk.conn.with_fixed_nodes(held);
    }
}

void Composite::find_vertices() {
    using Key = std::pair<int, std::size_t>;
    std::map<Key, int> group_of;
    std::vector<int> parent;
    auto id = [&](int b, std::size_t k) {
        const auto it = group_of.find({b, k});
        if (it != group_of.end()) return it->second;
        const int g = static_cast<int>(parent.size());
        group_of[{b, k}] = g;
        parent.push_back(g);
        return g;
    };
    auto root = [&](int g) {
        while (parent[static_cast<std::size_t>(g)] != g) g = parent[static_cast<std::size_t>(g)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(g)])];
        return g;
    };
    // Which side edges are joined (per block, side, edge q: nodes q..q+1), and the join ends grouped.
    std::vector<std::array<std::vector<char>, 4>> joined(blocks_.size());
    for (std::size_t b = 0; b < blocks_.size(); ++b)
        for (int s = 0; s < 4; ++s)
            joined[b][static_cast<std::size_t>(s)].assign(static_cast<std::size_t>(s % 2 == 0 ? blocks_[b].ni : blocks_[b].nj), 0);
    for (const Join &j : joins_) {
        const int count = j.a.count();
        for (int t : {0, count - 1}) {
            const Block &A = blocks_[static_cast<std::size_t>(j.a.block)], &B = blocks_[static_cast<std::size_t>(j.b.block)];
            const NodeIJ na = side_ij(A.ni, A.nj, j.a.side, j.a.at(t)), nb = side_ij(B.ni, B.nj, j.b.side, j.b.at(t));
            const int ga = root(id(j.a.block, A.at(na.i, na.j))), gb = root(id(j.b.block, B.at(nb.i, nb.j)));
            parent[static_cast<std::size_t>(std::max(ga, gb))] = std::min(ga, gb);
        }
        for (int t = 0; t + 1 < count && !j.held; ++t)  // (a held join bounds its vertices as a boundary does)
            for (const SideRange *r : {&j.a, &j.b})
                joined[static_cast<std::size_t>(r->block)][static_cast<std::size_t>(r->side)]
                      [static_cast<std::size_t>(std::min(r->at(t), r->at(t + 1)))] = 1;
    }
    std::map<int, Vertex> groups;
    for (const auto &kv : group_of) groups[root(kv.second)].copies.push_back(Node{kv.first.first, kv.first.second});
    // The node that stands for (b, k): a copy's source, a vertex's first copy, or itself.
    std::map<Key, Key> canonical;
    for (const Link &l : copies_) canonical[{l.to, l.dst}] = {l.from, l.src};
    for (const auto &kv : groups)
        for (const Node &n : kv.second.copies) canonical[{n.block, n.k}] = {kv.second.copies[0].block, kv.second.copies[0].k};
    for (auto &kv : groups) {
        Vertex &v = kv.second;
        bool free = true;
        for (const Node &n : v.copies) {
            const Block &blk = blocks_[static_cast<std::size_t>(n.block)];
            const int i = static_cast<int>(n.k % static_cast<std::size_t>(blk.ni + 2)) - 1;
            const int j = static_cast<int>(n.k / static_cast<std::size_t>(blk.ni + 2)) - 1;
            const struct { bool on; Side side; int p, length; } sides[] = {
                {j == 0, Side::JMin, i, blk.ni}, {i == blk.ni - 1, Side::IMax, j, blk.nj},
                {j == blk.nj - 1, Side::JMax, i, blk.ni}, {i == 0, Side::IMin, j, blk.nj}};
            for (const auto &sd : sides) {
                if (!sd.on) continue;
                const std::vector<char> &e = joined[static_cast<std::size_t>(n.block)][static_cast<std::size_t>(sd.side)];
                for (int q : {sd.p - 1, sd.p})
                    if (q >= 0 && q < sd.length - 1 && !e[static_cast<std::size_t>(q)]) free = false;
            }
            if (!free) break;
            for (const NodeIJ d : {NodeIJ{1, 0}, NodeIJ{-1, 0}, NodeIJ{0, 1}, NodeIJ{0, -1}}) {
                const int ii = i + d.i, jj = j + d.j;
                if (ii < 0 || jj < 0 || ii >= blk.ni || jj >= blk.nj) continue;
                Key key{n.block, blk.at(ii, jj)};
                const auto c = canonical.find(key);
                if (c != canonical.end()) key = c->second;
                const Node m{key.first, key.second};
                if (std::none_of(v.neighbours.begin(), v.neighbours.end(),
                                 [&](const Node &o) { return o.block == m.block && o.k == m.k; }))
                    v.neighbours.push_back(m);
            }
        }
        if (free && v.neighbours.size() >= 3) vertices_.push_back(std::move(v));
        else held_vertices_.push_back(std::move(v));
    }
}

void Composite::vertex_equation(const Vertex &v, double &rx, double &ry) const {
    double mx = 0.0, my = 0.0;
    for (const Node &n : v.neighbours) {
        mx += blocks_[static_cast<std::size_t>(n.block)].x[n.k];
        my += blocks_[static_cast<std::size_t>(n.block)].y[n.k];
    }
    const double count = static_cast<double>(v.neighbours.size());
    const Node &c = v.copies[0];
    rx = mx / count - blocks_[static_cast<std::size_t>(c.block)].x[c.k] - v.fx;
    ry = my / count - blocks_[static_cast<std::size_t>(c.block)].y[c.k] - v.fy;
}

namespace {
constexpr int kLocalSweeps = 4, kLocalRadius = 3;
}

void Composite::relax_vertices(System system) {
    if (vertices_.empty() && held_vertices_.empty()) return;
    for (int sweep = 0; sweep < kLocalSweeps; ++sweep) {
        for (std::size_t k = 0; k < vertices_.size() + held_vertices_.size(); ++k) {
            const bool held = k >= vertices_.size();
            const Vertex &v = held ? held_vertices_[k - vertices_.size()] : vertices_[k];
            for (const Node &n : v.copies) {
                Block &blk = blocks_[static_cast<std::size_t>(n.block)];
                const Level L = blk.level();
                const int ci = static_cast<int>(n.k % static_cast<std::size_t>(blk.ni + 2));
                const int cj = static_cast<int>(n.k / static_cast<std::size_t>(blk.ni + 2));
                blk.each_unknown([&](const Stencil &st) { blk.relax(system, L, st, 1.0); }, std::max(1, ci - kLocalRadius),
                                 std::min(blk.ni, ci + kLocalRadius), std::max(1, cj - kLocalRadius),
                                 std::min(blk.nj, cj + kLocalRadius));
                sync_from(static_cast<std::size_t>(n.block));  // the other blocks see the change
            }
            if (held) continue;
            double rx, ry;
            vertex_equation(v, rx, ry);
            for (const Node &n : v.copies) {
                blocks_[static_cast<std::size_t>(n.block)].x[n.k] += rx;
                blocks_[static_cast<std::size_t>(n.block)].y[n.k] += ry;
            }
        }
        for (const Link &l : halos_) copy(l, &Block::x), copy(l, &Block::y);
    }
}

double Composite::vertex_residual() const {
    double worst = 0.0;
    for (const Vertex &v : vertices_) {
        double rx, ry;
        vertex_equation(v, rx, ry);
        worst = std::max({worst, std::fabs(rx), std::fabs(ry)});
    }
    return worst;
}

Composite Composite::of(const BlockSet &set) {
    std::vector<BlockShape> shapes;
    for (int b = 0; b < set.size(); ++b) shapes.push_back({set.block(b)->grid().ni(), set.block(b)->grid().nj()});
    Composite c(shapes, set.joins());
    for (int b = 0; b < set.size(); ++b) {
        const Grid &g = set.block(b)->grid();
        Block &blk = c.blocks_[static_cast<std::size_t>(b)];
        for (int j = 0; j < g.nj(); ++j)
            for (int i = 0; i < g.ni(); ++i) {
                blk.x[blk.at(i, j)] = g.x[node_index(g.ni(), i, j)];
                blk.y[blk.at(i, j)] = g.y[node_index(g.ni(), i, j)];
            }
        ControlSet &controls = set.block(b)->controls();
        if (controls.empty()) continue;
        const ControlFields &fields = controls.update(g, true);
        for (int t = 0; t < kTermCount; ++t) {
            const double *f = fields.data(static_cast<Term>(t));
            if (!f) continue;
            std::vector<double> &e = blk.controls.at(static_cast<Term>(t), blk.x.size());
            for (int j = 0; j < g.nj(); ++j)
                for (int i = 0; i < g.ni(); ++i) e[blk.at(i, j)] = f[node_index(g.ni(), i, j)];
        }
    }
    for (Block &blk : c.blocks_) blk.given = blk.controls;
    // A joined node a block solves but computed no control at (its
    // boundary, to the control): the block's terms one line in.
    for (const Join &j : set.joins()) {
        Block &blk = c.blocks_[static_cast<std::size_t>(j.a.block)];
        if (blk.controls.empty()) continue;
        for (int t = 1; t + 1 < j.a.count(); ++t) {
            const NodeIJ n0 = side_ij(blk.ni, blk.nj, j.a.side, j.a.at(t)), n1 = side_ij(blk.ni, blk.nj, j.a.side, j.a.at(t), 1);
            const std::size_t k0 = blk.at(n0.i, n0.j), k1 = blk.at(n1.i, n1.j);
            bool none = true;
            for (const std::vector<double> &v : blk.controls.term)
                if (!v.empty() && v[k0] != 0.0) none = false;
            if (none)
                for (std::vector<double> &v : blk.controls.term)
                    if (!v.empty()) v[k0] = v[k1];
        }
    }
    c.sync();
    return c;
}

bool Composite::moves(int b, int i, int j, bool vertices) const {
    const Block &blk = blocks_[static_cast<std::size_t>(b)];
    const std::size_t k = blk.at(i, j);
    if (blk.role[k] == kUnknown || blk.role[k] == kCopy) return true;
    if (vertices)
        for (const Vertex &v : vertices_)
            for (const Node &n : v.copies)
                if (n.block == b && n.k == k) return true;
    return false;
}

void Composite::hold_vertices(bool hold) {
    for (Vertex &v : vertices_) {
        v.fx = v.fy = 0.0;
        if (!hold) continue;
        double rx, ry;
        vertex_equation(v, rx, ry);
        v.fx = rx;
        v.fy = ry;
    }
}

void Composite::hold_spacing(System system, bool exact) {
    for (Block &blk : blocks_) {
        ControlFields f = blk.given;
        std::vector<double> &phi = f.at(Term::AXi, blk.x.size()), &psi = f.at(Term::CEta, blk.x.size());
        Level L = blk.level();
        L.controls = &f;
        blk.each_unknown([&](const Stencil &s) {
            const std::size_t c = static_cast<std::size_t>(s.c);
            if (!exact) {
                auto d = [&](std::ptrdiff_t a, std::ptrdiff_t b) {
                    return std::hypot(blk.x[static_cast<std::size_t>(b)] - blk.x[static_cast<std::size_t>(a)],
                                      blk.y[static_cast<std::size_t>(b)] - blk.y[static_cast<std::size_t>(a)]);
                };
                const double back = d(s.w, s.c), ahead = d(s.c, s.e), below = d(s.s, s.c), above = d(s.c, s.n);
                phi[c] += -2.0 * (ahead - back) / (ahead + back);
                psi[c] += -2.0 * (above - below) / (above + below);
                return;
            }
            const double phi0 = phi[c], psi0 = psi[c];
            const NodeEquation e0 = node_equation(system, L, s);
            phi[c] = phi0 + 1.0;
            const NodeEquation e1 = node_equation(system, L, s);
            phi[c] = phi0;
            psi[c] = psi0 + 1.0;
            const NodeEquation e2 = node_equation(system, L, s);
            // [e1 - e0, e2 - e0] (dphi, dpsi) = -e0, by Cramer's rule
            // (its determinant a multiple of the Jacobian: nonzero unfolded).
            const double ax = e1.rx - e0.rx, ay = e1.ry - e0.ry, bx = e2.rx - e0.rx, by = e2.ry - e0.ry;
            const double det = ax * by - ay * bx;
            if (!(std::fabs(det) > 0.0)) {
                psi[c] = psi0;
                return;
            }
            phi[c] = phi0 + (-e0.rx * by + e0.ry * bx) / det;
            psi[c] = psi0 + (-ax * e0.ry + ay * e0.rx) / det;
        });
        blk.controls = std::move(f);
    }
}

double Composite::largest_skew() const {
    double worst = 0.0;
    for (const Block &blk : blocks_)
        for (int j = 0; j + 1 < blk.nj; ++j)
            for (int i = 0; i + 1 < blk.ni; ++i) {
                const std::size_t k[4] = {blk.at(i, j), blk.at(i + 1, j), blk.at(i + 1, j + 1), blk.at(i, j + 1)};
                for (int m = 0; m < 4; ++m) {
                    const std::size_t o = k[m], a = k[(m + 1) % 4], b = k[(m + 3) % 4];
                    const double ax = blk.x[a] - blk.x[o], ay = blk.y[a] - blk.y[o];
                    const double bx = blk.x[b] - blk.x[o], by = blk.y[b] - blk.y[o];
                    // the corner's angle, signed as the cell turns (a folded corner beyond 180)
                    const double angle = std::atan2(ax * by - ay * bx, ax * bx + ay * by) * 180.0 / M_PI;
                    worst = std::max(worst, std::fabs(std::fabs(angle) - 90.0));
                }
            }
    return worst;
}

long Composite::folded_cells() const {
    long folded = 0;
    for (const Block &blk : blocks_) {
        long positive = 0, other = 0;
        for (int j = 0; j + 1 < blk.nj; ++j)
            for (int i = 0; i + 1 < blk.ni; ++i) {
                const std::size_t a = blk.at(i, j), b = blk.at(i + 1, j), c = blk.at(i + 1, j + 1), d = blk.at(i, j + 1);
                const double area = (blk.x[c] - blk.x[a]) * (blk.y[d] - blk.y[b]) - (blk.y[c] - blk.y[a]) * (blk.x[d] - blk.x[b]);
                (area > 0.0 ? positive : other) += 1;
            }
        folded += std::min(positive, other);
    }
    return folded;
}

double Composite::stretching() const {
    double worst = 0.0;
    for (const Block &blk : blocks_)
        for (Term t : {Term::AXi, Term::CEta})
            if (const double *v = blk.controls.data(t))
                blk.each_unknown([&](const Stencil &s) { worst = std::max(worst, std::fabs(v[s.c])); });
    return worst;
}

long Composite::clip_stretching(double limit) {
    long clipped = 0;
    for (Block &blk : blocks_)
        for (Term t : {Term::AXi, Term::CEta}) {
            std::vector<double> &v = blk.controls.term[static_cast<int>(t)];
            for (double &c : v)
                if (std::fabs(c) > limit) {
                    c = std::copysign(limit, c);
                    ++clipped;
                }
        }
    return clipped;
}

namespace {
// The axis a side runs along: 0 for JMIN, JMAX (i), 1 for IMIN, IMAX (j).
int axis_of(Side s) { return s == Side::JMin || s == Side::JMax ? 0 : 1; }

// Coarse node I's full-weighting hat over the finer indices: the transpose
// of the interpolation (linear between the coarse nodes, mirrored past an
// end, where the halo holds the next block's node), weights summing to 1.
std::vector<std::pair<int, double>> hat(const CoarseAxis &a, int I) {
    const double c = a.pos[static_cast<std::size_t>(I)];
    const double l = I > 0 ? a.pos[static_cast<std::size_t>(I) - 1] : -a.pos[1];
    const double r = I < a.nc - 1 ? a.pos[static_cast<std::size_t>(I) + 1] : 2.0 * c - a.pos[static_cast<std::size_t>(a.nc) - 2];
    std::vector<std::pair<int, double>> w;
    double sum = 0.0;
    for (int i = static_cast<int>(std::floor(l)) + 1; i < r; ++i) {
        if (i <= l || i < -1 || i > a.nf) continue;
        const double v = i <= c ? (i - l) / (c - l) : (r - i) / (r - c);
        w.emplace_back(i, v);
        sum += v;
    }
    for (auto &p : w) p.second /= sum;
    return w;
}
}  // namespace

std::string Composite::coarse_anchors(std::vector<std::array<std::vector<int>, 2>> &anchors) const {
    for (std::size_t b = 0; b < blocks_.size(); ++b)
        if (blocks_[b].ni < 5 || blocks_[b].nj < 5)
            return format("block %zu has %d x %d cells (the set coarsens while every block has at least 4 cells each "
                          "way)", b, blocks_[b].ni - 1, blocks_[b].nj - 1);
    std::vector<std::array<std::set<int>, 2>> sets(blocks_.size());
    for (const Join &j : joins_)
        for (const SideRange *r : {&j.a, &j.b}) {
            std::set<int> &a = sets[static_cast<std::size_t>(r->block)][static_cast<std::size_t>(axis_of(r->side))];
            a.insert(r->first);
            a.insert(r->last);
        }
    for (bool added = true; added;) {
        added = false;
        for (const Join &j : joins_)
            for (int d = 0; d < 2; ++d) {
                const SideRange &from = d == 0 ? j.a : j.b, &to = d == 0 ? j.b : j.a;
                const std::set<int> known = sets[static_cast<std::size_t>(from.block)][static_cast<std::size_t>(axis_of(from.side))];
                std::set<int> &into = sets[static_cast<std::size_t>(to.block)][static_cast<std::size_t>(axis_of(to.side))];
                for (int p : known)
                    if ((p - from.first) * from.step() >= 0 && (p - from.first) * from.step() < from.count())
                        added = into.insert(to.at((p - from.first) * from.step())).second || added;
            }
    }
    anchors.assign(blocks_.size(), {});
    for (std::size_t b = 0; b < blocks_.size(); ++b)
        for (int d = 0; d < 2; ++d) anchors[b][static_cast<std::size_t>(d)].assign(sets[b][static_cast<std::size_t>(d)].begin(), sets[b][static_cast<std::size_t>(d)].end());
    return "";
}

std::string Composite::why_not_coarsenable() const {
    std::vector<std::array<std::vector<int>, 2>> anchors;
    return coarse_anchors(anchors);
}

Composite Composite::coarsened() const {
    std::vector<std::array<std::vector<int>, 2>> anchors;
    const std::string why = coarse_anchors(anchors);
    if (!why.empty()) fail(Failure::State, "the set does not coarsen: " + why);
    std::vector<std::array<CoarseAxis, 2>> axes(blocks_.size());
    std::vector<BlockShape> shapes;
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        axes[b][0] = make_axis(blocks_[b].ni, false, anchors[b][0], true);
        axes[b][1] = make_axis(blocks_[b].nj, false, anchors[b][1], true);
        shapes.push_back({axes[b][0].nc, axes[b][1].nc});
    }
    std::vector<Join> joins = joins_;
    for (Join &j : joins)
        for (SideRange *r : {&j.a, &j.b}) {
            const CoarseAxis &a = axes[static_cast<std::size_t>(r->block)][static_cast<std::size_t>(axis_of(r->side))];
            r->first = a.nearest(r->first);  // anchors: exact coarse nodes
            r->last = a.nearest(r->last);
        }
    Composite c(shapes, joins);
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block &blk = c.blocks_[b];
        blk.ai = std::move(axes[b][0]);
        blk.aj = std::move(axes[b][1]);
        for (int I = 0; I < blk.ni; ++I) blk.hat_i.push_back(hat(blk.ai, I));
        for (int J = 0; J < blk.nj; ++J) blk.hat_j.push_back(hat(blk.aj, J));
    }
    c.sample(*this);
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        const Block &f = blocks_[b];
        Block &blk = c.blocks_[b];
        for (int t = 0; t < kTermCount; ++t) {
            const double *src = f.controls.data(static_cast<Term>(t));
            if (!src) continue;
            std::vector<double> &e = blk.controls.at(static_cast<Term>(t), blk.x.size());
            for (int J = 0; J < blk.nj; ++J)
                for (int I = 0; I < blk.ni; ++I) {
                    const double si = blk.ai.h[static_cast<std::size_t>(I)], sj = blk.aj.h[static_cast<std::size_t>(J)];
                    const double scale[kTermCount] = {si, sj, sj * sj / si, 1.0 / si, si * si / sj, si, sj, 1.0 / sj};
                    e[blk.at(I, J)] = scale[t] * blk.sampled(f, src, I, J);
                }
        }
    }
    return c;
}

double Composite::Block::sampled(const Block &fine, const double *v, int I, int J) const {
    const std::size_t si = static_cast<std::size_t>(I), sj = static_cast<std::size_t>(J);
    const int i0 = ai.dn_lo[si], j0 = aj.dn_lo[sj];
    const double ti = ai.dn_t[si], tj = aj.dn_t[sj];
    return (1 - tj) * ((1 - ti) * v[fine.at(i0, j0)] + ti * v[fine.at(i0 + 1, j0)]) +
           tj * ((1 - ti) * v[fine.at(i0, j0 + 1)] + ti * v[fine.at(i0 + 1, j0 + 1)]);
}

void Composite::sample(const Composite &fine) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block &blk = blocks_[b];
        const Block &f = fine.blocks_[b];
        for (int j = 0; j < blk.nj; ++j)
            for (int i = 0; i < blk.ni; ++i) {
                blk.x[blk.at(i, j)] = blk.sampled(f, f.x.data(), i, j);
                blk.y[blk.at(i, j)] = blk.sampled(f, f.y.data(), i, j);
            }
    }
    sync();
}

void Composite::sync(Field a, Field b) {
    for (const Link &l : copies_) copy(l, a), copy(l, b);
    for (const Link &l : halos_) copy(l, a), copy(l, b);
}

void Composite::sync() { sync(&Block::x, &Block::y); }

void Composite::sync_from(std::size_t b) {
    for (const Link &l : copies_)
        if (l.from == static_cast<int>(b)) copy(l, &Block::x), copy(l, &Block::y);
    for (const Link &l : halos_)
        if (l.from == static_cast<int>(b) || blocks_[static_cast<std::size_t>(l.from)].role[l.src] == kCopy)
            copy(l, &Block::x), copy(l, &Block::y);
}

void Composite::sweep(System system, double omega) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block &blk = blocks_[b];
        const Level L = blk.level();
        blk.each_unknown([&](const Stencil &st) { blk.relax(system, L, st, omega); });
        sync_from(b);  // the blocks after this one see its new values at once (Gauss-Seidel across the set)
    }
    relax_vertices(system);
}

void Composite::sweep_lines(System system, double omega_xi, double omega_eta) {
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t b = 0; b < blocks_.size(); ++b) {
            Block &blk = blocks_[b];
            const Level L = blk.level();
            if (blk.self_joined) {
                // Its lines see each other across its own join only through
                // the copies: synced line by line, a line meets its
                // partner's new values (Gauss-Seidel by lines). Synced once
                // per block, the partners coupled as Jacobi, and a C-grid
                // cut as a join diverged above omega 1.5 (auto: 1.9).
                const Connectivity &conn = *L.conn;
                const bool xi = pass == 0;
                for (int k = xi ? conn.j_begin() : conn.i_begin(); k < (xi ? conn.j_end() : conn.i_end()); ++k) {
                    if (xi) relax_xi_line(system, L, k, omega_xi, blk.lines);
                    else relax_eta_line(system, L, k, omega_eta, blk.lines);
                    sync_from(b);
                }
                continue;
            }
            if (pass == 0) sweep_xi_lines(system, L, omega_xi, blk.lines);
            else sweep_eta_lines(system, L, omega_eta, blk.lines);
            sync_from(b);
        }
    relax_vertices(system);
}

int Composite::longest() const {
    int n = 0;
    for (const Block &blk : blocks_) n = std::max({n, blk.ni, blk.nj});
    return n;
}

LineOmega Composite::line_omega() const {
    LineOmega best{1.0, 1.0};
    for (const Block &blk : blocks_) {
        const LineOmega o = optimal_line_sor_omega(Connectivity(blk.ni, blk.nj, Topology::Single));
        best.xi = std::max(best.xi, o.xi);
        best.eta = std::max(best.eta, o.eta);
    }
    return best;
}

void Composite::smooth(System system) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block &blk = blocks_[b];
        const Level L = blk.level();
        ilu_sweep(system, L, false, 1.0, blk.ilu);
        ilu_sweep(system, L, true, 1.0, blk.ilu);
        sync_from(b);
    }
    relax_vertices(system);
}

void Composite::compute_residual(System system) {
    for (Block &blk : blocks_) {
        const Level L = blk.level();
        std::fill(blk.rx.begin(), blk.rx.end(), 0.0);
        std::fill(blk.ry.begin(), blk.ry.end(), 0.0);
        blk.each_unknown([&](const Stencil &st) {
            const NodeEquation eq = node_equation(system, L, st);
            blk.rx[static_cast<std::size_t>(st.c)] = eq.rx;
            blk.ry[static_cast<std::size_t>(st.c)] = eq.ry;
        });
    }
    sync(&Block::rx, &Block::ry);
}

void Composite::restrict_from(System system, const Composite &fine) {
    // Full weighting over each coarse node's hats (halos included).
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block &blk = blocks_[b];
        const Block &f = fine.blocks_[b];
        blk.x0 = blk.x;
        blk.y0 = blk.y;
        blk.fx.assign(blk.x.size(), 0.0);
        blk.fy.assign(blk.x.size(), 0.0);
        Level L = blk.level();
        L.fx = L.fy = nullptr;
        for (int J = 0; J < blk.nj; ++J)
            for (int I = 0; I < blk.ni; ++I) {
                const std::size_t k = blk.at(I, J);
                if (blk.role[k] != kUnknown) continue;
                double sx = 0.0, sy = 0.0;
                for (const auto &wj : blk.hat_j[static_cast<std::size_t>(J)])
                    for (const auto &wi : blk.hat_i[static_cast<std::size_t>(I)]) {
                        const std::size_t kf = f.at(wi.first, wj.first);
                        sx += wi.second * wj.second * f.rx[kf];
                        sy += wi.second * wj.second * f.ry[kf];
                    }
                const NodeEquation eq = node_equation(system, L, blk.conn.stencil(I + 1, J + 1));
                const double s = blk.scale(system, I, J);
                blk.fx[k] = eq.rx - s * sx;
                blk.fy[k] = eq.ry - s * sy;
            }
    }
    // The vertices (the same nodes on every level, in the same order),
    // injected: the mean of the neighbours less the vertex is h^2/4 times a
    // Laplacian, so four times the fine one on the coarse level.
    for (std::size_t v = 0; v < vertices_.size(); ++v) {
        Vertex &c = vertices_[v];
        double fine_rx, fine_ry, rx, ry;
        fine.vertex_equation(fine.vertices_[v], fine_rx, fine_ry);
        c.fx = c.fy = 0.0;
        vertex_equation(c, rx, ry);
        // (the Laplacian's scale where the vertex is)
        const Block &home = blocks_[static_cast<std::size_t>(c.copies[0].block)];
        const int I = static_cast<int>(c.copies[0].k % static_cast<std::size_t>(home.ni + 2)) - 1;
        const int J = static_cast<int>(c.copies[0].k / static_cast<std::size_t>(home.ni + 2)) - 1;
        const double s = home.scale(System::Laplace, I, J);
        c.fx = rx - s * fine_rx;
        c.fy = ry - s * fine_ry;
        c.x0 = blocks_[static_cast<std::size_t>(c.copies[0].block)].x[c.copies[0].k];
        c.y0 = blocks_[static_cast<std::size_t>(c.copies[0].block)].y[c.copies[0].k];
    }
}

void Composite::prolong_to(Composite &fine) const {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        const Block &blk = blocks_[b];
        Block &f = fine.blocks_[b];
        auto dx = [&](int I, int J) { return blk.x[blk.at(I, J)] - blk.x0[blk.at(I, J)]; };
        auto dy = [&](int I, int J) { return blk.y[blk.at(I, J)] - blk.y0[blk.at(I, J)]; };
        for (int j = 0; j < f.nj; ++j)
            for (int i = 0; i < f.ni; ++i) {
                const std::size_t k = f.at(i, j);
                if (f.role[k] != kUnknown) continue;
                const int I = blk.ai.up_lo[static_cast<std::size_t>(i)], J = blk.aj.up_lo[static_cast<std::size_t>(j)];
                const double ti = blk.ai.up_t[static_cast<std::size_t>(i)], tj = blk.aj.up_t[static_cast<std::size_t>(j)];
                f.x[k] += (1 - tj) * ((1 - ti) * dx(I, J) + ti * dx(I + 1, J)) + tj * ((1 - ti) * dx(I, J + 1) + ti * dx(I + 1, J + 1));
                f.y[k] += (1 - tj) * ((1 - ti) * dy(I, J) + ti * dy(I + 1, J)) + tj * ((1 - ti) * dy(I, J + 1) + ti * dy(I + 1, J + 1));
            }
    }
    for (std::size_t v = 0; v < vertices_.size(); ++v) {
        const Vertex &c = vertices_[v];
        const Node &n = c.copies[0];
        const double ddx = blocks_[static_cast<std::size_t>(n.block)].x[n.k] - c.x0;
        const double ddy = blocks_[static_cast<std::size_t>(n.block)].y[n.k] - c.y0;
        for (const Node &m : fine.vertices_[v].copies) {
            fine.blocks_[static_cast<std::size_t>(m.block)].x[m.k] += ddx;
            fine.blocks_[static_cast<std::size_t>(m.block)].y[m.k] += ddy;
        }
    }
    fine.sync();
}

void Composite::start_fmg() {
    for (Vertex &v : vertices_) {
        v.fx = v.fy = 0.0;
        v.x0 = blocks_[static_cast<std::size_t>(v.copies[0].block)].x[v.copies[0].k];
        v.y0 = blocks_[static_cast<std::size_t>(v.copies[0].block)].y[v.copies[0].k];
    }
    for (Block &blk : blocks_) {
        blk.fx.clear();
        blk.fy.clear();
        blk.x0 = blk.x;
        blk.y0 = blk.y;
    }
}

double Composite::residual(System system, double extent) const {
    double worst = 0.0;
    for (const Block &blk : blocks_) {
        const Level L = blk.level();
        blk.each_unknown([&](const Stencil &st) {
            const NodeEquation eq = node_equation(system, L, st);
            worst = std::max(worst, std::max(std::fabs(eq.rx), std::fabs(eq.ry)) / eq.diag);
        });
    }
    worst = std::max(worst, vertex_residual());
    return extent > 0.0 ? worst / extent : worst;
}

long Composite::nodes() const {
    long n = 0;
    for (const Block &blk : blocks_) n += static_cast<long>(blk.ni) * blk.nj;
    return n;
}

void Composite::save() { snapshot(saved_); }

void Composite::restore() { restore(saved_); }

// Into s, whose vectors keep their capacity: no allocation after the first
// guarded sweep.
void Composite::snapshot(Snapshot &s) const {
    s.x.resize(blocks_.size());
    s.y.resize(blocks_.size());
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        s.x[b] = blocks_[b].x;
        s.y[b] = blocks_[b].y;
    }
}

Composite::Snapshot Composite::snapshot() const {
    Snapshot s;
    snapshot(s);
    return s;
}

void Composite::restore(const Snapshot &s) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        blocks_[b].x = s.x[b];
        blocks_[b].y = s.y[b];
    }
}

double Composite::move() const {
    double m = 0.0;
    for (std::size_t b = 0; b < blocks_.size(); ++b)
        for (std::size_t k = 0; k < blocks_[b].x.size(); ++k) {
            const double d =
                std::max(std::fabs(blocks_[b].x[k] - saved_.x[b][k]), std::fabs(blocks_[b].y[k] - saved_.y[b][k]));
            if (!std::isfinite(d)) return std::numeric_limits<double>::infinity();
            m = std::max(m, d);
        }
    return m;
}

bool Composite::finite() const {
    for (const Block &blk : blocks_)
        for (std::size_t k = 0; k < blk.x.size(); ++k)
            if (!std::isfinite(blk.x[k]) || !std::isfinite(blk.y[k])) return false;
    return true;
}

void Composite::extract(int b, std::vector<double> &x, std::vector<double> &y) const {
    const Block &blk = blocks_[static_cast<std::size_t>(b)];
    x.resize(static_cast<std::size_t>(blk.ni) * static_cast<std::size_t>(blk.nj));
    y.resize(x.size());
    for (int j = 0; j < blk.nj; ++j)
        for (int i = 0; i < blk.ni; ++i) {
            x[node_index(blk.ni, i, j)] = blk.x[blk.at(i, j)];
            y[node_index(blk.ni, i, j)] = blk.y[blk.at(i, j)];
        }
}

}  // namespace eg2d
