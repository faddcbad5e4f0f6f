// A set of blocks as one grid for the solver: each block's coordinates with
// a ring of halo nodes round it, which hold the nodes across its joins, so
// that a joined side's nodes have the whole nine-point stencil of an
// interior node (the stencil spans both blocks) and the operator
// (operator.hpp) is used unchanged. A joined side's node is solved by one
// block (the first of its join) and copied into the other; the halos are
// copied from the nodes one line into the neighbouring block.
//
// Vertices (the end nodes of a join: where three, four or five blocks meet,
// or a join meets the domain's boundary) are held where the blocks'
// boundaries put them: the fixed-vertex treatment of Thompson, Soni &
// Weatherill (1999, ch. 6), which needs no stencil round a vertex of any
// valence.
#pragma once
#include <cstddef>
#include <vector>

#include "base/connectivity.hpp"
#include "blocks/block_set.hpp"
#include "operator/system.hpp"

namespace eg2d {

class Composite {
public:
    // From the blocks' current coordinates.
    explicit Composite(const BlockSet &set);

    // One Gauss-Seidel/SOR sweep over every block's unknowns, the copies
    // and halos brought up to date after each block.
    void sweep(System system, double omega);
    // NUMERICS.md's residual over every unknown, over `extent`.
    double residual(System system, double extent) const;
    // Every copy and halo from its source.
    void sync();
    bool finite() const;
    // Block b's coordinates (ni*nj, Fortran order) into x, y.
    void extract(int b, std::vector<double> &x, std::vector<double> &y) const;
    long unknowns() const { return unknowns_; }
    // For a guarded sweep: keep the coordinates, put them back, and the
    // largest coordinate change since save() (inf if any is not finite).
    void save();
    void restore();
    double move() const;

private:
    enum Role : char { kHeld = 0, kUnknown = 1, kCopy = 2, kHalo = 3 };
    struct Block {
        int ni, nj;
        Connectivity conn;  // (ni+2) x (nj+2), single block
        std::vector<double> x, y;
        std::vector<char> role;
        std::size_t at(int i, int j) const {  // block node (i, j), -1 <= i <= ni
            return static_cast<std::size_t>(i + 1) + static_cast<std::size_t>(ni + 2) * static_cast<std::size_t>(j + 1);
        }
    };
    // Node `dst` of block `to` holds node `src` of block `from`.
    struct Link {
        int from;
        std::size_t src;
        int to;
        std::size_t dst;
    };
    void copy(const Link &l) {
        blocks_[static_cast<std::size_t>(l.to)].x[l.dst] = blocks_[static_cast<std::size_t>(l.from)].x[l.src];
        blocks_[static_cast<std::size_t>(l.to)].y[l.dst] = blocks_[static_cast<std::size_t>(l.from)].y[l.src];
    }
    std::vector<Block> blocks_;
    std::vector<std::vector<double>> saved_x_, saved_y_;
    std::vector<Link> copies_, halos_;  // copies first: a halo may read a copy
    long unknowns_ = 0;
};

}  // namespace eg2d
