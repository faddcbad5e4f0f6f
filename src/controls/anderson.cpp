#include "controls/anderson.hpp"

#include <cmath>

namespace eg2d {

namespace {
double dot(const std::vector<double> &a, const std::vector<double> &b) {
    double s = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
    return s;
}
}  // namespace

std::vector<double> Anderson::next(const std::vector<double> &x, const std::vector<double> &f, double beta) {
    if (last_x_.size() != x.size()) restart();
    if (!last_x_.empty()) {
        std::vector<double> a(x.size()), b(x.size());
        for (std::size_t k = 0; k < x.size(); ++k) {
            a[k] = x[k] - last_x_[k];
            b[k] = f[k] - last_f_[k];
        }
        dx_.push_back(std::move(a));
        df_.push_back(std::move(b));
        if (static_cast<int>(dx_.size()) > depth_) {
            dx_.erase(dx_.begin());
            df_.erase(df_.begin());
        }
    }
    last_x_ = x;
    last_f_ = f;
    std::vector<double> out(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) out[k] = x[k] + beta * f[k];
    // Least squares by modified Gram-Schmidt on dF (m is a handful): a
    // column nearly in the span of the newer ones is dropped rather than
    // allowed to blow gamma up.
    const int m = static_cast<int>(df_.size());
    std::vector<std::vector<double>> q;
    std::vector<std::vector<double>> r(static_cast<std::size_t>(m), std::vector<double>(static_cast<std::size_t>(m), 0.0));
    std::vector<int> used;
    for (int c = m - 1; c >= 0; --c) {  // newest first: they describe the current map best
        std::vector<double> v = df_[static_cast<std::size_t>(c)];
        const double norm0 = std::sqrt(dot(v, v));
        std::vector<double> rc(q.size());
        for (std::size_t p = 0; p < q.size(); ++p) {
            rc[p] = dot(q[p], v);
            for (std::size_t k = 0; k < v.size(); ++k) v[k] -= rc[p] * q[p][k];
        }
        const double norm = std::sqrt(dot(v, v));
        if (!(norm > 1e-8 * norm0) || !(norm0 > 0.0)) continue;
        for (double &e : v) e /= norm;
        const std::size_t col = q.size();
        for (std::size_t p = 0; p < col; ++p) r[p][col] = rc[p];
        r[col][col] = norm;
        q.push_back(std::move(v));
        used.push_back(c);
    }
    const std::size_t n = q.size();
    if (n == 0) return out;
    std::vector<double> gamma(n);
    for (std::size_t p = 0; p < n; ++p) gamma[p] = dot(q[p], f);
    for (std::size_t p = n; p-- > 0;) {  // back substitution, R gamma = Q^T f
        for (std::size_t s = p + 1; s < n; ++s) gamma[p] -= r[p][s] * gamma[s];
        gamma[p] /= r[p][p];
    }
    for (std::size_t p = 0; p < n; ++p) {
        const std::vector<double> &ddx = dx_[static_cast<std::size_t>(used[p])];
        const std::vector<double> &ddf = df_[static_cast<std::size_t>(used[p])];
        for (std::size_t k = 0; k < x.size(); ++k) out[k] -= gamma[p] * (ddx[k] + beta * ddf[k]);
    }
    return out;
}

}  // namespace eg2d
