// One direction of a coarse multigrid level, for any node count.
//
// The coarse nodes sit at real positions in the finer level's index space:
// between anchors (the ends, and a C-grid's trailing edges) a segment of L
// fine cells becomes ceil(L/2) coarse cells of equal length L/ceil(L/2), in
// (1, 2]. Each coarse level is thus uniform in its own index (the operator,
// written in index units, needs no change) and within 5% of a factor 2
// everywhere (L >= 10); where L is even the coarse nodes are every other fine
// node, as in the classical nested hierarchy. Transfers are the linear
// interpolation between the two grids and its transpose (full weighting),
// in the spirit of the non-nested coarsening of Trottenberg, Oosterlee &
// Schueller, "Multigrid" (2001), sec. 7.7; injection samples the finer grid
// by the same interpolation.
#pragma once
#include <vector>

namespace eg2d {

struct CoarseAxis {
    int nf = 0, nc = 0;       // fine and coarse node counts
    bool periodic = false;    // node n-1 is node 0 (an O-grid's xi)
    std::vector<double> pos;  // nc: fine index of coarse node I
    std::vector<double> h;    // nc: fine cells per coarse cell around I (1 if not coarsened)
    // Interpolation to fine node i: (1 - up_t[i]) * coarse[up_lo[i]] + up_t[i] * coarse[up_lo[i] + 1].
    std::vector<int> up_lo;
    std::vector<double> up_t;
    // Sampling at coarse node I: (1 - dn_t[I]) * fine[dn_lo[I]] + dn_t[I] * fine[dn_lo[I] + 1].
    std::vector<int> dn_lo;
    std::vector<double> dn_t;
    // Full weighting at coarse node I: fine nodes r_idx[k], weights r_w[k] (sum 1),
    // k in [r_start[I], r_start[I+1]). Periodic indices are wrapped into
    // [0, nf-1); at a non-periodic end the hat is mirrored, which gives the
    // index -1 (across a C-grid's wake cut: its caller maps it).
    std::vector<int> r_start, r_idx;
    std::vector<double> r_w;

    bool coarsened() const { return nc != nf; }
    // The coarse node nearest to fine index i.
    int nearest(int i) const;
};

// The same nodes, transfers the identity (a direction left as it is).
CoarseAxis identity_axis(int n, bool periodic);

// Coarse nodes for n fine nodes with the given anchors (fine indices that stay
// nodes; 0 and n-1 are added), or the identity when `coarsen` is false.
CoarseAxis make_axis(int n, bool periodic, std::vector<int> anchors, bool coarsen);

// The coarse node count make_axis would give (for deciding whether to coarsen).
int coarse_count(int n, std::vector<int> anchors);

}  // namespace eg2d
