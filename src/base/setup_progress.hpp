// Progress before a run's first iteration: the long steps of its set-up (a
// wall layer's march, layer by layer) call setup_tick(), which calls what
// the run installed (Generator::run: the monitor, which cancels by
// throwing). Thread-local: a run and its set-up are on one thread, and a
// grid on another thread has its own run.
#pragma once
#include <functional>

namespace eg2d {

void setup_tick();

// Installs `tick` for setup_tick() on this thread for its lifetime.
class SetupProgress {
public:
    explicit SetupProgress(std::function<void()> tick);
    ~SetupProgress();
    SetupProgress(const SetupProgress &) = delete;
    SetupProgress &operator=(const SetupProgress &) = delete;

private:
    std::function<void()> outer_;
};

}  // namespace eg2d
