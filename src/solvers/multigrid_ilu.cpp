#include "solvers/multigrid_ilu.hpp"

#include <cstddef>

namespace eg2d {

void ilu_sweep(System system, const Level &L, bool mirror, double omega, IluWork &w) {
    const Connectivity &conn = *L.conn;
    const int ni = conn.ni(), i0 = conn.i_begin(), i1 = conn.i_end(), j0 = conn.j_begin(), j1 = conn.j_end();
    const std::size_t size = static_cast<std::size_t>(ni) * conn.nj();
    for (auto *v : {&w.uc, &w.ue, &w.unw, &w.un, &w.une, &w.zx, &w.zy})
        if (v->size() < size) v->assign(size, 0.0);
    const int di = mirror ? -1 : 1;
    // Ordering-relative neighbours: "w" is the node visited before on the
    // same row (i - di), "e" the one after (i + di).
    const std::ptrdiff_t W = -di, E = di, S = -ni, N = ni;
    double *uc = w.uc.data(), *ue = w.ue.data(), *unw = w.unw.data(), *un = w.un.data(), *une = w.une.data();
    double *zx = w.zx.data(), *zy = w.zy.data();
    // A single block (the only topology it is used on): every unknown's
    // neighbours are at fixed offsets, so no Connectivity::stencil lookups.
    auto plain = [ni](std::ptrdiff_t k) {
        return Stencil{k, k + 1, k - 1, k + ni, k - ni, k + ni + 1, k + ni - 1, k - ni + 1, k - ni - 1};
    };
    const int ib = mirror ? i1 - 1 : i0, ie = mirror ? i0 - 1 : i1;
    for (int j = j0; j < j1; ++j)
        for (int i = ib; i != ie; i += di) {
            const std::ptrdiff_t k = i + std::ptrdiff_t(ni) * j;
            Metrics m;
            const NodeEquation eq = node_equation(system, L, plain(k), &m);
            // Physical coefficients (line_relax.hpp; Laplace: alpha = gamma =
            // 1, beta = C = 0), then named in the ordering. The factors follow
            // from A = L U on the pattern {sw, s, se, w | c, e, nw, n, ne}.
            const double ce = m.alpha + 0.5 * m.cxi, cw = m.alpha - 0.5 * m.cxi;
            const double a_e = mirror ? cw : ce, a_w = mirror ? ce : cw;
            const double a_n = m.gamma + 0.5 * m.ceta, a_s = m.gamma - 0.5 * m.ceta;
            const double hb = 0.5 * m.beta * di;  // the mirror flips the sign of the xi-derivative
            const double a_ne = -hb, a_sw = -hb, a_nw = hb, a_se = hb;
            const double a_c = -2.0 * (m.alpha + m.gamma);
            // Which neighbours are unknowns of the rectangle (the others enter through R).
            const bool hw = i != ib, hs = j > j0, hsw = hw && hs, hse = hs && i + di != ie;
            const double lsw = hsw ? a_sw * uc[k + S + W] : 0.0;
            const double ls = hs ? (a_s - lsw * ue[k + S + W]) * uc[k + S] : 0.0;
            const double lse = hse ? (a_se - ls * ue[k + S]) * uc[k + S + E] : 0.0;
            const double lw =
                hw ? (a_w - (hsw ? lsw * un[k + S + W] : 0.0) - (hs ? ls * unw[k + S] : 0.0)) * uc[k + W] : 0.0;
            double c = a_c;
            if (hsw) c -= lsw * une[k + S + W];
            if (hs) c -= ls * un[k + S];
            if (hse) c -= lse * unw[k + S + E];
            if (hw) c -= lw * ue[k + W];
            // An incomplete pivot that is not negative (ILU breakdown, or all
            // neighbours coincident: a_c = 0 and R = 0) falls back to the
            // point Jacobi pivot, so a sweep never divides by zero.
            if (!(c < 0.0)) c = a_c < 0.0 ? a_c : -1.0;
            uc[k] = 1.0 / c;
            ue[k] = a_e - (hs ? ls * une[k + S] : 0.0) - (hse ? lse * un[k + S + E] : 0.0);
            unw[k] = a_nw - (hw ? lw * un[k + W] : 0.0);
            un[k] = a_n - (hw ? lw * une[k + W] : 0.0);
            une[k] = a_ne;
            // Forward substitution, L z = -R, row by row with the factorisation.
            double bx = -eq.rx, by = -eq.ry;
            if (hsw) { bx -= lsw * zx[k + S + W]; by -= lsw * zy[k + S + W]; }
            if (hs) { bx -= ls * zx[k + S]; by -= ls * zy[k + S]; }
            if (hse) { bx -= lse * zx[k + S + E]; by -= lse * zy[k + S + E]; }
            if (hw) { bx -= lw * zx[k + W]; by -= lw * zy[k + W]; }
            zx[k] = bx;
            zy[k] = by;
        }
    // Backward substitution U d = z (d overwrites z), then move the grid.
    for (int j = j1 - 1; j >= j0; --j) {
        for (int i = ie - di; i != ib - di; i -= di) {
            const std::ptrdiff_t k = i + std::ptrdiff_t(ni) * j;
            double bx = zx[k], by = zy[k];
            const bool he = i + di != ie, hw = i != ib, hn = j + 1 < j1;
            if (he) { bx -= ue[k] * zx[k + E]; by -= ue[k] * zy[k + E]; }
            if (hn && hw) { bx -= unw[k] * zx[k + N + W]; by -= unw[k] * zy[k + N + W]; }
            if (hn) { bx -= un[k] * zx[k + N]; by -= un[k] * zy[k + N]; }
            if (hn && he) { bx -= une[k] * zx[k + N + E]; by -= une[k] * zy[k + N + E]; }
            zx[k] = bx * uc[k];
            zy[k] = by * uc[k];
        }
    }
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) {
            const std::ptrdiff_t k = i + std::ptrdiff_t(ni) * j;
            L.x[k] += omega * zx[k];
            L.y[k] += omega * zy[k];
        }
}

}  // namespace eg2d
