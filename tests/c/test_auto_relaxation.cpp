// The automatic SOR factor: Laplace's optimum, Winslow's more cautious start,
// and the backoff when the residual rises 10x above its best.
#include <cmath>
#include <cstdio>

#include "solvers/auto_relaxation.hpp"
#include "solvers/solver.hpp"

static int passed = 0, failed = 0;
static void check(bool ok, const char *what, double value) {
    std::printf("%-58s %.6f %s\n", what, value, ok ? "ok" : "FAILED");
    ok ? ++passed : ++failed;
}

int main() {
    using namespace eg2d;
    Settings settings;
    const double opt = optimal_sor_omega(257, 257);  // 1.97585
    AutoRelaxation r;
    check(std::fabs(r.omega(settings, System::Laplace, 257, 257) - opt) < 1e-15, "Laplace: seed 003 optimum", opt);
    const double w0 = r.omega(settings, System::Winslow, 257, 257);
    check(std::fabs(w0 - (2 - 2 * (2 - opt))) < 1e-15, "Winslow: optimum of a grid half as fine", w0);
    // A start that decreases, with a 9x bump: no backoff.
    for (double res : {1e-3, 5e-4, 2e-4, 1.8e-3, 1e-4}) r.observe(res);
    check(r.omega(settings, System::Winslow, 257, 257) == w0, "a 9x transient keeps omega", w0);
    // A 10x rise above the best (1e-4) widens 2 - omega once, and only once.
    r.observe(1.1e-3);
    const double w1 = r.omega(settings, System::Winslow, 257, 257);
    check(std::fabs((2 - w1) - 2 * (2 - w0)) < 1e-15, "a 10x rise doubles 2 - omega", w1);
    r.observe(1.2e-3);
    check(r.omega(settings, System::Winslow, 257, 257) == w1, "the next sweep keeps the new omega", w1);
    // Repeated rises never take omega below 1 (Gauss-Seidel).
    for (int k = 0; k < 40; ++k) r.observe(std::pow(10.0, k));
    const double w_min = r.omega(settings, System::Winslow, 257, 257);
    check(w_min == 1.0, "omega never drops below 1", w_min);
    r.reset();
    check(r.omega(settings, System::Winslow, 257, 257) == w0, "reset restores the start", w0);
    settings.relaxation = 1.3;
    r.observe(1.0);
    r.observe(100.0);
    check(r.omega(settings, System::Winslow, 257, 257) == 1.3, "a user's factor is never changed", 1.3);
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
