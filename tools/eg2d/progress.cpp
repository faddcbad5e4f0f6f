#include "progress.hpp"

#include <csignal>
#include <cmath>

namespace eg2dtool {

namespace {
volatile std::sig_atomic_t signal_seen = 0;  // the signal's number
struct sigaction previous_int, previous_term;

extern "C" void on_signal(int number) { signal_seen = number; }
}  // namespace

Progress::Progress(bool live, bool quiet) : live_(live), quiet_(quiet) {
    signal_seen = 0;
    struct sigaction a = {};
    a.sa_handler = on_signal;
    sigemptyset(&a.sa_mask);
    a.sa_flags = SA_RESETHAND;  // a second Ctrl-C (or SIGTERM) ends the program the usual way
    sigaction(SIGINT, &a, &previous_int);
    sigaction(SIGTERM, &a, &previous_term);
    last_time_ = std::chrono::steady_clock::now();
}

Progress::~Progress() {
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
}

bool Progress::interrupted() { return signal_seen != 0; }

int Progress::interrupt_exit_code() { return 128 + (signal_seen ? static_cast<int>(signal_seen) : SIGINT); }

const char *Progress::interrupt_name() { return signal_seen == SIGTERM ? "SIGTERM" : "SIGINT"; }

void Progress::print(int iteration, double residual) {
    char rate[32] = "-";  // unknown until two lines apart
    if (rate_ > 0) std::snprintf(rate, sizeof rate, "%.4f", rate_);
    if (live_)
        std::printf("\r  iteration %8d  residual %.3e  rate %s/iteration ", iteration, residual, rate);
    else
        std::printf("  iteration %d  residual %.3e  rate %s/iteration\n", iteration, residual, rate);
    std::fflush(stdout);
    shown_ = true;
}

int Progress::monitor(void *user, int iteration, double residual) {
    Progress &p = *static_cast<Progress *>(user);
    if (signal_seen) return 1;  // in the set-up too: the march stops at its next layer
    if (p.quiet_ || std::isinf(residual)) return 0;  // no residual yet (the set-up's calls)
    const auto now = std::chrono::steady_clock::now();
    const double since = std::chrono::duration<double>(now - p.last_time_).count();
    // The first line at once, then a few a second on a terminal, one a second otherwise.
    if (p.shown_ && since < (p.live_ ? 0.2 : 1.0)) return 0;
    // rate: the mean factor by which the residual fell per iteration since the last line
    if (p.last_iteration_ > 0 && iteration > p.last_iteration_ && p.last_residual_ > 0 && residual > 0)
        p.rate_ = std::pow(residual / p.last_residual_, 1.0 / (iteration - p.last_iteration_));
    p.print(iteration, residual);
    p.last_time_ = now;
    p.last_iteration_ = iteration;
    p.last_residual_ = residual;
    return 0;
}

void Progress::finish() {
    if (live_ && shown_) std::printf("\r%72s\r", "");
    std::fflush(stdout);
    shown_ = false;
}

}  // namespace eg2dtool
