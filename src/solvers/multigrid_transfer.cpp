// Grid transfers of the FAS multigrid: injection (coordinates, controls),
// full weighting (residuals), bilinear interpolation (corrections). A
// direction with factor 1 (semicoarsening) is copied as it is.
#include <cstddef>
#include <vector>

#include "solvers/multigrid_hierarchy.hpp"

namespace eg2d {

void inject(const Connectivity &fine_conn, const double *src, const MgLevel &coarse, double *dst) {
    const std::ptrdiff_t nif = fine_conn.ni(), nic = coarse.conn.ni(), njc = coarse.conn.nj();
    const std::ptrdiff_t si = coarse.si, sj = coarse.sj;
    for (std::ptrdiff_t J = 0; J < njc; ++J) {
        const double *row = src + nif * sj * J;
        double *out = dst + nic * J;
        if (si == 2)
            for (std::ptrdiff_t I = 0; I < nic; ++I) out[I] = row[2 * I];
        else
            for (std::ptrdiff_t I = 0; I < nic; ++I) out[I] = row[I];
    }
}

void full_weighting(const Connectivity &fc, const double *src, const MgLevel &coarse, double scale, double *dst) {
    const Connectivity &cc = coarse.conn;
    const std::ptrdiff_t nif = fc.ni(), nic = cc.ni();
    const int si = coarse.si, sj = coarse.sj;
    const bool periodic = fc.periodic_i();
    const std::ptrdiff_t period = fc.i_period();
    // 1D weights (1/4, 1/2, 1/4) per coarsened direction, (0, 1, 0) otherwise.
    const double wi[3] = {si == 2 ? 0.25 : 0.0, si == 2 ? 0.5 : 1.0, si == 2 ? 0.25 : 0.0};
    const double wj[3] = {sj == 2 ? 0.25 : 0.0, sj == 2 ? 0.5 : 1.0, sj == 2 ? 0.25 : 0.0};
    for (int J = cc.j_begin(); J < cc.j_end(); ++J) {
        const std::ptrdiff_t jf = static_cast<std::ptrdiff_t>(sj) * J;
        for (int I = cc.i_begin(); I < cc.i_end(); ++I) {
            const std::ptrdiff_t ifc = static_cast<std::ptrdiff_t>(si) * I;
            std::ptrdiff_t col[3] = {ifc - 1, ifc, ifc + 1};
            if (periodic) {
                if (col[0] < 0) col[0] += period;
                if (col[2] >= period) col[2] -= period;
            }
            double sum = 0.0;
            for (int b = 0; b < 3; ++b) {
                if (wj[b] == 0.0) continue;
                const std::ptrdiff_t row = nif * (jf + b - 1);
                for (int a = 0; a < 3; ++a)
                    if (wi[a] != 0.0) sum += wi[a] * wj[b] * src[row + col[a]];
            }
            dst[I + nic * J] = scale * sum;
        }
    }
}

void restrict_residual(const MgLevel &fine, const MgLevel &coarse, double scale, double *out_x, double *out_y) {
    full_weighting(fine.conn, fine.rx.data(), coarse, scale, out_x);
    full_weighting(fine.conn, fine.ry.data(), coarse, scale, out_y);
    // Coarse nodes off the rectangle (a C-grid's wake cut): the same weights
    // over the fine node's stencil, whose "south" lies across the cut.
    const double wi0 = coarse.si == 2 ? 0.25 : 0.0, wi1 = coarse.si == 2 ? 0.5 : 1.0;
    const double wj0 = coarse.sj == 2 ? 0.25 : 0.0, wj1 = coarse.sj == 2 ? 0.5 : 1.0;
    for (const Connectivity::Node &p : coarse.conn.extra_unknowns()) {
        const Stencil f = fine.conn.stencil(coarse.si * p.i, coarse.sj * p.j);
        auto weigh = [&](const std::vector<double> &r) {
            return wi1 * wj1 * r[f.c] + wi0 * wj1 * (r[f.e] + r[f.w]) + wi1 * wj0 * (r[f.n] + r[f.s]) +
                   wi0 * wj0 * (r[f.ne] + r[f.nw] + r[f.se] + r[f.sw]);
        };
        const std::ptrdiff_t k = p.i + static_cast<std::ptrdiff_t>(coarse.conn.ni()) * p.j;
        out_x[k] = scale * weigh(fine.rx);
        out_y[k] = scale * weigh(fine.ry);
    }
}

void prolong_correction(const MgLevel &coarse, const Level &fine) {
    const Connectivity &fc = *fine.conn, &cc = coarse.conn;
    const std::ptrdiff_t nif = fc.ni(), nic = cc.ni();
    const int si = coarse.si, sj = coarse.sj;
    const double *xc = coarse.x.data(), *yc = coarse.y.data(), *x0 = coarse.x0.data(), *y0 = coarse.y0.data();
    for (int j = fc.j_begin(); j < fc.j_end(); ++j) {
        // Coarse rows J0 (weight wj0) and J1 = J0 + 1 (weight 1 - wj0) around row j.
        const std::ptrdiff_t J0 = j / sj;
        const double wj0 = (j % sj == 0) ? 1.0 : 0.5;
        const std::ptrdiff_t r0 = nic * J0, r1 = wj0 < 1.0 ? r0 + nic : r0;
        double *x = fine.x + nif * j, *y = fine.y + nif * j;
        for (int i = fc.i_begin(); i < fc.i_end(); ++i) {
            const std::ptrdiff_t I0 = i / si;
            const double wi0 = (i % si == 0) ? 1.0 : 0.5;
            const std::ptrdiff_t I1 = wi0 < 1.0 ? I0 + 1 : I0;
            const double w00 = wi0 * wj0, w10 = (1.0 - wi0) * wj0, w01 = wi0 * (1.0 - wj0),
                         w11 = (1.0 - wi0) * (1.0 - wj0);
            x[i] += w00 * (xc[r0 + I0] - x0[r0 + I0]) + w10 * (xc[r0 + I1] - x0[r0 + I1]) +
                    w01 * (xc[r1 + I0] - x0[r1 + I0]) + w11 * (xc[r1 + I1] - x0[r1 + I1]);
            y[i] += w00 * (yc[r0 + I0] - y0[r0 + I0]) + w10 * (yc[r0 + I1] - y0[r0 + I1]) +
                    w01 * (yc[r1 + I0] - y0[r1 + I0]) + w11 * (yc[r1 + I1] - y0[r1 + I1]);
        }
        fc.sync_node(fine.x, 0, j);
        fc.sync_node(fine.y, 0, j);
    }
    // Fine nodes off the rectangle (a C-grid's wake cut, row 0): linear along
    // the coarse row 0, whose cut nodes carry the coarse correction (zero
    // where the coarse grid keeps the cut fixed).
    for (const Connectivity::Node &p : fc.extra_unknowns()) {
        const std::ptrdiff_t I0 = p.i / si, r0 = nic * (p.j / sj);
        const double w0 = (p.i % si == 0) ? 1.0 : 0.5;
        const std::ptrdiff_t I1 = w0 < 1.0 ? I0 + 1 : I0;
        const std::ptrdiff_t k = p.i + nif * p.j;
        fine.x[k] += w0 * (xc[r0 + I0] - x0[r0 + I0]) + (1.0 - w0) * (xc[r0 + I1] - x0[r0 + I1]);
        fine.y[k] += w0 * (yc[r0 + I0] - y0[r0 + I0]) + (1.0 - w0) * (yc[r0 + I1] - y0[r0 + I1]);
        fc.sync_node(fine.x, p.i, p.j);
        fc.sync_node(fine.y, p.i, p.j);
    }
}

}  // namespace eg2d
