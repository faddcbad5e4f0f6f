// The automatic SOR factor's guard (auto_relaxation.hpp), driven by made-up
// sweeps that move a 5x5 grid by chosen amounts: the ramp, a jump undone and
// redone at half the over-relaxation, a creep after the ramp, moves that
// grow during the ramp left alone, NaN undone, reset; the ramp's length.
#include <cmath>
#include <cstdio>
#include <vector>

#include "base/connectivity.hpp"
#include "solvers/auto_relaxation.hpp"
#include "solvers/solver.hpp"

static int passed = 0, failed = 0;
static void check(bool ok, const char *what, double value) {
    std::printf("%-62s %.6f %s\n", what, value, ok ? "ok" : "FAILED");
    ok ? ++passed : ++failed;
}

namespace {
using namespace eg2d;

struct Fixture {
    Connectivity conn{5, 5, Topology::Single};
    std::vector<double> x = std::vector<double>(25, 0.0), y = std::vector<double>(25, 0.0);
    Level level() {
        Level L;
        L.conn = &conn;
        L.x = x.data();
        L.y = y.data();
        return L;
    }
};

// One guarded sweep that moves node 12 by `move` (whatever the factor) and
// records the factors it was called with.
void sweep(AutoRelaxation &r, Fixture &f, long ramp, double move, std::vector<double> &omegas) {
    r.sweep(f.level(), ramp, [&] {
        omegas.push_back(r.omega(1.8));
        f.x[12] += move;
    });
}
}  // namespace

int main() {
    check(AutoRelaxation::ramp_for(1.91) == 100, "ramp: 9 / (2 - target) sweeps", AutoRelaxation::ramp_for(1.91));

    {  // the ramp: 1 + (k+1)/4 * 0.8 over four sweeps, moves growing 2x a sweep left alone
        Fixture f;
        AutoRelaxation r;
        std::vector<double> w;
        double move = 1e-3;
        for (int k = 0; k < 6; ++k, move *= 2.0) sweep(r, f, 4, move, w);
        check(w.size() == 6, "a sweep per call while moves grow 2x during the ramp", w.size());
        check(std::fabs(w[0] - 1.2) < 1e-15 && std::fabs(w[2] - 1.6) < 1e-15, "ramp from 1 towards the target", w[2]);
        check(std::fabs(w[5] - 1.8) < 1e-15, "the full target after the ramp", w[5]);
        check(std::fabs(f.x[12] - 63e-3) < 1e-15, "every move kept", f.x[12]);
    }
    {  // a jump (4x the last move) is undone, the over-relaxation halved, the sweep redone
        Fixture f;
        AutoRelaxation r;
        std::vector<double> w;
        sweep(r, f, 0, 1e-3, w);
        sweep(r, f, 0, 9e-4, w);
        const double before = f.x[12];
        r.sweep(f.level(), 0, [&] {
            w.push_back(r.omega(1.8));
            f.x[12] += w.size() == 3 ? 3.6e-3 : 5e-4;
        });
        check(w.size() == 4, "a jump runs the sweep twice", w.size());
        check(std::fabs(w[3] - 1.4) < 1e-15, "redone at half the over-relaxation", w[3]);
        check(std::fabs(f.x[12] - (before + 5e-4)) < 1e-15, "only the redone sweep's move is kept", f.x[12]);
        sweep(r, f, 0, 4e-4, w);
        check(std::fabs(w.back() - 1.4) < 1e-15, "the next sweeps keep the lower factor", w.back());
    }
    {  // a creep after the ramp: 1.5x a sweep, never a jump, 10x over the least halves
        Fixture f;
        AutoRelaxation r;
        std::vector<double> w;
        for (int k = 0; k < 3; ++k) sweep(r, f, 3, 1e-3, w);  // ramp over: least 1e-3
        double move = 1e-3;
        int creep_at = -1;
        for (int k = 0; k < 8 && creep_at < 0; ++k) {
            move *= 1.5;
            sweep(r, f, 3, move, w);
            if (r.omega(1.8) < 1.8) creep_at = k;
        }
        check(creep_at == 5, "backs off at the first move over 10x the least (1.5^6)", creep_at);
        check(std::fabs(r.omega(1.8) - 1.4) < 1e-15, "by halving the over-relaxation", r.omega(1.8));
    }
    {  // NaN is undone; reset restores the start
        Fixture f;
        AutoRelaxation r;
        std::vector<double> w;
        sweep(r, f, 0, 1e-3, w);
        const double before = f.x[12];
        r.sweep(f.level(), 0, [&] { f.x[12] += w.size() == 1 ? NAN : 2e-4, w.push_back(0); });
        check(f.x[12] == before + 2e-4, "a NaN sweep is undone and redone", f.x[12]);
        check(std::fabs(r.omega(1.8) - 1.4) < 1e-15, "and backs off", r.omega(1.8));
        r.reset();
        r.sweep(f.level(), 4, [&] { w.push_back(r.omega(1.8)); });
        check(std::fabs(w.back() - 1.2) < 1e-15, "reset: the ramp and the full share again", w.back());
    }
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
