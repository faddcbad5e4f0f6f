// What a run actually did: the solver, the multigrid levels it used, and every
// change of strategy on the way (a level dropped, a fall back to sweeps, a
// start thrown away), so that none of them is silent. The Generator owns one
// per run; solvers note into it through Problem::report.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace eg2d {

struct RunEvent {
    int iteration;        // the iteration during which it happened (1-based)
    std::string message;  // "multigrid: ..." in plain words, with the reason
};

struct RunReport {
    int solver = -1;        // EG2D_SOLVER_* of the run
    int levels = 1;         // grid levels in use at the end (1: the fine grid alone)
    int levels_built = 1;   // levels the size allows (multigrid, nested)
    int iteration = 0;      // the iteration under way, stamped on events
    std::vector<RunEvent> events;

    void note(std::string message) { events.push_back({iteration, std::move(message)}); }
};

}  // namespace eg2d
