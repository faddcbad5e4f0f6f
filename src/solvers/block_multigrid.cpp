#include "solvers/block_multigrid.hpp"

#include <algorithm>
#include <cmath>

namespace eg2d {

namespace {

// Coarsest levels at or below this many nodes are solved exactly (dense
// Cholesky of at most 2*kDenseNodes unknowns); a larger one (a direction
// that cannot coarsen) gets kCoarseSweeps symmetric sweep pairs.
constexpr std::size_t kDenseNodes = 160;
constexpr int kCoarseSweeps = 20;

inline Vec2 mul(const Mat2 &m, const Vec2 &v) { return Vec2{m.a * v.x + m.b * v.y, m.c * v.x + m.d * v.y}; }

inline Vec2 solve2(const Mat2 &m, const Vec2 &r) {
    const double det = m.a * m.d - m.b * m.c;
    return Vec2{(m.d * r.x - m.b * r.y) / det, (m.a * r.y - m.c * r.x) / det};
}

BlockMultigrid::Axis make_axis(int n, bool periodic) {
    BlockMultigrid::Axis a;
    a.fine = n;
    a.i0.assign(static_cast<std::size_t>(n), 0);
    a.i1.assign(static_cast<std::size_t>(n), 0);
    a.w0.assign(static_cast<std::size_t>(n), 1.0);
    a.w1.assign(static_cast<std::size_t>(n), 0.0);
    const bool coarsen = periodic ? n >= 8 : n >= 5;
    if (!coarsen) {
        a.coarse = n;
        for (int f = 0; f < n; ++f) a.i0[static_cast<std::size_t>(f)] = f, a.at.push_back(f);
        return a;
    }
    for (int f = 0; f < n; f += 2) a.at.push_back(f);
    if (!periodic && (n - 1) % 2 != 0) a.at.push_back(n - 1);  // the last node is always kept
    a.coarse = static_cast<int>(a.at.size());
    for (int f = 0; f < n; ++f) {
        const std::size_t k = static_cast<std::size_t>(f);
        if (f % 2 == 0) {
            a.i0[k] = f / 2;
        } else if (!periodic && f == n - 1) {
            a.i0[k] = a.coarse - 1;
        } else {
            a.i0[k] = (f - 1) / 2;
            a.i1[k] = ((f + 1) / 2) % a.coarse;
            a.w0[k] = a.w1[k] = 0.5;
        }
    }
    return a;
}

// The coarse nodes that fine node (i, j) interpolates from (bilinear, per
// axis; those with weight and an unknown of C): f(U, I, J, weight) for each,
// U = I + C.nc J.
template <class Visit>
void for_each_weight(const BlockMultigrid::Axis &ai, const BlockMultigrid::Axis &aj, const BlockStencil &C, int i,
                     int j, Visit &&f) {
    const std::size_t si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
    const int ci[2] = {ai.i0[si], ai.i1[si]}, cj[2] = {aj.i0[sj], aj.i1[sj]};
    const double wi[2] = {ai.w0[si], ai.w1[si]}, wj[2] = {aj.w0[sj], aj.w1[sj]};
    for (int b = 0; b < 2; ++b)
        for (int a = 0; a < 2; ++a) {
            if (wi[a] == 0.0 || wj[b] == 0.0) continue;
            const std::size_t U = static_cast<std::size_t>(ci[a]) + static_cast<std::size_t>(C.nc) * cj[b];
            if (C.unknown[U]) f(U, ci[a], cj[b], wi[a] * wj[b]);
        }
}

void gauss_seidel(const BlockStencil &A, const std::vector<Vec2> &b, std::vector<Vec2> &x, bool backward) {
    const int nc = A.nc, nr = A.nr;
    auto relax = [&](int i, int j) {
        const std::size_t u = static_cast<std::size_t>(i) + static_cast<std::size_t>(nc) * j;
        if (!A.unknown[u]) return;
        Vec2 s = b[u];
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                if (di == 0 && dj == 0) continue;
                const Vec2 p = mul(A.at(u, di, dj), x[static_cast<std::size_t>(A.column(i, di)) +
                                                      static_cast<std::size_t>(nc) * (j + dj)]);
                s.x -= p.x;
                s.y -= p.y;
            }
        x[u] = solve2(A.at(u, 0, 0), s);
    };
    if (!backward) {
        for (int j = 1; j < nr - 1; ++j)
            for (int i = 0; i < nc; ++i) relax(i, j);
    } else {
        for (int j = nr - 2; j >= 1; --j)
            for (int i = nc - 1; i >= 0; --i) relax(i, j);
    }
}

}  // namespace

void BlockStencil::resize(int columns, int rows, bool periodic_i) {
    nc = columns;
    nr = rows;
    periodic = periodic_i;
    unknown.assign(nodes(), 0);
    a.assign(9 * nodes(), Mat2{});
}

