// TFI with Hermite blending in eta and the orthogonal projector of the grid-generation lecture notes
// (eqs 2.4-2.6): at JMIN and JMAX the eta-derivative is normal to the side,
// with length d/Delta = alpha |r(i, nj-1) - r(i, 0)| (the lecture notes' d(s) =
// alpha Delta r, alpha measured against the straight line between the two
// boundary points of the column). In xi: linear TFI (the Boolean sum, the grid-generation lecture notes
// eq 2.3) for the single-block and C topologies, none for the O-grid.
#include <cmath>
#include <vector>

#include "base/error.hpp"
#include "grid/initializers.hpp"

namespace eg2d {

namespace {

struct Vec { double x, y; };

// The eta-derivatives along row j (0 or nj-1): normal to the row, of length
// alpha times the column's end-to-end distance, turned toward the other row.
std::vector<Vec> normal_derivatives(const Grid &g, int j, double alpha) {
    const int ni = g.ni(), nj = g.nj();
    const bool periodic = g.connectivity().periodic_i();
    auto at = [ni](int i, int jj) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * jj; };
    std::vector<Vec> d(static_cast<std::size_t>(ni));
    double orientation = 0.0;
    for (int i = 0; i < ni; ++i) {
        int ie = i + 1, iw = i - 1;
        if (periodic) {
            if (iw < 0) iw = ni - 2;
            if (ie > ni - 1) ie = 1;
        } else {
            if (iw < 0) iw = 0;
            if (ie > ni - 1) ie = ni - 1;
        }
        const double tx = g.x[at(ie, j)] - g.x[at(iw, j)], ty = g.y[at(ie, j)] - g.y[at(iw, j)];
        const double t = std::hypot(tx, ty);
        const double cx = g.x[at(i, nj - 1)] - g.x[at(i, 0)], cy = g.y[at(i, nj - 1)] - g.y[at(i, 0)];
        const double len = alpha * std::hypot(cx, cy);
        d[static_cast<std::size_t>(i)] = t > 0 ? Vec{len * ty / t, -len * tx / t} : Vec{0.0, 0.0};
        orientation += d[static_cast<std::size_t>(i)].x * cx + d[static_cast<std::size_t>(i)].y * cy;
    }
    // One sign for the whole row (the grid-generation lecture notes eq 2.6 leaves it open): the one that
    // points into the domain on balance. The derivative is d r/d s, s = eta
    // from JMIN to JMAX, so it points away from JMIN at both rows.
    if (orientation < 0)
        for (Vec &v : d) v = Vec{-v.x, -v.y};
    if (!periodic) {
        // The corner columns are the sides IMIN, IMAX: take their own eta
        // slope there, so that the xi-projector's part of the Boolean sum,
        // P_xi - P_xi P_eta, vanishes to O(Delta^2) near JMIN and JMAX and the
        // orthogonality of P_eta survives in the sum.
        const int jn = j == 0 ? 1 : nj - 2;
        for (int i : {0, ni - 1}) {
            const double sx = (g.x[at(i, jn)] - g.x[at(i, j)]) * (nj - 1), sy = (g.y[at(i, jn)] - g.y[at(i, j)]) * (nj - 1);
            d[static_cast<std::size_t>(i)] = j == 0 ? Vec{sx, sy} : Vec{-sx, -sy};
        }
    }
    return d;
}

}  // namespace

void tfi_hermite(Grid &g, const Settings &settings) {
    if (settings.hermite_sides != 0.0) return tfi_hermite_sides(g, settings);
    const int ni = g.ni(), nj = g.nj();
    const double alpha = settings.hermite_spacing;
    auto at = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
    const std::vector<Vec> d0 = normal_derivatives(g, 0, alpha), d1 = normal_derivatives(g, nj - 1, alpha);
    const bool o_grid = g.topology() == Topology::O;
    for (int pass = 0; pass < 2; ++pass) {
        double *f = pass == 0 ? g.x.data() : g.y.data();
        auto deriv = [&](const std::vector<Vec> &d, int i) {
            return pass == 0 ? d[static_cast<std::size_t>(i)].x : d[static_cast<std::size_t>(i)].y;
        };
        // P_eta at column i and eta = s: Hermite blending, the grid-generation lecture notes eq 2.4.
        auto p_eta = [&](int i, double s) {
            const double phi0 = (2 * s + 1) * (1 - s) * (1 - s), phi1 = (3 - 2 * s) * s * s;
            const double psi0 = (1 - s) * (1 - s) * s, psi1 = (s - 1) * s * s;
            return phi0 * f[at(i, 0)] + phi1 * f[at(i, nj - 1)] + psi0 * deriv(d0, i) + psi1 * deriv(d1, i);
        };
        std::vector<double> out(g.size());
        for (int j = 1; j < nj - 1; ++j) {
            const double s = static_cast<double>(j) / (nj - 1);
            if (o_grid) {
                for (int i = 0; i < ni; ++i) out[at(i, j)] = p_eta(i, s);
                continue;
            }
            const double left = p_eta(0, s), right = p_eta(ni - 1, s);
            for (int i = 1; i < ni - 1; ++i) {
                const double r = static_cast<double>(i) / (ni - 1);
                // Boolean sum P_xi + P_eta - P_xi P_eta (the grid-generation lecture notes eq 2.3).
                out[at(i, j)] = (1 - r) * f[at(0, j)] + r * f[at(ni - 1, j)] + p_eta(i, s) - (1 - r) * left - r * right;
            }
        }
        for (int j = 1; j < nj - 1; ++j)
            for (int i = o_grid ? 0 : 1; i < (o_grid ? ni : ni - 1); ++i) f[at(i, j)] = out[at(i, j)];
        g.connectivity().sync(f);
    }
}

}  // namespace eg2d
