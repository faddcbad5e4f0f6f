// The coefficients of r_xi and r_eta in NUMERICS.md's equation, in the one
// canonical form that every control term adds into:
//
//   C_xi  = alpha*a_xi  + beta*b_xi  + gamma*c_xi  + J^2*d_xi
//   C_eta = alpha*a_eta + beta*b_eta + gamma*c_eta + J^2*d_eta
//   alpha r_xixi - 2 beta r_xieta + gamma r_etaeta + C_xi r_xi + C_eta r_eta = 0
//
// TTM sources:          P -> d_xi, Q -> d_eta          (Petrilli 1989 p1/p2, Ly & Norrison 2007 p/q)
// Thomas-Middlecoff:    Phi -> a_xi, Psi -> c_eta      (Petrilli 1989 section 4)
// Khattri (2006) adaptive:    P11^1 -> a_xi, -2 P12^1 -> b_xi, P22^1 -> c_xi,
//                       P11^2 -> a_eta, -2 P12^2 -> b_eta, P22^2 -> c_eta
//
// Values are per node, in the index units of the grid they belong to. On a
// grid coarsened by 2 in both directions the a, b, c terms double and the d
// terms halve (r_xi scales by 2, J^2 by 16, alpha, beta, gamma by 4).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

namespace eg2d {

enum class Term { AXi, BXi, CXi, DXi, AEta, BEta, CEta, DEta };
constexpr int kTermCount = 8;

struct ControlFields {
    // An empty vector is a field that is zero everywhere.
    std::array<std::vector<double>, kTermCount> term;

    bool empty() const {
        for (const auto &t : term)
            if (!t.empty()) return false;
        return true;
    }
    void clear() {
        for (auto &t : term) t.clear();
    }
    // The field of a term, zero-filled to n nodes on first use.
    std::vector<double> &at(Term t, std::size_t n) {
        auto &v = term[static_cast<int>(t)];
        if (v.empty()) v.assign(n, 0.0);
        return v;
    }
    const double *data(Term t) const {
        const auto &v = term[static_cast<int>(t)];
        return v.empty() ? nullptr : v.data();
    }
};

}  // namespace eg2d
