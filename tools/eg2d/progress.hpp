// The progress line of a run (iteration, residual, rate) through eg2d_set_monitor,
// and the signals that stop a run: SIGINT (Ctrl-C) and SIGTERM make the
// monitor return nonzero, so the run stops cleanly, and an output set
// (output_set.hpp) stops before its next file and removes its stage.
#pragma once

#include <chrono>
#include <cstdio>

namespace eg2dtool {

class Progress {
public:
    // live: rewrite one line in place (a terminal); else print plain lines, one a second.
    // quiet: print nothing (the signals still stop the run).
    Progress(bool live, bool quiet);
    ~Progress();  // restores the previous SIGINT and SIGTERM handlers
    Progress(const Progress &) = delete;
    Progress &operator=(const Progress &) = delete;

    // The eg2d_monitor_fn; user is the Progress.
    static int monitor(void *user, int iteration, double residual);
    // Ends the live line (before any other output).
    void finish();
    // True once SIGINT or SIGTERM arrived.
    static bool interrupted();
    // The exit code of the signal that arrived, 128 + its number (130 SIGINT, 143 SIGTERM).
    static int interrupt_exit_code();
    // "SIGINT" or "SIGTERM".
    static const char *interrupt_name();

private:
    void print(int iteration, double residual);
    bool live_, quiet_, shown_ = false;
    std::chrono::steady_clock::time_point last_time_;
    int last_iteration_ = 0;
    double last_residual_ = 0;
    double rate_ = 0;
};

}  // namespace eg2dtool
