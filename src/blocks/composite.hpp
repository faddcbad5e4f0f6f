// A set of blocks as one grid for the solvers: each block's coordinates with
// a ring of halo nodes round it, which hold the nodes across its joins, so
// that a joined side's nodes have the whole nine-point stencil of an
// interior node (the stencil spans both blocks) and the operator
// (operator.hpp) and the single-block kernels (the ILU sweep) run unchanged
// on each block. A joined side's node is solved by one block (the first of
// its join) and copied into the other; the halos are copied from the nodes
// one line into the neighbouring block. Every node a block does not solve
// (its boundary, the copies, the vertices) is a held node of its
// connectivity (Connectivity::with_fixed_nodes): an identity row.
//
// Vertices (the end nodes of a join: where three, four or five blocks meet,
// or a join meets the domain's boundary) have no nine-point stencil in any
// one block. One on the domain's boundary stays where the blocks'
// boundaries put it. One inside the set (every side edge round it joined)
// moves to the mean of its neighbours along the grid lines that leave it,
// whatever their number (the averaged treatment of Thompson, Soni &
// Weatherill 1999, ch. 6: the five-point Laplace equation where four
// blocks meet), after every sweep of every level, its equation restricted
// and corrected with the rest in multigrid.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "base/block_tridiagonal.hpp"  // Vec2
#include "base/connectivity.hpp"
#include "blocks/block_set.hpp"
#include "operator/operator.hpp"
#include "operator/system.hpp"
#include "solvers/coarse_axis.hpp"
#include "solvers/line_relax.hpp"
#include "solvers/multigrid_ilu.hpp"

namespace eg2d {

struct BlockShape {
    int ni, nj;
};

class Composite {
public:
    // The blocks' shapes and joins, coordinates 0.
    Composite(const std::vector<BlockShape> &shapes, const std::vector<Join> &joins);
    // From the blocks' current coordinates and their static control terms
    // (each block's own, on its own grid; at a joined node the block
    // computes none, those one line into the block).
    static Composite of(const BlockSet &set);

    // Every block has at least 4 cells each way: the set coarsens, any
    // size (the single block's coarse axes, solvers/coarse_axis.hpp: a
    // stretch of L cells between anchors becomes ceil(L/2) equal cells, every
    // other node where L is even). The anchors of a block's axis are its
    // joins' ends and, carried across each join until none is added, the
    // anchors of the axes it is joined to, so a join's two sides keep the
    // same coarse nodes.
    bool coarsenable() const { return why_not_coarsenable().empty(); }
    // What keeps it from coarsening ("block 1 has 3 x 40 cells"), or "".
    std::string why_not_coarsenable() const;
    // The coarse level: each block on its coarse axes, the joins' ends their
    // coarse nodes; coordinates and control fields sampled (a, b, c times
    // the local coarsening factor and d over it: multigrid_hierarchy.cpp's
    // restrict_controls).
    Composite coarsened() const;
    // Coordinates sampled from `fine` (of which this is coarsened()), halos synced.
    void sample(const Composite &fine);

    // One Gauss-Seidel/SOR sweep over every block's unknowns, the copies
    // and halos brought up to date after each block.
    void sweep(System system, double omega);
    // One line SOR sweep: every block's xi-lines, then every block's
    // eta-lines (line_relax.hpp), the copies and halos after each block.
    void sweep_lines(System system, double omega_xi, double omega_eta);
    // The multigrid smoother: on each block the ILU sweep in both orderings
    // (solvers/multigrid_ilu.hpp), then its copies and halos.
    void smooth(System system);
    // Each free vertex to the mean of its neighbours, kLocalSweeps times
    // together with point Gauss-Seidel on the unknowns within kLocalRadius
    // of it in each block: the block sweeps see a vertex held, and the
    // error they leave round it is what limits the cycle (the bump in four
    // blocks, Laplace: 0.20 per cycle with V(2,1) where one block takes
    // 0.001; six sweeps before and after made it 0.03). The same local
    // sweeps round the vertices on the domain's boundary (a step's corner).
    void relax_vertices(System system);
    int free_vertices() const { return static_cast<int>(vertices_.size()); }
    int held_vertices() const { return static_cast<int>(held_vertices_.size()); }
    // R = L(r) - f at every unknown into the residual fields (0 elsewhere),
    // copies and halos synced so a restriction reads across the joins.
    void compute_residual(System system);
    // FAS: this coarse level's right-hand side f = L(r) - s FW(R_fine) at
    // its unknowns (r: its coordinates as sampled), s the operator's scale
    // under coarsening by two (Laplace 4, Winslow 16); keeps r as r0.
    void restrict_from(System system, const Composite &fine);
    // fine += the bilinear interpolation of (r - r0) at fine's unknowns.
    void prolong_to(Composite &fine) const;
    // Full multigrid's start on a coarse level: its own problem (f = 0),
    // r0 the coordinates as they are (sampled from the start).
    void start_fmg();

