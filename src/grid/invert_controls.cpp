#include "grid/invert_controls.hpp"

namespace eg2d {

void invert_controls(const Grid &m, int i, int a, int b, int j, double &phi, double &psi) {
    const int ni = m.ni();
    auto X = [&](int p, int q) { return m.x[node_index(ni, p, q)]; };
    auto Y = [&](int p, int q) { return m.y[node_index(ni, p, q)]; };
    const double xx = 0.5 * (X(b, j) - X(a, j)), yx = 0.5 * (Y(b, j) - Y(a, j));
    const double xe = 0.5 * (X(i, j + 1) - X(i, j - 1)), ye = 0.5 * (Y(i, j + 1) - Y(i, j - 1));
    const double xxx = X(b, j) - 2 * X(i, j) + X(a, j), yxx = Y(b, j) - 2 * Y(i, j) + Y(a, j);
    const double xee = X(i, j + 1) - 2 * X(i, j) + X(i, j - 1), yee = Y(i, j + 1) - 2 * Y(i, j) + Y(i, j - 1);
    const double xxe = 0.25 * (X(b, j + 1) - X(b, j - 1) - X(a, j + 1) + X(a, j - 1));
    const double yxe = 0.25 * (Y(b, j + 1) - Y(b, j - 1) - Y(a, j + 1) + Y(a, j - 1));
    const double al = xe * xe + ye * ye, be = xx * xe + yx * ye, ga = xx * xx + yx * yx, J = xx * ye - xe * yx;
    const double rx = al * xxx - 2 * be * xxe + ga * xee, ry = al * yxx - 2 * be * yxe + ga * yee;
    phi = -(ye * rx - xe * ry) / (al * J);
    psi = -(xx * ry - yx * rx) / (ga * J);
}

}  // namespace eg2d
