#include "blocks/composite.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "generator/generator.hpp"
#include "operator/operator.hpp"

namespace eg2d {

Composite::Composite(const BlockSet &set) {
    blocks_.reserve(static_cast<std::size_t>(set.size()));
    for (int b = 0; b < set.size(); ++b) {
        const Grid &g = set.block(b)->grid();
        Block blk{g.ni(), g.nj(), Connectivity(g.ni() + 2, g.nj() + 2, Topology::Single), {}, {}, {}};
        const std::size_t n = static_cast<std::size_t>(g.ni() + 2) * static_cast<std::size_t>(g.nj() + 2);
        blk.x.assign(n, 0.0);
        blk.y.assign(n, 0.0);
        blk.role.assign(n, kHeld);
        for (int j = 0; j < g.nj(); ++j)
            for (int i = 0; i < g.ni(); ++i) {
                const std::size_t k = blk.at(i, j), kg = node_index(g.ni(), i, j);
                blk.x[k] = g.x[kg];
                blk.y[k] = g.y[kg];
                if (i > 0 && j > 0 && i < g.ni() - 1 && j < g.nj() - 1) blk.role[k] = kUnknown;
            }
        blocks_.push_back(std::move(blk));
    }
    for (const Join &j : set.joins()) {
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
    for (const Block &blk : blocks_) unknowns_ += std::count(blk.role.begin(), blk.role.end(), kUnknown);
    sync();
}

void Composite::sync() {
    for (const Link &l : copies_) copy(l);
    for (const Link &l : halos_) copy(l);
}

void Composite::sweep(System system, double omega) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block &blk = blocks_[b];
        Level L;
        L.conn = &blk.conn;
        L.x = blk.x.data();
        L.y = blk.y.data();
        for (int j = 1; j <= blk.nj; ++j)
            for (int i = 1; i <= blk.ni; ++i) {
                const Stencil s = blk.conn.stencil(i, j);
                if (blk.role[static_cast<std::size_t>(s.c)] != kUnknown) continue;
                const NodeEquation eq = node_equation(system, L, s);
                blk.x[static_cast<std::size_t>(s.c)] += omega * eq.rx / eq.diag;
                blk.y[static_cast<std::size_t>(s.c)] += omega * eq.ry / eq.diag;
            }
        // The blocks after this one see its new values at once (Gauss-Seidel across the set).
        for (const Link &l : copies_)
            if (l.from == static_cast<int>(b)) copy(l);
        for (const Link &l : halos_)
            if (l.from == static_cast<int>(b) || blocks_[static_cast<std::size_t>(l.from)].role[l.src] == kCopy) copy(l);
    }
}

double Composite::residual(System system, double extent) const {
    double worst = 0.0;
    for (const Block &blk : blocks_) {
        Level L;
        L.conn = &blk.conn;
        L.x = const_cast<double *>(blk.x.data());  // node_equation only reads
        L.y = const_cast<double *>(blk.y.data());
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
            const double d = std::max(std::fabs(blocks_[b].x[k] - saved_x_[b][k]), std::fabs(blocks_[b].y[k] - saved_y_[b][k]));
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