    // NUMERICS.md's residual over every unknown and free vertex (its
    // distance from its neighbours' mean, less f), over `extent`.
    double residual(System system, double extent) const;
    // Every copy and halo from its source.
    void sync();
    bool finite() const;
    // Block b's coordinates (ni*nj, Fortran order) into x, y.
    void extract(int b, std::vector<double> &x, std::vector<double> &y) const;
    long unknowns() const { return unknowns_; }
    long nodes() const;
    // The most nodes along one side of any block.
    int longest() const;
    // The line SOR model optimum of the block whose factors are largest.
    LineOmega line_omega() const;
    // Node by node, for what re-spaces the set's lines (set_wall_layer.hpp).
    int size() const { return static_cast<int>(blocks_.size()); }
    BlockShape shape(int b) const {
        return {blocks_[static_cast<std::size_t>(b)].ni, blocks_[static_cast<std::size_t>(b)].nj};
    }
    Vec2 point(int b, int i, int j) const {
        const Block &blk = blocks_[static_cast<std::size_t>(b)];
        return {blk.x[blk.at(i, j)], blk.y[blk.at(i, j)]};
    }
    // Node (i, j) of block b alone: the caller puts every block's copy of
    // the node, then syncs.
    void put(int b, int i, int j, Vec2 p) {
        Block &blk = blocks_[static_cast<std::size_t>(b)];
        blk.x[blk.at(i, j)] = p.x;
        blk.y[blk.at(i, j)] = p.y;
    }
    // Whether the solve moves node (i, j) of block b: one a block solves, a
    // copy of one, or (with `vertices`) a free vertex.
    bool moves(int b, int i, int j, bool vertices) const;
    // Each block's controls: its static terms plus, at every node it
    // solves, a Phi and Psi (Term::AXi, CEta) that hold the grid's spacing:
    // the one-dimensional ones of the lines through the node (Thomas &
    // Middlecoff 1980; a joined node's lines run on into the next block),
    // or, `exact`, the ones that make the grid as it is an exact solution
    // (the node's equation is affine in them: solved from three of its
    // evaluations). Winslow's system; before the solver's levels are built.
    void hold_spacing(System system, bool exact);
    // Each free vertex held where it is (its equation's right-hand side
    // the mean of its neighbours less it, as the exact controls hold the
    // nodes round it: without, a pitzDaily vertex re-spaced round pulled
    // against them and the smoother diverged), or (false) at the mean again.
    void hold_vertices(bool hold);
    // Each block's controls its static terms alone again, the vertices at
    // their neighbours' mean.
    void drop_layer_controls() {
        for (Block &blk : blocks_) blk.controls = blk.given;
        hold_vertices(false);
    }
    // The largest deviation of a cell's corner angle from 90 degrees.
    double largest_skew() const;
    // Cells whose signed area (shoelace) is zero or of the other sign than
    // most of its block's.
    long folded_cells() const;
    // The largest |Phi|, |Psi| (Term::AXi, CEta) at any node a block solves.
    double stretching() const;
    // Those past `limit` set to it, signs kept; how many.
    long clip_stretching(double limit);
    // For a guarded sweep: keep the coordinates, put them back, and the
    // largest coordinate change since save() (inf if any is not finite).
    void save();
    void restore();
    double move() const;
    // The coordinates kept apart from the guarded sweep's (a pass of the
    // solve that may be undone: the sweeps inside it save their own).
    struct Snapshot {
        std::vector<std::vector<double>> x, y;
    };
    Snapshot snapshot() const;
    void snapshot(Snapshot &s) const;
    void restore(const Snapshot &s);

private:
    enum Role : char { kHeld = 0, kUnknown = 1, kCopy = 2, kHalo = 3 };
    // Each block's axes' anchors (i, j) for the next coarser level, or why
    // the set does not coarsen.
    std::string coarse_anchors(std::vector<std::array<std::vector<int>, 2>> &anchors) const;
    struct Block {
        int ni, nj;
        Connectivity conn;  // (ni+2) x (nj+2), single block, every node not solved here held
        std::vector<double> x, y, fx, fy, rx, ry, x0, y0;  // fx, fy, x0, y0: coarse levels only
        std::vector<char> role;
        ControlFields controls;  // (ni+2) x (nj+2); empty: none
        ControlFields given;     // the static terms of the block's own controls (of())
        // Coarse levels: the axes from the finer level's block, and each
        // coarse node's full-weighting hat over the finer indices -1..n (the
        // halo included, so it reads across a join).
        CoarseAxis ai, aj;
        std::vector<std::vector<std::pair<int, double>>> hat_i, hat_j;
        IluWork ilu;
        LineWork lines;
        bool self_joined = false;  // some join pairs two of its own sides' nodes (an O- or C-grid's cut)
        std::size_t at(int i, int j) const {  // block node (i, j), -1 <= i <= ni
            return static_cast<std::size_t>(i + 1) + static_cast<std::size_t>(ni + 2) * static_cast<std::size_t>(j + 1);
        }
        Level level() const;
        // Coarse levels: v (a field of `fine`, of which this is the coarse
        // block) interpolated at coarse node (I, J).
        double sampled(const Block &fine, const double *v, int I, int J) const;
        // The operator's scale under this coarsening at (I, J) (the single
        // block's operator_scale): (si sj)^2 for Winslow, si sj for Laplace.
        double scale(System system, int I, int J) const {
            const double s = ai.h[static_cast<std::size_t>(I)] * aj.h[static_cast<std::size_t>(J)];
            return system == System::Winslow ? s * s : s;
        }
        // f(stencil) at every node this block solves within columns i0..i1
        // and rows j0..j1 of the extended frame (default: all of them).
        template <class F>
        void each_unknown(F &&f, int i0 = 1, int i1 = -1, int j0 = 1, int j1 = -1) const {
            for (int j = j0; j <= (j1 < 0 ? nj : j1); ++j)
                for (int i = i0; i <= (i1 < 0 ? ni : i1); ++i) {
                    const Stencil s = conn.stencil(i, j);
                    if (role[static_cast<std::size_t>(s.c)] == kUnknown) f(s);
                }
        }
        // One point Gauss-Seidel/SOR step at the node of s.
        void relax(System system, const Level &L, const Stencil &s, double omega) {
            const NodeEquation eq = node_equation(system, L, s);
            x[static_cast<std::size_t>(s.c)] += omega * eq.rx / eq.diag;
            y[static_cast<std::size_t>(s.c)] += omega * eq.ry / eq.diag;
        }
    };
    // Node `dst` of block `to` holds node `src` of block `from`.
    struct Link {
        int from;
        std::size_t src;
        int to;
        std::size_t dst;
    };
    using Field = std::vector<double> Block::*;
    void copy(const Link &l, Field f) {
        (blocks_[static_cast<std::size_t>(l.to)].*f)[l.dst] = (blocks_[static_cast<std::size_t>(l.from)].*f)[l.src];
    }
    void sync(Field a, Field b);
    // After block b moved: its copies, then the halos that read it or a copy.
    void sync_from(std::size_t b);
    std::vector<Join> joins_;
    std::vector<Block> blocks_;
    std::vector<Link> copies_, halos_;  // copies first: a halo may read a copy
    struct Node {
        int block;
        std::size_t k;  // extended index
    };
    struct Vertex {
        std::vector<Node> copies;      // the vertex in each block that has it
        std::vector<Node> neighbours;  // one node per grid line leaving it
        double fx = 0.0, fy = 0.0;     // FAS right-hand side (coarse levels)
        double x0 = 0.0, y0 = 0.0;     // coarse levels: as sampled
    };
    // The mean of a vertex's neighbours less the vertex, less f.
    void vertex_equation(const Vertex &v, double &rx, double &ry) const;
    std::vector<Vertex> vertices_;       // the free ones
    std::vector<Vertex> held_vertices_;  // on the domain's boundary (no neighbours kept): local sweeps only
    void find_vertices();
    double vertex_residual() const;  // the largest |vertex_equation|
    long unknowns_ = 0;
    Snapshot saved_;  // the guarded sweep's (save, restore, move)
};

}  // namespace eg2d
