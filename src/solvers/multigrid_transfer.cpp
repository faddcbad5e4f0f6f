// Grid transfers of the FAS multigrid: sampling (coordinates, controls), full
// weighting (residuals), bilinear interpolation (corrections), all from the
// 1-D tables of coarse_axis.hpp. A direction that is not coarsened has
// identity tables.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "solvers/multigrid_hierarchy.hpp"

namespace eg2d {

namespace {
using Index = std::ptrdiff_t;
}

void inject(const Connectivity &fine_conn, const double *src, const MgLevel &coarse, double *dst) {
    const Index nif = fine_conn.ni(), nic = coarse.conn.ni(), njc = coarse.conn.nj();
    const CoarseAxis &ai = coarse.ai, &aj = coarse.aj;
    for (Index J = 0; J < njc; ++J) {
        const Index j0 = aj.dn_lo[J];
        const double tj = aj.dn_t[J];
        const double *r0 = src + nif * j0, *r1 = tj > 0.0 ? r0 + nif : r0;
        double *out = dst + nic * J;
        for (Index I = 0; I < nic; ++I) {
            const Index i0 = ai.dn_lo[I];
            const double ti = ai.dn_t[I];
            if (ti == 0.0 && tj == 0.0) {  // a fine node: exact, as the classical injection
                out[I] = r0[i0];
                continue;
            }
            out[I] = (1.0 - tj) * ((1.0 - ti) * r0[i0] + ti * r0[i0 + 1]) + tj * ((1.0 - ti) * r1[i0] + ti * r1[i0 + 1]);
        }
    }
}

void restrict_residual(System system, const MgLevel &fine, const MgLevel &coarse, double *out_x, double *out_y) {
    const Connectivity &fc = fine.conn, &cc = coarse.conn;
    const Index nif = fc.ni(), nic = cc.ni();
    const CoarseAxis &ai = coarse.ai, &aj = coarse.aj;
    const double *rx = fine.rx.data(), *ry = fine.ry.data();
    for (int J = cc.j_begin(); J < cc.j_end(); ++J)
        for (int I = cc.i_begin(); I < cc.i_end(); ++I) {
            double sx = 0.0, sy = 0.0;
            for (int b = aj.r_start[J]; b < aj.r_start[J + 1]; ++b) {
                const Index row = nif * aj.r_idx[b];
                for (int a = ai.r_start[I]; a < ai.r_start[I + 1]; ++a) {
                    const double w = aj.r_w[b] * ai.r_w[a];
                    sx += w * rx[row + ai.r_idx[a]];
                    sy += w * ry[row + ai.r_idx[a]];
                }
            }
            const double s = operator_scale(system, coarse, I, J);
            out_x[I + nic * J] = s * sx;
            out_y[I + nic * J] = s * sy;
        }
    // Coarse nodes off the rectangle (a C-grid's wake cut, row 0): the same
    // weights, with the fine row "-1" across the cut (row 1 of the other
    // half, reversed in i: the fine stencil's south).
    for (const Connectivity::Node &p : cc.extra_unknowns()) {
        double sx = 0.0, sy = 0.0;
        for (int b = aj.r_start[p.j]; b < aj.r_start[p.j + 1]; ++b)
            for (int a = ai.r_start[p.i]; a < ai.r_start[p.i + 1]; ++a) {
                const int i = ai.r_idx[a], j = aj.r_idx[b];
                const Index k = j >= 0 ? i + nif * j : fc.stencil(i, 0).s;
                const double w = aj.r_w[b] * ai.r_w[a];
                sx += w * rx[k];
                sy += w * ry[k];
            }
        const double s = operator_scale(system, coarse, p.i, p.j);
        out_x[p.i + nic * p.j] = s * sx;
        out_y[p.i + nic * p.j] = s * sy;
    }
}

std::vector<Connectivity::Node> coarse_nodes(const std::vector<Connectivity::Node> &fine, const MgLevel &coarse) {
    std::vector<Connectivity::Node> out;
    for (const Connectivity::Node &n : fine) {
        const Connectivity::Node c{coarse.ai.nearest(n.i), coarse.aj.nearest(n.j)};
        if (std::none_of(out.begin(), out.end(), [&](const Connectivity::Node &o) { return o.i == c.i && o.j == c.j; }))
            out.push_back(c);
    }
    return out;
}

void prolong_correction(const MgLevel &coarse, const Level &fine) {
    const Connectivity &fc = *fine.conn, &cc = coarse.conn;
    const Index nif = fc.ni(), nic = cc.ni();
    const CoarseAxis &ai = coarse.ai, &aj = coarse.aj;
    const double *xc = coarse.x.data(), *yc = coarse.y.data(), *x0 = coarse.x0.data(), *y0 = coarse.y0.data();
    for (int j = fc.j_begin(); j < fc.j_end(); ++j) {
        // Coarse rows J0 (weight 1 - tj) and J0 + 1 (weight tj) around row j.
        const Index J0 = aj.up_lo[j];
        const double tj = aj.up_t[j];
        const Index r0 = nic * J0, r1 = tj > 0.0 ? r0 + nic : r0;
        double *x = fine.x + nif * j, *y = fine.y + nif * j;
        for (int i = fc.i_begin(); i < fc.i_end(); ++i) {
            const Index I0 = ai.up_lo[i];
            const double ti = ai.up_t[i];
            const Index I1 = ti > 0.0 ? I0 + 1 : I0;
            const double w00 = (1.0 - ti) * (1.0 - tj), w10 = ti * (1.0 - tj), w01 = (1.0 - ti) * tj, w11 = ti * tj;
            x[i] += w00 * (xc[r0 + I0] - x0[r0 + I0]) + w10 * (xc[r0 + I1] - x0[r0 + I1]) +
                    w01 * (xc[r1 + I0] - x0[r1 + I0]) + w11 * (xc[r1 + I1] - x0[r1 + I1]);
            y[i] += w00 * (yc[r0 + I0] - y0[r0 + I0]) + w10 * (yc[r0 + I1] - y0[r0 + I1]) +
                    w01 * (yc[r1 + I0] - y0[r1 + I0]) + w11 * (yc[r1 + I1] - y0[r1 + I1]);
        }
        fc.sync_node(fine.x, 0, j);
        fc.sync_node(fine.y, 0, j);
    }
    // Fine nodes off the rectangle (a C-grid's wake cut, row 0): linear along
    // the coarse row 0, whose cut nodes carry the coarse correction (zero at
    // the outflow and at the trailing edge, which stay fixed).
    for (const Connectivity::Node &p : fc.extra_unknowns()) {
        const Index I0 = ai.up_lo[p.i];
        const double t = ai.up_t[p.i];
        const Index I1 = t > 0.0 ? I0 + 1 : I0;
        const Index k = p.i + nif * p.j;
        fine.x[k] += (1.0 - t) * (xc[I0] - x0[I0]) + t * (xc[I1] - x0[I1]);
        fine.y[k] += (1.0 - t) * (yc[I0] - y0[I0]) + t * (yc[I1] - y0[I1]);
        fc.sync_node(fine.x, p.i, p.j);
        fc.sync_node(fine.y, p.i, p.j);
    }
}

}  // namespace eg2d
