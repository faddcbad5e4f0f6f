#include "solvers/coarse_axis.hpp"

#include <algorithm>
#include <cmath>

namespace eg2d {

namespace {

std::vector<int> sorted_anchors(int n, std::vector<int> anchors) {
    anchors.push_back(0);
    anchors.push_back(n - 1);
    std::sort(anchors.begin(), anchors.end());
    anchors.erase(std::unique(anchors.begin(), anchors.end()), anchors.end());
    anchors.erase(std::remove_if(anchors.begin(), anchors.end(), [n](int a) { return a < 0 || a > n - 1; }),
                  anchors.end());
    return anchors;
}

// Coarse cells for a segment of L fine cells: ceil(L/2).
int segment_cells(int L) { return (L + 1) / 2; }

// Fills h and the transfer tables from pos.
void fill_tables(CoarseAxis &a) {
    const int nf = a.nf, nc = a.nc;
    const double period = nf - 1;
    auto left = [&](int I) {  // the position of the coarse node before I
        if (I > 0) return a.pos[I - 1];
        return a.periodic ? a.pos[nc - 2] - period : -a.pos[1];
    };
    auto right = [&](int I) {
        if (I < nc - 1) return a.pos[I + 1];
        return a.periodic ? a.pos[1] + period : 2.0 * a.pos[nc - 1] - a.pos[nc - 2];
    };
    a.h.resize(nc);
    for (int I = 0; I < nc; ++I) a.h[I] = 0.5 * (right(I) - left(I));
    // Interpolation to the fine nodes: the coarse cell [pos[I], pos[I+1]] holding i.
    a.up_lo.resize(nf);
    a.up_t.resize(nf);
    for (int i = 0, I = 0; i < nf; ++i) {
        while (I < nc - 2 && a.pos[I + 1] <= i) ++I;
        a.up_lo[i] = I;
        a.up_t[i] = (i - a.pos[I]) / (a.pos[I + 1] - a.pos[I]);
    }
    // Sampling the fine grid at the coarse nodes.
    a.dn_lo.resize(nc);
    a.dn_t.resize(nc);
    for (int I = 0; I < nc; ++I) {
        const int lo = std::min(static_cast<int>(std::floor(a.pos[I])), nf - 2);
        a.dn_lo[I] = lo;
        a.dn_t[I] = a.pos[I] - lo;
    }
    // Full weighting: the hat of coarse node I at the fine nodes inside its
    // support (the transpose of the interpolation), normalised to sum 1.
    a.r_start.assign(1, 0);
    a.r_idx.clear();
    a.r_w.clear();
    for (int I = 0; I < nc; ++I) {
        const double l = left(I), c = a.pos[I], r = right(I);
        const std::size_t first = a.r_idx.size();
        double sum = 0.0;
        for (int i = static_cast<int>(std::floor(l)) + 1; i < r; ++i) {
            if (i <= l) continue;
            const double w = i <= c ? (i - l) / (c - l) : (r - i) / (r - c);
            int k = i;
            if (a.periodic) k = ((k % (nf - 1)) + (nf - 1)) % (nf - 1);
            else if (k > nf - 1 || k < -1) continue;
            a.r_idx.push_back(k);
            a.r_w.push_back(w);
            sum += w;
        }
        for (std::size_t k = first; k < a.r_w.size(); ++k) a.r_w[k] /= sum;
        a.r_start.push_back(static_cast<int>(a.r_idx.size()));
    }
}

}  // namespace

int CoarseAxis::nearest(int i) const {
    int best = 0;
    for (int I = 1; I < nc; ++I)
        if (std::fabs(pos[I] - i) < std::fabs(pos[best] - i)) best = I;
    return best;
}

CoarseAxis identity_axis(int n, bool periodic) { return make_axis(n, periodic, {}, false); }

int coarse_count(int n, std::vector<int> anchors) {
    anchors = sorted_anchors(n, std::move(anchors));
    int cells = 0;
    for (std::size_t k = 1; k < anchors.size(); ++k) cells += segment_cells(anchors[k] - anchors[k - 1]);
    return cells + 1;
}

CoarseAxis make_axis(int n, bool periodic, std::vector<int> anchors, bool coarsen) {
    CoarseAxis a;
    a.nf = n;
    a.periodic = periodic;
    if (!coarsen) {
        a.nc = n;
        a.pos.resize(n);
        for (int i = 0; i < n; ++i) a.pos[i] = i;
    } else {
        anchors = sorted_anchors(n, std::move(anchors));
        a.pos.push_back(0.0);
        for (std::size_t k = 1; k < anchors.size(); ++k) {
            const int from = anchors[k - 1], L = anchors[k] - from, m = segment_cells(L);
            // Exact where L is even: every other fine node.
            for (int q = 1; q <= m; ++q) a.pos.push_back(q == m ? anchors[k] : from + static_cast<double>(q) * L / m);
        }
        a.nc = static_cast<int>(a.pos.size());
    }
    fill_tables(a);
    return a;
}

}  // namespace eg2d
