// Linear transfinite interpolation, the grid-generation lecture notes eq 2.2, with the index
// parameters r = i/(ni-1), s = j/(nj-1).
#include "grid/initializers.hpp"

namespace eg2d {

void tfi_linear(Grid &g, const Settings &) {
    const int ni = g.ni(), nj = g.nj();
    auto at = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
    for (double *f : {g.x.data(), g.y.data()}) {
        if (g.topology() == Topology::O) {
            // Between the inner (JMIN) and outer (JMAX) closed curves the sides
            // i = const are the cut itself: interpolate along eta only.
            for (int j = 1; j < nj - 1; ++j) {
                const double s = static_cast<double>(j) / (nj - 1);
                for (int i = 0; i < ni; ++i) f[at(i, j)] = (1 - s) * f[at(i, 0)] + s * f[at(i, nj - 1)];
            }
            continue;
        }
        const double f00 = f[at(0, 0)], f10 = f[at(ni - 1, 0)], f01 = f[at(0, nj - 1)], f11 = f[at(ni - 1, nj - 1)];
        for (int j = 1; j < nj - 1; ++j) {
            const double s = static_cast<double>(j) / (nj - 1);
            for (int i = 1; i < ni - 1; ++i) {
                const double r = static_cast<double>(i) / (ni - 1);
                f[at(i, j)] = (1 - r) * f[at(0, j)] + r * f[at(ni - 1, j)] + (1 - s) * f[at(i, 0)] +
                              s * f[at(i, nj - 1)] - (1 - r) * (1 - s) * f00 - r * (1 - s) * f10 -
                              (1 - r) * s * f01 - r * s * f11;
            }
        }
    }
}

}  // namespace eg2d
