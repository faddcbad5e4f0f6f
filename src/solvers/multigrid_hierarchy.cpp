#include "solvers/multigrid_hierarchy.hpp"

#include <algorithm>
#include <cmath>

namespace eg2d {

namespace {

// Can a direction of n nodes become nc nodes and keep a sound coarse grid?
bool can_coarsen(int n, int nc, bool periodic, int coarsest) {
    if (n <= coarsest || nc >= n) return false;
    // A periodic direction goes round a body: keep at least 8 cells on it
    // (with 4, an airfoil is a diamond and the coarse problem breaks down).
    return periodic ? nc - 1 >= 8 : nc >= 3;
}

}  // namespace

void coarse_stretch(const ControlFields *fields, double &stretch_i, double &stretch_j) {
    stretch_i = stretch_j = 0.0;
    if (!fields) return;
    // Not the largest value: a few nodes (a trailing edge's fan) may have a
    // large Phi where the coarse grid does not resolve them anyway; the 98th
    // percentile of the nonzero values says what the coarse levels meet.
    auto largest = [](const double *f, std::size_t n) {
        std::vector<double> v;
        for (std::size_t k = 0; f && k < n; ++k)
            if (f[k] != 0.0) v.push_back(std::fabs(f[k]));
        if (v.empty()) return 0.0;
        const std::size_t q = v.size() * 98 / 100;
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(q), v.end());
        return v[q];
    };
    const std::size_t n = fields->term[static_cast<int>(Term::AXi)].size();
    stretch_i = largest(fields->data(Term::AXi), n);
    stretch_j = largest(fields->data(Term::CEta), fields->term[static_cast<int>(Term::CEta)].size());
}

std::vector<MgLevel> build_hierarchy(const Connectivity &fine, System system, int coarsest, double stretch_i,
                                     double stretch_j) {
    std::vector<MgLevel> levels;
    levels.emplace_back(fine);
    levels.back().ai = identity_axis(fine.ni(), fine.periodic_i());
    levels.back().aj = identity_axis(fine.nj(), false);
    for (;;) {
        const Connectivity &c = levels.back().conn;
        // A C-grid's trailing edges stay coarse nodes: the cut ends there.
        std::vector<int> anchors, j_anchors;
        // push_back, not = {...}: GCC 12 at -O3 warns (-Wnonnull, falsely) on a list assigned to an empty vector.
        if (c.wake() > 0) {
            anchors.push_back(c.wake());
            anchors.push_back(c.ni() - 1 - c.wake());
        }
        // Held rows (a wall layer) end at a coarse node too, and each level
        // keeps at least two rows of unknowns above them: with one (the
        // hybrid C-grid 1793x513 to 500 chords, a 15x6 level over 3 held
        // rows) the cycles stalled at a residual of 5e-8; down to 15x10 they
        // converge in 7.
        const int held = c.held_rows();
        if (held > 0) j_anchors.push_back(held);
        // Fixed interior lines stay coarse nodes and stay fixed there, so a
        // coarse correction is exactly 0 on them (coarse_axis.hpp: an
        // anchor's interpolation weight is 1).
        const std::vector<int> fixed_i = c.fixed_columns(), fixed_j = c.fixed_rows();
        anchors.insert(anchors.end(), fixed_i.begin(), fixed_i.end());
        j_anchors.insert(j_anchors.end(), fixed_j.begin(), fixed_j.end());
        bool ci = can_coarsen(c.ni(), coarse_count(c.ni(), anchors), c.periodic_i(), coarsest);
        bool cj = can_coarsen(c.nj(), coarse_count(c.nj(), j_anchors), false, coarsest);
        // Phi and Psi double with each coarsening of their direction. Past
        // the limit a level stops coarsening, unless it is large: then it
        // goes on and its coarser levels' controls are clipped.
        const bool large = levels.back().size() > kLargeCoarsest;
        bool clip = levels.back().clip;
        auto limit = [&](bool &coarsen, bool over) {
            if (!over || !coarsen) return;
            if (large) clip = true;
            else coarsen = false;
        };
        limit(ci, 2.0 * stretch_i > kMaxCoarseStretching);
        limit(cj, 2.0 * stretch_j > kMaxCoarseStretching);
        if (cj && held > 0 && coarse_count(c.nj(), j_anchors) - coarse_count(held + 1, {}) < 3) cj = false;
        // Above a held wall layer the rows are stretched (Psi): the eta-lines
        // of the smoother solve across them exactly, and only xi is coarsened
        // (semicoarsening with line relaxation across it: Trottenberg,
        // Oosterlee & Schueller 2001, sec. 5.1). Coarsening eta too put
        // Psi's doubled values on coarse rings a few cells round and stalled
        // the cycle (annulus 65x33, 1e-3 wall, far field 10: residual stuck
        // at 8e-4; xi alone: 6 cycles). Where Psi stays small on the coarse
        // rings (the hybrid layer's controls, |Psi| about 0.12) eta is
        // coarsened too: NACA 0012 250x100 at 1.04e-5, 8 cycles instead of 61.
        if (held > 0) limit(cj, 2.0 * stretch_j > kMaxHeldStretching);
        // Laplace in index units is not invariant under coarsening one
        // direction only (x_xixi + x_etaeta would change its anisotropy), so
        // it coarsens in both or stops, and so does the variational system
        // (its S is Laplace's); Winslow's equation is invariant.
        if (system != System::Winslow ? !(ci && cj) : !(ci || cj)) break;
        CoarseAxis ai = make_axis(c.ni(), c.periodic_i(), anchors, ci);
        CoarseAxis aj = make_axis(c.nj(), false, j_anchors, cj);
        const int wake = c.wake() > 0 ? ai.nearest(c.wake()) : 0;
        const Connectivity plain(ai.nc, aj.nc, c.topology(), wake);
        std::vector<int> coarse_i, coarse_j;
        for (int i : fixed_i) coarse_i.push_back(ai.nearest(i));
        for (int j : fixed_j) coarse_j.push_back(aj.nearest(j));
        const Connectivity coarse = plain.with_fixed(coarse_i, coarse_j);
        levels.emplace_back(held > 0 ? coarse.held_below(aj.nearest(held)) : coarse);
        if (ci) stretch_i *= 2.0;
        if (cj) stretch_j *= 2.0;
        levels.back().clip = clip;
        levels.back().ai = std::move(ai);
        levels.back().aj = std::move(aj);
    }
    for (std::size_t l = 0; l < levels.size(); ++l) {
        MgLevel &m = levels[l];
        const std::size_t n = m.size();
        m.rx.assign(n, 0.0);
        m.ry.assign(n, 0.0);
        if (l > 0) {
            m.x.assign(n, 0.0);
            m.y.assign(n, 0.0);
            m.x0.assign(n, 0.0);
            m.y0.assign(n, 0.0);
            m.fx.assign(n, 0.0);
            m.fy.assign(n, 0.0);
            m.level.x = m.x.data();
            m.level.y = m.y.data();
            m.level.fx = m.fx.data();
            m.level.fy = m.fy.data();
        }
        m.work.reserve(std::max(m.conn.ni(), m.conn.nj()));
    }
    for (MgLevel &m : levels) m.level.conn = &m.conn;  // after the vector stopped moving
    return levels;
}

