#include "blocks/composite.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
    return L;
}

Composite::Composite(const std::vector<BlockShape> &shapes, const std::vector<Join> &joins)
    : shapes_(shapes), joins_(joins) {
    blocks_.reserve(shapes.size());
    for (const BlockShape &sh : shapes) {
        Block blk{sh.ni, sh.nj, Connectivity(sh.ni + 2, sh.nj + 2, Topology::Single), {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
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
            if (t == 0 || t == count - 1) continue;  // a vertex: held
            A.role[node(A, j.a, t, 0)] = kUnknown;
            B.role[node(B, j.b, t, 0)] = kCopy;
            copies_.push_back(Link{j.a.block, node(A, j.a, t, 0), j.b.block, node(B, j.b, t, 0)});
        }
    }
    for (Block &blk : blocks_) {
        unknowns_ += std::count(blk.role.begin(), blk.role.end(), kUnknown);
        std::vector<char> held(blk.role.size());
        for (std::size_t k = 0; k < held.size(); ++k) held[k] = blk.role[k] != kUnknown;
        blk.conn = blk.conn.with_fixed_nodes(held);
    }
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
    }
    c.sync();
    return c;
}

bool Composite::coarsenable() const {
    for (const BlockShape &s : shapes_)
        if ((s.ni - 1) % 2 != 0 || (s.nj - 1) % 2 != 0 || s.ni < 5 || s.nj < 5) return false;
    for (const Join &j : joins_)
        for (const SideRange &r : {j.a, j.b})
            if (r.first % 2 != 0 || r.last % 2 != 0) return false;
    return true;
}

Composite Composite::coarsened() const {
    std::vector<BlockShape> shapes;
    for (const BlockShape &s : shapes_) shapes.push_back({(s.ni - 1) / 2 + 1, (s.nj - 1) / 2 + 1});
    std::vector<Join> joins = joins_;
    for (Join &j : joins)
        for (SideRange *r : {&j.a, &j.b}) {
            r->first /= 2;
            r->last /= 2;
        }
    Composite c(shapes, joins);
    c.sample(*this);
    return c;
}

void Composite::sample(const Composite &fine) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block &blk = blocks_[b];
        const Block &f = fine.blocks_[b];
        for (int j = 0; j < blk.nj; ++j)
            for (int i = 0; i < blk.ni; ++i) {
                blk.x[blk.at(i, j)] = f.x[f.at(2 * i, 2 * j)];
                blk.y[blk.at(i, j)] = f.y[f.at(2 * i, 2 * j)];
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
        for (int j = 1; j <= blk.nj; ++j)
            for (int i = 1; i <= blk.ni; ++i) {
                const Stencil s = blk.conn.stencil(i, j);
                if (blk.role[static_cast<std::size_t>(s.c)] != kUnknown) continue;
                const NodeEquation eq = node_equation(system, L, s);
                blk.x[static_cast<std::size_t>(s.c)] += omega * eq.rx / eq.diag;
                blk.y[static_cast<std::size_t>(s.c)] += omega * eq.ry / eq.diag;
            }
        sync_from(b);  // the blocks after this one see its new values at once (Gauss-Seidel across the set)
    }
}

void Composite::smooth(System system) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block &blk = blocks_[b];
        const Level L = blk.level();
        ilu_sweep(system, L, false, 1.0, blk.ilu);
        ilu_sweep(system, L, true, 1.0, blk.ilu);
        sync_from(b);
    }
}

void Composite::compute_residual(System system) {
    for (Block &blk : blocks_) {
        const Level L = blk.level();
        for (int j = 1; j <= blk.nj; ++j)
            for (int i = 1; i <= blk.ni; ++i) {
                const Stencil s = blk.conn.stencil(i, j);
                const std::size_t k = static_cast<std::size_t>(s.c);
                if (blk.role[k] != kUnknown) {
                    blk.rx[k] = blk.ry[k] = 0.0;
                    continue;
                }
                const NodeEquation eq = node_equation(system, L, s);
                blk.rx[k] = eq.rx;
                blk.ry[k] = eq.ry;
            }
    }
    sync(&Block::rx, &Block::ry);
}

void Composite::restrict_from(System system, const Composite &fine) {
    // Full weighting over the fine node's 3x3 neighbours (halos included).
    static constexpr double w[3] = {0.25, 0.5, 0.25};
    const double scale = system == System::Winslow ? 16.0 : 4.0;
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
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di) {
                        const std::size_t kf = f.at(2 * I + di, 2 * J + dj);
                        sx += w[di + 1] * w[dj + 1] * f.rx[kf];
                        sy += w[di + 1] * w[dj + 1] * f.ry[kf];
                    }
                const NodeEquation eq = node_equation(system, L, blk.conn.stencil(I + 1, J + 1));
                blk.fx[k] = eq.rx - scale * sx;
                blk.fy[k] = eq.ry - scale * sy;
            }
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
                const int I0 = i / 2, J0 = j / 2, I1 = I0 + (i % 2), J1 = J0 + (j % 2);
                f.x[k] += 0.25 * (dx(I0, J0) + dx(I1, J0) + dx(I0, J1) + dx(I1, J1));
                f.y[k] += 0.25 * (dy(I0, J0) + dy(I1, J0) + dy(I0, J1) + dy(I1, J1));
            }
    }
    fine.sync();
}

void Composite::start_fmg() {
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
        for (int j = 1; j <= blk.nj; ++j)
            for (int i = 1; i <= blk.ni; ++i) {
                const Stencil s = blk.conn.stencil(i, j);
                if (blk.role[static_cast<std::size_t>(s.c)] != kUnknown) continue;
                const NodeEquation eq = node_equation(system, L, s);
                worst = std::max(worst, std::max(std::fabs(eq.rx), std::fabs(eq.ry)) / eq.diag);
            }
    }
    return extent > 0.0 ? worst / extent : worst;
}

long Composite::nodes() const {
    long n = 0;
    for (const BlockShape &s : shapes_) n += static_cast<long>(s.ni) * s.nj;
    return n;
}

void Composite::save() {
    saved_x_.resize(blocks_.size());
    saved_y_.resize(blocks_.size());
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        saved_x_[b] = blocks_[b].x;  // capacity kept: no allocation after the first sweep
        saved_y_[b] = blocks_[b].y;
    }
}

void Composite::restore() {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        blocks_[b].x = saved_x_[b];
        blocks_[b].y = saved_y_[b];
    }
}

double Composite::move() const {
    double m = 0.0;
    for (std::size_t b = 0; b < blocks_.size(); ++b)
        for (std::size_t k = 0; k < blocks_[b].x.size(); ++k) {
            const double d =
                std::max(std::fabs(blocks_[b].x[k] - saved_x_[b][k]), std::fabs(blocks_[b].y[k] - saved_y_[b][k]));
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
