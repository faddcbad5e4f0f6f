// Grid: the node coordinates (Fortran order), the topology and which parts of
// the boundary ring the user has given. Coordinates are checked here so that
// nothing downstream sees NaN, Inf or a boundary whose corners disagree.
#pragma once
#include <cstddef>
#include <array>
#include <vector>

#include "base/connectivity.hpp"
#include "base/interior_lines.hpp"
#include "base/patches.hpp"

namespace eg2d {

enum class Side { JMin = 0, IMax = 1, JMax = 2, IMin = 3 };
const char *side_name(Side s);

class Grid {
public:
    // Throws Failure::Argument for ni or nj < 3 or a node count that
    // overflows, Failure::Memory when the arrays cannot be allocated.
    Grid(int ni, int nj);

    int ni() const { return ni_; }
    int nj() const { return nj_; }
    std::size_t size() const { return x.size(); }
    Topology topology() const { return connectivity_.topology(); }
    const Connectivity &connectivity() const { return connectivity_; }

    // Forgets boundary and interior (the sides a topology has differ).
    void set_topology(Topology t);

    // Number of points of a side, and whether the topology has that side.
    int side_length(Side s) const;
    bool has_side(Side s) const;
    bool side_set(Side s) const { return (sides_set_ >> static_cast<int>(s)) & 1u; }
    // Node p of side s as the user set it (the grid's own node where the
    // side is not set): a set of blocks moves its joined nodes.
    double given_x(Side s, int p) const;
    double given_y(Side s, int p) const;
    bool boundary_complete() const;

    // Strong guarantee: on a throw nothing changed.
    void set_side(Side s, const double *px, const double *py);
    void set_boundary(const double *px, const double *py);   // ring of ni*nj arrays
    void set_coordinates(const double *px, const double *py);  // whole grid

    // Whether every side of the topology is set and holds, as set, the
    // points of the ring px, py (ni*nj arrays).
    bool boundary_is(const double *px, const double *py) const;

    // Puts the user's points back on every set side. Solving moves some of
    // them (a C-grid's wake cut is solved for, sliding sides slide), and a
    // new start must begin from the boundary as set, as a fresh handle does.
    void restore_boundary();

    // The points of side s (side_length(s) each, in increasing index) out
    // of any ni*nj arrays: x, y or a caller's ring.
    void read_side(Side s, const double *fx, const double *fy, std::vector<double> &px,
                   std::vector<double> &py) const;

    // Rows 1..rows are held fixed by the solvers (a wall layer made before
    // the solve); 0 releases them. Throws Argument unless 0 <= rows <= nj-3.
    void hold_rows(int rows);

    // Interior lines (base/interior_lines.hpp; interior_lines.cpp): a line
    // of the same family and index is replaced. Throws Argument for an
    // index outside [1, n-2], a column on an O- or C-grid (Unsupported), an
    // open row of an O-grid, non-finite points, or ends or crossings that
    // disagree with what is set (check_interior_lines). Strong guarantee.
    void set_interior_line(bool xi, int index, const double *px, const double *py);
    void clear_interior_lines();
    const std::vector<InteriorLine> &interior_lines() const { return lines_; }
    // Throws Boundary unless every line's ends lie on the boundary nodes
    // they meet and crossing lines share their crossing node (1e-8 of the
    // boundary's size); sides not set yet are not checked.
    void check_interior_lines() const;
    // Writes the lines' nodes (ends excluded: they are the boundary's).
    void restore_interior_lines();
    int held_rows() const { return held_rows_; }

    bool initialized() const { return initialized_; }
    void mark_initialized() { initialized_ = true; }

    // C-grid: the trailing-edge index on JMIN read when JMIN was set (0 while
    // it is not, and for the other topologies), whatever rows are held.
    int cut_wake() const { return base_connectivity_.wake(); }

    // The user's boundary patches (base/patches.hpp: with_patch checks them,
    // resolve_patches completes them); forgotten with the topology.
    std::vector<Patch> patches;

    // The user's first-cell heights node by node along each side
    // (eg2d_set_wall_spacing_nodes; empty: the side's one height, if any);
    // forgotten with the topology.
    std::array<std::vector<double>, 4> wall_node_spacing;
    // Side s's height at its node k: its own there, else `one` (the side's one height).
    double wall_height_at(Side s, int k, double one) const {
        const std::vector<double> &v = wall_node_spacing[static_cast<std::size_t>(s)];
        return v.size() == static_cast<std::size_t>(side_length(s)) ? v[static_cast<std::size_t>(k)] : one;
    }

    // Diagonal of the bounding box of the boundary ring: the L of NUMERICS.md.
    double extent() const;

    // Node coordinates, ni*nj each. Solvers write them; the boundary ring
    // holds the user's points whenever side_set says so.
    std::vector<double> x, y;

private:
    void check_corners(Side s, const double *px, const double *py) const;
    void check_closed(Side s, const double *px, const double *py, int n) const;
    // C-grid: the trailing-edge index of a JMIN side (throws Boundary).
    int detect_wake(const double *px, const double *py) const;
    // A side's points (side_length(s) each) into x, y.
    void write_side(Side s, const double *px, const double *py);

    int ni_, nj_;
    Connectivity base_connectivity_;  // the topology's, no rows held
    Connectivity connectivity_;       // with the held rows
    int held_rows_ = 0;
    std::vector<InteriorLine> lines_;
    // connectivity_ from base_connectivity_, the held rows and the lines.
    void rebuild_connectivity();
    unsigned sides_set_ = 0;
    std::vector<double> user_x_[4], user_y_[4];  // each set side's points as set_side wrote them
    bool initialized_ = false;
};

// Indices (i, j) of the p-th node of side s (increasing index along the
// side), or of the node `depth` lines into the domain from it, on an
// ni x nj grid. The one place that maps sides to indices.
struct NodeIJ {
    int i, j;
};
inline NodeIJ side_ij(int ni, int nj, Side s, int p, int depth = 0) {
    switch (s) {
    case Side::JMin: return {p, depth};
    case Side::JMax: return {p, nj - 1 - depth};
    case Side::IMin: return {depth, p};
    case Side::IMax: return {ni - 1 - depth, p};
    }
    return {0, 0};
}

// Array index of node (i, j) of a grid ni wide.
inline std::size_t node_index(int ni, int i, int j) {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * static_cast<std::size_t>(j);
}

// Array index of the same node.
inline std::size_t side_node(int ni, int nj, Side s, int p, int depth = 0) {
    const NodeIJ n = side_ij(ni, nj, s, p, depth);
    return static_cast<std::size_t>(n.i) + static_cast<std::size_t>(ni) * static_cast<std::size_t>(n.j);
}
inline std::size_t side_node(const Grid &g, Side s, int p, int depth = 0) {
    return side_node(g.ni(), g.nj(), s, p, depth);
}

// Relative tolerance on the domain size for points that must coincide
// (corners of adjacent sides, an interior line's ends).
constexpr double kCornerTolerance = 1e-8;

// Largest coordinate magnitude accepted: J^2 grows as the fourth power of the
// coordinates, so much larger values would overflow the metric terms.
constexpr double kMaxCoordinate = 1e30;

// Checks every value is finite and within +-kMaxCoordinate; names the array
// and the first bad index.
void check_coordinates(const char *what, const double *v, std::size_t n);

}  // namespace eg2d
