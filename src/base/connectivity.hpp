// Which nodes are unknowns and who their neighbours are, per topology.
// Every solver and the operator reach neighbours only through stencil(), so a
// topology (O-grid branch cut, C-grid wake cut) is defined once, here.
#pragma once
#include <cstddef>
#include <vector>

#include "base/table.hpp"

namespace eg2d {

enum class Topology { Single = 0, O = 1, C = 2 };

const char *topology_name(Topology t);  // for messages: "O-grid"
Table<NamedId> topology_table();         // EG2D_TOPO_*, by list name: "o"

// Array indices (k = i + ni*j) of a node and its eight neighbours.
struct Stencil {
    std::ptrdiff_t c, e, w, n, s, ne, nw, se, sw;
};

class Connectivity {
public:
    Connectivity(int ni, int nj, Topology topology) : ni_(ni), nj_(nj), topology_(topology) {}
    // C-grid with a wake cut: JMIN nodes i = 0..wake run along the lower wake
    // from the outflow to the trailing edge (i = wake), and node (i, 0) is the
    // same point as (ni-1-i, 0) on the upper wake. Nodes (i, 0), 0 < i < wake,
    // are unknowns whose south neighbours lie across the cut in row j = 1 of
    // the upper half; the upper copies are kept equal by sync_node.
    // wake = 0: the cut is not known yet (no unknowns on it).
    Connectivity(int ni, int nj, Topology topology, int wake);

    int ni() const { return ni_; }
    int nj() const { return nj_; }
    Topology topology() const { return topology_; }
    bool periodic_i() const { return topology_ == Topology::O; }

    // Unknown nodes are i in [i_begin, i_end) x j in [j_begin, j_end).
    // O-grid: column ni-1 duplicates column 0 (kept equal by sync_node).
    int i_begin() const { return periodic_i() ? 0 : 1; }
    int i_end() const { return ni_ - 1; }
    int j_begin() const { return j_first_; }
    int j_end() const { return nj_ - 1; }
    // Unknown nodes outside that rectangle (the C-grid's wake cut), solved
    // pointwise by every solver and counted by the residual. Empty for the
    // single-block and O topologies.
    struct Node { int i, j; };
    const std::vector<Node> &extra_unknowns() const { return extra_; }
    // Number of distinct columns in i (ni-1 on a periodic grid).
    int i_period() const { return ni_ - 1; }
    // The connectivity of the grid coarsened by si in i and sj in j (every
    // si-th column, every sj-th row), for multigrid: a C-grid keeps its cut
    // up to the last coarse column at or before the trailing edge (wake/si,
    // rounded down). When the edge falls between coarse columns, the coarse
    // grid holds the cut node next to it fixed, an error of one fine cell
    // there; a coarse cut held fixed as a whole cannot correct the cut's
    // sliding at all (measured: NACA0012 C-grid 129x33 with a wake of 31,
    // 94 cycles at 0.84 per cycle against 7 at 0.11).
    Connectivity coarsened(int si, int sj) const {
        const int wake = (topology_ == Topology::C) ? wake_ / si : 0;
        return Connectivity((ni_ - 1) / si + 1, (nj_ - 1) / sj + 1, topology_, wake);
    }
    // C-grid: the trailing-edge index on JMIN (0 for the other topologies,
    // and for a C-grid whose cut lies in held rows).
    int wake() const { return wake_; }
    // The same grid with rows 0..rows held fixed (a wall layer made before
    // the solve): the unknowns start at row rows + 1. A C-grid's cut lies in
    // the held rows then, so it has no unknowns and no wake: the rows above
    // form one block, non-periodic in i.
    Connectivity held_below(int rows) const {
        Connectivity c(ni_, nj_, topology_, rows > 0 ? 0 : wake_);
        c.j_first_ = rows + 1;
        c.fixed_i_ = fixed_i_;
        c.fixed_j_ = fixed_j_;
        c.fixed_mask_ = fixed_mask_;
        return c;
    }
    // The same grid with interior lines held fixed (eg2d_set_interior_line):
    // whole columns i and rows j whose nodes are Dirichlet nodes inside the
    // unknowns' rectangle. The operator gives them R = 0 with a unit
    // diagonal and no coupling, so every point, line and ILU kernel leaves
    // them where they are while their neighbours see them as boundary.
    Connectivity with_fixed(const std::vector<int> &columns, const std::vector<int> &rows) const;
    // The same with single nodes held too (mask: ni*nj, nonzero = held): a
    // set of blocks' joined nodes that another block solves, its vertices
    // and the boundary's nodes in the unknowns' rectangle (blocks/composite).
    Connectivity with_fixed_nodes(const std::vector<char> &mask) const;
    bool has_fixed() const { return !fixed_mask_.empty(); }
    bool fixed(int i, int j) const { return has_fixed() && fixed_mask_[static_cast<std::size_t>(i) + static_cast<std::size_t>(ni_) * static_cast<std::size_t>(j)]; }
    bool fixed_node(std::ptrdiff_t k) const { return has_fixed() && fixed_mask_[static_cast<std::size_t>(k)]; }
    // The fixed columns and rows in increasing order.
    std::vector<int> fixed_columns() const { return marked(fixed_i_); }
    std::vector<int> fixed_rows() const { return marked(fixed_j_); }
    // Rows held fixed above row 0 (0: none).
    int held_rows() const { return j_first_ - 1; }
    // C-grid: is (i, 0) a wake node solved for (0 < i < wake)?
    bool on_cut(int i, int j) const { return j == 0 && i > 0 && i < wake_; }

    Stencil stencil(int i, int j) const {
        int iw = i - 1, ie = i + 1;
        if (periodic_i()) {
            if (iw < 0) iw = ni_ - 2;  // across the cut: column ni-1 is column 0
            if (ie > ni_ - 1) ie = 1;
        }
        const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(ni_) * j;
        const std::ptrdiff_t up = row + ni_, down = row - ni_;
        if (on_cut(i, j)) {
            // Across the wake cut: "row -1" of the lower half is row 1 of the
            // upper half, read in reversed i (column i-1 there is ni-i, ...).
            const std::ptrdiff_t m = ni_ - 1;
            return Stencil{row + i, row + ie, row + iw, up + i, up + (m - i),
                           up + ie, up + iw, up + (m - ie), up + (m - iw)};
        }
        return Stencil{row + i, row + ie, row + iw, up + i, down + i,
                       up + ie, up + iw, down + ie, down + iw};
    }

    // After writing node (i, j), copy it to the node that stores the same point.
    void sync_node(double *f, int i, int j) const {
        if (periodic_i() && i == 0) {
            const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(ni_) * j;
            f[row + ni_ - 1] = f[row];
        } else if (on_cut(i, j)) {
            f[ni_ - 1 - i] = f[i];
        }
    }
    // The same for a whole field.
    void sync(double *f) const;

private:
    int ni_, nj_;
    Topology topology_;
    int wake_ = 0;
    int j_first_ = 1;
    std::vector<Node> extra_;
    std::vector<char> fixed_i_, fixed_j_;  // per column / row: held fixed (both empty: none)
    std::vector<char> fixed_mask_;         // per node: the rows', columns' and single nodes' (empty: none)
    static std::vector<int> marked(const std::vector<char> &m);
};

}  // namespace eg2d
