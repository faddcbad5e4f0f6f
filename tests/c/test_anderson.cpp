// Anderson acceleration (controls/anderson.hpp) on fixed points whose answer
// is known: a linear map x = M x + b with the eigenvalues of M spread over
// [0, 0.95], where the plain iteration gains a factor 0.95 per step, and the
// accelerator's edge cases (first step, restart, a repeated iterate).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "controls/anderson.hpp"

using namespace eg2d;

static int failed = 0, passed = 0;
static void check(bool ok, const std::string &what, double value) {
    std::printf("%-64s %-10.3g %s\n", what.c_str(), value, ok ? "ok" : "FAILED");
    ok ? ++passed : ++failed;
}

namespace {
constexpr int kN = 40;
constexpr double kPi = 3.14159265358979323846;

// M = Q diag(lambda) Q^T with Q the orthonormal sine basis, lambda_k spread
// over [0, 0.95]; b chosen so that x* = (1, 2, ..., n) / n.
struct LinearMap {
    std::vector<double> q, lambda, b, xstar;
    LinearMap() : q(kN * kN), lambda(kN), b(kN), xstar(kN) {
        for (int i = 0; i < kN; ++i)
            for (int k = 0; k < kN; ++k) q[i * kN + k] = std::sqrt(2.0 / (kN + 1)) * std::sin(kPi * (i + 1) * (k + 1) / (kN + 1));
        for (int k = 0; k < kN; ++k) lambda[k] = 0.95 * k / (kN - 1);
        for (int i = 0; i < kN; ++i) xstar[i] = (i + 1.0) / kN;
        const std::vector<double> mx = apply(xstar);
        for (int i = 0; i < kN; ++i) b[i] = xstar[i] - mx[i];
    }
    std::vector<double> apply(const std::vector<double> &x) const {  // M x
        std::vector<double> c(kN, 0.0), y(kN, 0.0);
        for (int k = 0; k < kN; ++k)
            for (int i = 0; i < kN; ++i) c[k] += q[i * kN + k] * x[i];
        for (int i = 0; i < kN; ++i)
            for (int k = 0; k < kN; ++k) y[i] += q[i * kN + k] * lambda[k] * c[k];
        return y;
    }
    std::vector<double> residual(const std::vector<double> &x) const {  // G(x) - x
        std::vector<double> f = apply(x);
        for (int i = 0; i < kN; ++i) f[i] += b[i] - x[i];
        return f;
    }
    double error(const std::vector<double> &x) const {
        double e = 0.0;
        for (int i = 0; i < kN; ++i) e = std::fmax(e, std::fabs(x[i] - xstar[i]));
        return e;
    }
};

// Steps until the error is below tol (or cap), with or without acceleration.
int steps(const LinearMap &m, bool accelerate, double tol, int cap, double &error) {
    Anderson aa(5);
    std::vector<double> x(kN, 0.0);
    for (int it = 0; it < cap; ++it) {
        error = m.error(x);
        if (error <= tol) return it;
        const std::vector<double> f = m.residual(x);
        if (accelerate) x = aa.next(x, f, 1.0);
        else
            for (int i = 0; i < kN; ++i) x[i] += f[i];
    }
    error = m.error(x);
    return cap;
}
}  // namespace

int main() {
    const LinearMap m;
    double e_plain = 0.0, e_aa = 0.0;
    const int plain = steps(m, false, 1e-10, 2000, e_plain);
    const int aa = steps(m, true, 1e-10, 2000, e_aa);
    // The plain iteration needs log(1e-10)/log(0.95) = 449 steps for a unit
    // error along the slowest eigenvector (this start has less there); a
    // Krylov-like method on I - M (condition 20) needs tens.
    check(plain > 250 && e_plain <= 1e-10, "plain iteration, factor 0.95: steps to 1e-10", plain);
    check(4 * aa <= plain, "Anderson(5): steps to 1e-10, at most a quarter of those", aa);
    check(e_aa <= 1e-10, "and it reaches the fixed point", e_aa);

    {  // the first step, and the first after restart(), is x + beta f
        Anderson a(3);
        const std::vector<double> x = {1.0, 2.0}, f = {0.5, -1.0};
        std::vector<double> y = a.next(x, f, 0.3);
        check(y[0] == 1.0 + 0.3 * 0.5 && y[1] == 2.0 - 0.3, "first step is the mixed step", y[0]);
        y = a.next({1.1, 1.9}, {0.2, 0.1}, 0.3);
        check(a.history() == 1, "one difference kept after the second step", static_cast<double>(a.history()));
        a.restart();
        y = a.next({1.1, 1.9}, {0.2, 0.1}, 0.3);
        check(a.history() == 0 && y[0] == 1.1 + 0.3 * 0.2, "restart: the plain step again", y[0]);
    }
    {  // a repeated iterate gives a zero difference: dropped, no NaN
        Anderson a(3);
        const std::vector<double> x = {1.0, 2.0}, f = {0.5, -1.0};
        a.next(x, f, 1.0);
        const std::vector<double> y = a.next(x, f, 1.0);
        check(std::isfinite(y[0]) && std::isfinite(y[1]) && y[0] == 1.5 && y[1] == 1.0,
              "a repeated iterate: finite, the plain step", y[0]);
    }
    {  // the history never exceeds the depth
        Anderson a(2);
        for (int k = 0; k < 6; ++k) a.next({1.0 + k, 2.0 * k}, {0.1 * k, 1.0}, 0.5);
        check(a.history() == 2, "history is capped at the depth", static_cast<double>(a.history()));
    }
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