double operator_scale(System system, const MgLevel &coarse, int I, int J) {
    const double s = coarse.ai.h[static_cast<std::size_t>(I)] * coarse.aj.h[static_cast<std::size_t>(J)];
    return system == System::Winslow ? s * s : s;
}

void attach_functional(std::vector<MgLevel> &levels, const Functional *fine) {
    if (levels.empty()) return;
    levels[0].level.functional = fine;
    const Functional f = fine ? *fine : Functional{};
    const double fine_cells = static_cast<double>(levels[0].conn.ni() - 1) * (levels[0].conn.nj() - 1);
    for (std::size_t l = 1; l < levels.size(); ++l) {
        MgLevel &m = levels[l];
        m.functional = coarsened(f, static_cast<double>(m.conn.ni() - 1) * (m.conn.nj() - 1) / fine_cells);
        m.level.functional = &m.functional;
    }
}

// With r_xi = r_Xi/si, r_eta = r_Eta/sj on the coarse grid (capitals), alpha =
// alpha_c/sj^2, beta = beta_c/(si sj), gamma = gamma_c/si^2, J^2 = J_c^2/(si sj)^2,
// and the coarse equation (si sj)^2 times the fine one, C_xi r_xi needs
// C_xi,c = si sj^2 C_xi, C_eta,c = si^2 sj C_eta; written in the coarse metrics:
//   a_xi*si, b_xi*sj, c_xi*sj^2/si, d_xi/si;  a_eta*si^2/sj, b_eta*si, c_eta*sj, d_eta/sj.
// For si = sj = 2: a, b, c double and d halves (control_fields.hpp). Here si,
// sj are the local spacings hi(I), hj(J) of the coarse axes.
long clip_coarse_stretching(MgLevel &coarse) {
    long clipped = 0;
    if (!coarse.clip) return 0;
    for (Term t : {Term::AXi, Term::CEta})
        for (double &v : coarse.controls.term[static_cast<int>(t)])
            if (std::fabs(v) > kMaxCoarseStretching) {
                v = std::copysign(kMaxCoarseStretching, v);
                ++clipped;
            }
    return clipped;
}

void restrict_controls(const ControlFields *fine, const Connectivity &fine_conn, MgLevel &coarse) {
    if (!fine || fine->empty()) {
        coarse.level.controls = nullptr;
        return;
    }
    const int nic = coarse.conn.ni(), njc = coarse.conn.nj();
    for (int t = 0; t < kTermCount; ++t) {
        const double *f = fine->data(static_cast<Term>(t));
        std::vector<double> &dst = coarse.controls.term[t];
        if (!f) {
            dst.clear();
            continue;
        }
        dst.resize(coarse.size());
        inject(fine_conn, f, coarse, dst.data());
        for (int J = 0; J < njc; ++J)
            for (int I = 0; I < nic; ++I) {
                const double si = coarse.ai.h[static_cast<std::size_t>(I)], sj = coarse.aj.h[static_cast<std::size_t>(J)];
                const double scale[kTermCount] = {si, sj, sj * sj / si, 1.0 / si, si * si / sj, si, sj, 1.0 / sj};
                dst[static_cast<std::size_t>(I) + static_cast<std::size_t>(nic) * J] *= scale[t];
            }
    }
    coarse.level.controls = &coarse.controls;
}

}  // namespace eg2d
