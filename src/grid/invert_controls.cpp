#include "grid/invert_controls.hpp"

namespace eg2d {

void invert_grid_controls(const Grid &g, int j0, std::vector<double> &phi, std::vector<double> &psi) {
    const int ni = g.ni(), nj = g.nj();
    const bool ring = g.topology() == Topology::O;
    const std::size_t row = static_cast<std::size_t>(ni);
    for (int j = j0 < 1 ? 1 : j0; j < nj - 1; ++j) {
        // Rows j-1, j, j+1 (one pass per row, no index arithmetic per node:
        // a tenth of a straight channel's graded run was in it).
        const std::size_t r = row * static_cast<std::size_t>(j);
        const double *x0 = g.x.data() + r - row, *x1 = g.x.data() + r, *x2 = g.x.data() + r + row;
        const double *y0 = g.y.data() + r - row, *y1 = g.y.data() + r, *y2 = g.y.data() + r + row;
        for (int i = ring ? 0 : 1; i < ni - 1; ++i) {
            const int a = i == 0 ? ni - 2 : i - 1, b = i + 1;
            const double xx = 0.5 * (x1[b] - x1[a]), yx = 0.5 * (y1[b] - y1[a]);
            const double xe = 0.5 * (x2[i] - x0[i]), ye = 0.5 * (y2[i] - y0[i]);
            const double xxx = x1[b] - 2 * x1[i] + x1[a], yxx = y1[b] - 2 * y1[i] + y1[a];
            const double xee = x2[i] - 2 * x1[i] + x0[i], yee = y2[i] - 2 * y1[i] + y0[i];
            const double xxe = 0.25 * (x2[b] - x0[b] - x2[a] + x0[a]);
            const double yxe = 0.25 * (y2[b] - y0[b] - y2[a] + y0[a]);
            const double al = xe * xe + ye * ye, be = xx * xe + yx * ye, ga = xx * xx + yx * yx, J = xx * ye - xe * yx;
            const double rx = al * xxx - 2 * be * xxe + ga * xee, ry = al * yxx - 2 * be * yxe + ga * yee;
            phi[r + static_cast<std::size_t>(i)] = -(ye * rx - xe * ry) / (al * J);
            psi[r + static_cast<std::size_t>(i)] = -(xx * ry - yx * rx) / (ga * J);
        }
        if (ring) {
            phi[r + row - 1] = phi[r];
            psi[r + row - 1] = psi[r];
        }
    }
}

}  // namespace eg2d