void BlockStencil::multiply(const Vec2 *x, Vec2 *y) const {
    for (int j = 0; j < nr; ++j)
        for (int i = 0; i < nc; ++i) {
            const std::size_t u = static_cast<std::size_t>(i) + static_cast<std::size_t>(nc) * j;
            if (!unknown[u]) {
                y[u] = x[u];
                continue;
            }
            Vec2 s{0.0, 0.0};
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const Vec2 p = mul(at(u, di, dj), x[static_cast<std::size_t>(column(i, di)) +
                                                        static_cast<std::size_t>(nc) * (j + dj)]);
                    s.x += p.x;
                    s.y += p.y;
                }
            y[u] = s;
        }
}

bool BlockMultigrid::setup(const BlockStencil &A) {
    fine_ = &A;
    levels_.reserve(64);  // no reallocation below: F refers into levels_ (a level halves a direction)
    if (levels_.empty()) levels_.emplace_back();
    std::size_t l = 0;
    for (;; ++l) {
        const BlockStencil &F = matrix(l);
        levels_[l].b.assign(F.nodes(), Vec2{});
        levels_[l].x.assign(F.nodes(), Vec2{});
        levels_[l].r.assign(F.nodes(), Vec2{});
        if (F.nodes() <= kDenseNodes) break;
        Axis ai = make_axis(F.nc, F.periodic), aj = make_axis(F.nr, false);
        if (ai.coarse == F.nc && aj.coarse == F.nr) break;  // nothing coarsens
        if (levels_.size() < l + 2) levels_.emplace_back();
        LevelData &c = levels_[l + 1];
        c.ai = std::move(ai);
        c.aj = std::move(aj);
        BlockStencil &C = c.own;
        C.resize(c.ai.coarse, c.aj.coarse, F.periodic);
        for (int J = 0; J < C.nr; ++J)
            for (int I = 0; I < C.nc; ++I)
                C.unknown[static_cast<std::size_t>(I) + static_cast<std::size_t>(C.nc) * J] =
                    F.unknown[static_cast<std::size_t>(c.ai.at[static_cast<std::size_t>(I)]) +
                              static_cast<std::size_t>(F.nc) * c.aj.at[static_cast<std::size_t>(J)]];
        // C = P^T F P: every fine coupling (p, q) spread over the coarse
        // nodes p and q interpolate from.
        auto weights = [&](int i, int j, int *I, int *J, double *w) {
            int n = 0;
            for_each_weight(c.ai, c.aj, C, i, j, [&](std::size_t, int ci, int cj, double wij) {
                I[n] = ci, J[n] = cj, w[n] = wij;
                ++n;
            });
            return n;
        };
        for (int j = 1; j < F.nr - 1; ++j)
            for (int i = 0; i < F.nc; ++i) {
                const std::size_t u = static_cast<std::size_t>(i) + static_cast<std::size_t>(F.nc) * j;
                if (!F.unknown[u]) continue;
                int Ip[4], Jp[4];
                double wp[4];
                const int np = weights(i, j, Ip, Jp, wp);
                if (np == 0) continue;
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di) {
                        const int qi = F.column(i, di), qj = j + dj;
                        if (qi == i && di != 0) continue;
                        if (!F.unknown[static_cast<std::size_t>(qi) + static_cast<std::size_t>(F.nc) * qj]) continue;
                        const Mat2 &m = F.at(u, di, dj);
                        int Iq[4], Jq[4];
                        double wq[4];
                        const int nq = weights(qi, qj, Iq, Jq, wq);
                        for (int a = 0; a < np; ++a) {
                            const std::size_t U = static_cast<std::size_t>(Ip[a]) + static_cast<std::size_t>(C.nc) * Jp[a];
                            for (int b = 0; b < nq; ++b) {
                                int dI = Iq[b] - Ip[a];
                                if (C.periodic) dI = dI > C.nc / 2 ? dI - C.nc : dI < -C.nc / 2 ? dI + C.nc : dI;
                                const double w = wp[a] * wq[b];
                                Mat2 &t = C.at(U, dI, Jq[b] - Jp[a]);
                                t.a += w * m.a;
                                t.b += w * m.b;
                                t.c += w * m.c;
                                t.d += w * m.d;
                            }
                        }
                    }
            }
        for (std::size_t U = 0; U < C.nodes(); ++U)
            if (!C.unknown[U]) C.at(U, 0, 0) = Mat2{1.0, 0.0, 0.0, 1.0};
    }
    levels_.resize(l + 1);
    return factor_coarsest();
}

