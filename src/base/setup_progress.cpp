#include "base/setup_progress.hpp"

#include <utility>

namespace eg2d {

namespace {
thread_local std::function<void()> current;
}  // namespace

void setup_tick() {
    if (current) current();
}

SetupProgress::SetupProgress(std::function<void()> tick) : outer_(std::move(current)) { current = std::move(tick); }

SetupProgress::~SetupProgress() { current = std::move(outer_); }

}  // namespace eg2d
