// The progress line of a run (iteration, residual, rate) through eg2d_set_monitor,
// and Ctrl-C: SIGINT makes the monitor return nonzero, so the run stops cleanly.
#pragma once

#include <chrono>
#include <cstdio>

namespace eg2dtool {

class Progress {
public:
    // live: rewrite one line in place (a terminal); else print plain lines, one a second.
    // quiet: print nothing (SIGINT still stops the run).
    Progress(bool live, bool quiet);
    ~Progress();  // restores the previous SIGINT handler
    Progress(const Progress &) = delete;
    Progress &operator=(const Progress &) = delete;

    // The eg2d_monitor_fn; user is the Progress.
    static int monitor(void *user, int iteration, double residual);
    // Ends the live line (before any other output).
    void finish();
    // True once SIGINT arrived.
    static bool interrupted();

private:
    void print(int iteration, double residual);
    bool live_, quiet_, shown_ = false;
    std::chrono::steady_clock::time_point last_time_;
    int last_iteration_ = 0;
    double last_residual_ = 0;
    double rate_ = 0;
};

}  // namespace eg2dtool