bool BlockMultigrid::factor_coarsest() {
    const BlockStencil &A = matrix(levels_.size() - 1);
    dense_n_ = 0;
    chol_.clear();
    if (A.nodes() > kDenseNodes) return true;  // swept, not factored
    dense_index_.assign(A.nodes(), static_cast<std::size_t>(-1));
    for (std::size_t u = 0; u < A.nodes(); ++u)
        if (A.unknown[u]) dense_index_[u] = dense_n_++;
    const std::size_t n = 2 * dense_n_;
    chol_.assign(n * n, 0.0);
    for (int j = 0; j < A.nr; ++j)
        for (int i = 0; i < A.nc; ++i) {
            const std::size_t u = static_cast<std::size_t>(i) + static_cast<std::size_t>(A.nc) * j;
            if (!A.unknown[u]) continue;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int qi = A.column(i, di);
                    if (qi == i && di != 0) continue;
                    const std::size_t v = static_cast<std::size_t>(qi) + static_cast<std::size_t>(A.nc) * (j + dj);
                    if (!A.unknown[v]) continue;
                    const Mat2 &m = A.at(u, di, dj);
                    const std::size_t r = 2 * dense_index_[u], c = 2 * dense_index_[v];
                    chol_[r * n + c] += m.a;
                    chol_[r * n + c + 1] += m.b;
                    chol_[(r + 1) * n + c] += m.c;
                    chol_[(r + 1) * n + c + 1] += m.d;
                }
        }
    for (std::size_t k = 0; k < n; ++k) {  // lower triangle in place
        double d = chol_[k * n + k];
        for (std::size_t m = 0; m < k; ++m) d -= chol_[k * n + m] * chol_[k * n + m];
        if (!(d > 0.0)) return false;
        d = std::sqrt(d);
        chol_[k * n + k] = d;
        for (std::size_t r = k + 1; r < n; ++r) {
            double s = chol_[r * n + k];
            for (std::size_t m = 0; m < k; ++m) s -= chol_[r * n + m] * chol_[k * n + m];
            chol_[r * n + k] = s / d;
        }
    }
    return true;
}

void BlockMultigrid::solve_coarsest() {
    LevelData &L = levels_.back();
    const BlockStencil &A = matrix(levels_.size() - 1);
    std::fill(L.x.begin(), L.x.end(), Vec2{});
    if (chol_.empty()) {
        for (int s = 0; s < kCoarseSweeps; ++s) {
            gauss_seidel(A, L.b, L.x, false);
            gauss_seidel(A, L.b, L.x, true);
        }
        return;
    }
    const std::size_t n = 2 * dense_n_;
    std::vector<double> z(n);
    for (std::size_t u = 0; u < A.nodes(); ++u)
        if (A.unknown[u]) {
            z[2 * dense_index_[u]] = L.b[u].x;
            z[2 * dense_index_[u] + 1] = L.b[u].y;
        }
    for (std::size_t k = 0; k < n; ++k) {
        double s = z[k];
        for (std::size_t m = 0; m < k; ++m) s -= chol_[k * n + m] * z[m];
        z[k] = s / chol_[k * n + k];
    }
    for (std::size_t k = n; k-- > 0;) {
        double s = z[k];
        for (std::size_t m = k + 1; m < n; ++m) s -= chol_[m * n + k] * z[m];
        z[k] = s / chol_[k * n + k];
    }
    for (std::size_t u = 0; u < A.nodes(); ++u)
        if (A.unknown[u]) L.x[u] = Vec2{z[2 * dense_index_[u]], z[2 * dense_index_[u] + 1]};
}

void BlockMultigrid::cycle(std::size_t l) {
    if (l + 1 == levels_.size()) {
        solve_coarsest();
        return;
    }
    LevelData &F = levels_[l];
    LevelData &C = levels_[l + 1];
    const BlockStencil &A = matrix(l);
    std::fill(F.x.begin(), F.x.end(), Vec2{});
    gauss_seidel(A, F.b, F.x, false);
    A.multiply(F.x.data(), F.r.data());
    for (std::size_t u = 0; u < A.nodes(); ++u) F.r[u] = A.unknown[u] ? Vec2{F.b[u].x - F.r[u].x, F.b[u].y - F.r[u].y} : Vec2{};
    // b_c = P^T r, then x += P x_c.
    std::fill(C.b.begin(), C.b.end(), Vec2{});
    const BlockStencil &Cm = matrix(l + 1);
    for (int j = 1; j < A.nr - 1; ++j)
        for (int i = 0; i < A.nc; ++i) {
            const std::size_t u = static_cast<std::size_t>(i) + static_cast<std::size_t>(A.nc) * j;
            if (!A.unknown[u]) continue;
            const Vec2 r = F.r[u];
            for_each_weight(C.ai, C.aj, Cm, i, j, [&](std::size_t U, int, int, double w) {
                C.b[U].x += w * r.x;
                C.b[U].y += w * r.y;
            });
        }
    cycle(l + 1);
    for (int j = 1; j < A.nr - 1; ++j)
        for (int i = 0; i < A.nc; ++i) {
            const std::size_t u = static_cast<std::size_t>(i) + static_cast<std::size_t>(A.nc) * j;
            if (!A.unknown[u]) continue;
            for_each_weight(C.ai, C.aj, Cm, i, j, [&](std::size_t U, int, int, double w) {
                F.x[u].x += w * C.x[U].x;
                F.x[u].y += w * C.x[U].y;
            });
        }
    gauss_seidel(A, F.b, F.x, true);
}

void BlockMultigrid::apply(const Vec2 *r, Vec2 *z) {
    LevelData &F = levels_[0];
    std::copy(r, r + fine_->nodes(), F.b.begin());
    cycle(0);
    std::copy(F.x.begin(), F.x.end(), z);
}

}  // namespace eg2d
