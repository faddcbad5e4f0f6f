// The variational Newton minimiser's stop tests (solvers/newton_progress)
// on given sequences of residuals, V and fold-limited steps: which test
// ends a run, at which step, with which message, and that a run whose V
// keeps falling is not stopped while its residual wanders.
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "base/error.hpp"
#include "solvers/newton_progress.hpp"

using eg2d::NewtonProgress;

static int failures = 0;
static void check(bool ok, const char *what, double value) {
    std::printf("%-66s %10g %s\n", what, value, ok ? "ok" : "FAILED");
    if (!ok) ++failures;
}

struct Step {
    double residual, energy;
    bool limited;
};

// Feeds steps 1..n (step(k) gives step k) with or without a barrier; the
// step at which a test ended the run (0: none did) and its message.
static int run(int n, bool barrier, const std::function<Step(int)> &step, std::string &message) {
    NewtonProgress p;
    p.restart();
    for (int k = 1; k <= n; ++k) {
        const Step s = step(k);
        try {
            p.observe(s.residual, s.energy, s.limited, barrier, 0.0);
        } catch (const eg2d::Error &e) {
            message = e.what();
            return e.failure() == eg2d::Failure::NotConverged ? k : -k;
        }
    }
    message.clear();
    return 0;
}

static bool says(const std::string &message, const char *text) { return message.find(text) != std::string::npos; }

int main() {
    std::string m;
    // Ab on the swan at 129^2: the residual wanders between 2e-6 and 4e-5
    // after its best while V falls by about 1e-6 of itself per step.
    int at = run(300, true, [](int k) {
        return Step{k == 1 ? 1e-6 : (k % 2 ? 2e-6 : 4e-5), 9.0 - 1e-5 * k, k % 2 == 0};
    }, m);
    check(at == 0, "residual wandering, V falling 1e-6 per step: runs on (300 steps)", at);
    // Neither falls: the no-progress test, 40 steps after the last progress.
    at = run(300, false, [](int k) { return Step{k == 1 ? 1e-6 : 2e-6, 9.0, false}; }, m);
    check(at == 41 && says(m, "in 40 Newton steps the residual fell by less than 1.25 and V by less than 1e-09"),
          "residual and V flat: stops 40 steps after the best (step 41)", at);
    // V falling by less than 1e-9 of itself per 40 steps counts as flat.
    at = run(300, false, [](int k) { return Step{k == 1 ? 1e-6 : 2e-6, 9.0 - 1e-12 * k, false}; }, m);
    check(at == 41, "V falling 1e-13 of itself per step: stops at step 41", at);
    // V falling, then flat from step 100: 40 steps after V's last fall.
    at = run(300, false, [](int k) { return Step{k == 1 ? 1e-6 : 2e-6, 9.0 - 1e-5 * std::fmin(k, 100), false}; }, m);
    check(at == 140, "V falling to step 100, then flat: stops at step 140", at);
    // The fold guard's stall (no barrier): 12 shortened steps without the residual falling.
    at = run(300, false, [](int k) { return Step{k == 1 ? 1e-6 : 2e-6, 9.0 - 1e-5 * k, k > 1}; }, m);
    check(at == 13 && says(m, "the fold guard shortened the last 12 Newton steps"),
          "fold-limited steps, no barrier, V falling: fold stall at step 13", at);
    // With a barrier, shortened steps are the way to the minimum: 500 in a row end the run.
    at = run(800, true, [](int k) { return Step{k == 1 ? 1e-6 : 2e-6, 9.0 - 1e-5 * k, k > 1}; }, m);
    check(at == 501 && says(m, "the fold limit shortened the last 500 Newton steps"),
          "fold-limited steps with a barrier: stop after 500 in a row (step 501)", at);
    // V infinite where the run begins (a step from a folded grid, with a
    // barrier in V), then falling: the finite V counts as progress.
    at = run(300, true, [](int k) {
        return Step{k == 1 ? 1e-6 : (k % 2 ? 2e-6 : 4e-5), k == 1 ? HUGE_VAL : 9.0 - 1e-5 * k, false};
    }, m);
    check(at == 0, "V infinite at step 1, then falling: runs on (300 steps)", at);
    // An infinite or NaN V is never progress.
    at = run(300, false, [](int k) { return Step{k == 1 ? 1e-6 : 2e-6, k % 2 ? HUGE_VAL : NAN, false}; }, m);
    check(at == 41, "V infinite or NaN throughout: stops at step 41", at);
    // Every other step shortened by the fold limit with a barrier, V flat:
    // the shortened steps do not count against the residual, so 40 others
    // (steps 3, 5, ..., 81) end the run, as before V was read.
    at = run(300, true, [](int k) { return Step{k == 1 ? 1e-6 : 2e-6, 9.0, k % 2 == 0}; }, m);
    check(at == 81 && says(m, "in 40 Newton steps"), "every other step fold-limited, barrier, V flat: stops at step 81",
          at);
    // A residual falling by 1.25 every step never stops, whatever V does.
    at = run(300, false, [](int k) { return Step{std::pow(0.79, k), 9.0, false}; }, m);
    check(at == 0, "residual falling 0.79 per step, V flat: runs on (300 steps)", at);
    return failures == 0 ? 0 : 1;
}
