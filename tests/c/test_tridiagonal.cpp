// The tridiagonal kernels against a dense solve of the same systems.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "base/tridiagonal.hpp"

static int failures = 0, passes = 0;
static void check(bool ok, const char *what, double err) {
    std::printf("%-40s max error %.3e %s\n", what, err, ok ? "ok" : "FAILED");
    if (!ok) ++failures;
    else ++passes;
}

int main() {
    for (std::size_t n : {1u, 2u, 7u, 64u}) {
        std::vector<double> a(n), b(n), c(n), d(n), u(n);
        for (std::size_t k = 0; k < n; ++k) {
            a[k] = -1.0 - 0.1 * std::sin(k + 1.0);
            c[k] = -1.0 + 0.2 * std::cos(3.0 * k);
            b[k] = 4.0 + 0.5 * std::sin(k * 0.7);
            u[k] = std::cos(0.3 * k) + k;
        }
        for (std::size_t k = 0; k < n; ++k)
            d[k] = b[k] * u[k] + (k > 0 ? a[k] * u[k - 1] : 0.0) + (k + 1 < n ? c[k] * u[k + 1] : 0.0);
        std::vector<double> cc = c;
        eg2d::solve_tridiagonal(n, a.data(), b.data(), cc.data(), d.data());
        double err = 0;
        for (std::size_t k = 0; k < n; ++k) err = std::fmax(err, std::fabs(d[k] - u[k]));
        check(err < 1e-12, ("thomas n=" + std::to_string(n)).c_str(), err);
        // Two right-hand sides at once: u and 2u - 1.
        for (std::size_t k = 0; k < n; ++k)
            d[k] = b[k] * u[k] + (k > 0 ? a[k] * u[k - 1] : 0.0) + (k + 1 < n ? c[k] * u[k + 1] : 0.0);
        std::vector<double> d2(n);
        for (std::size_t k = 0; k < n; ++k) d2[k] = 2.0 * d[k] - (b[k] + (k > 0 ? a[k] : 0.0) + (k + 1 < n ? c[k] : 0.0));
        cc = c;
        eg2d::solve_tridiagonal2(n, a.data(), b.data(), cc.data(), d.data(), d2.data());
        err = 0;
        for (std::size_t k = 0; k < n; ++k)
            err = std::fmax(err, std::fmax(std::fabs(d[k] - u[k]), std::fabs(d2[k] - (2.0 * u[k] - 1.0))));
        check(err < 1e-12, ("thomas, two right-hand sides n=" + std::to_string(n)).c_str(), err);
        if (n < 3) continue;
        // Periodic: a[0] couples to u[n-1], c[n-1] to u[0].
        for (std::size_t k = 0; k < n; ++k)
            d[k] = b[k] * u[k] + a[k] * u[(k + n - 1) % n] + c[k] * u[(k + 1) % n];
        std::vector<double> work;
        eg2d::solve_cyclic_tridiagonal(n, a.data(), b.data(), c.data(), d.data(), work);
        err = 0;
        for (std::size_t k = 0; k < n; ++k) err = std::fmax(err, std::fabs(d[k] - u[k]));
        check(err < 1e-12, ("cyclic (Sherman-Morrison) n=" + std::to_string(n)).c_str(), err);
    }
    std::printf("%d passed, %d failed\n", passes, failures);
    return failures == 0 ? 0 : 1;
}
