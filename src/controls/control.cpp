#include "controls/control.hpp"

#include <algorithm>

namespace eg2d {

ControlSet::ControlSet(const ControlSet &other)
    : static_(other.static_), fields_(other.fields_), stale_(other.stale_), unsettled_(other.unsettled_) {
    for (const auto &c : other.controls_) controls_.push_back(c->clone());
}

ControlSet &ControlSet::operator=(const ControlSet &other) {
    if (this != &other) {
        ControlSet copy(other);
        *this = std::move(copy);
    }
    return *this;
}

void ControlSet::put(std::unique_ptr<Control> c) {
    if (c->kind() == ControlKind::Other) return add(std::move(c));
    for (auto &old : controls_)
        if (old->kind() == c->kind()) {
            old = std::move(c);
            stale_ = unsettled_ = true;
            return;
        }
    controls_.push_back(std::move(c));
    stale_ = unsettled_ = true;
}

void ControlSet::remove(ControlKind k) {
    for (auto it = controls_.begin(); it != controls_.end(); ++it)
        if ((*it)->kind() == k) {
            controls_.erase(it);
            stale_ = unsettled_ = true;
            return;
        }
}

Control *ControlSet::find(ControlKind k) {
    for (auto &c : controls_)
        if (c->kind() == k) return c.get();
    return nullptr;
}

bool ControlSet::has_dynamic() const {
    for (const auto &c : controls_)
        if (c->dynamic()) return true;
    return false;
}

void ControlSet::sum_dynamic(const Grid &grid) {
    // In place, into the storage it had (same object: a Problem holding a
    // reference sees it; new vectors each update were a tenth of a straight
    // channel's graded run, in page faults). A throw leaves it part-summed:
    // every run starts with update(), which sums it again.
    for (int t = 0; t < kTermCount; ++t) {
        std::vector<double> &f = fields_.term[static_cast<std::size_t>(t)];
        const std::vector<double> &s = static_.term[static_cast<std::size_t>(t)];
        if (s.empty()) f.clear();  // keeps its capacity for at()
        else f.assign(s.begin(), s.end());
    }
    for (const auto &c : controls_)
        if (c->dynamic()) c->add_to(grid, fields_);
}

const ControlFields &ControlSet::update(const Grid &grid, bool start_of_run) {
    if (stale_ || start_of_run) {
        ControlFields next;
        for (const auto &c : controls_)
            if (!c->dynamic()) c->add_to(grid, next);
        static_ = std::move(next);
        stale_ = false;
    }
    if (has_dynamic()) sum_dynamic(grid);
    else fields_ = static_;
    return fields_;
}

bool ControlSet::settled() const {
    for (const auto &c : controls_)
        if (c->dynamic() && !c->settled()) return false;
    return true;
}

double ControlSet::mismatch() const {
    double m = 0.0;
    for (const auto &c : controls_)
        if (c->dynamic()) m = std::max(m, c->mismatch());
    return m;
}

bool ControlSet::advance(const Grid &grid, const Settings &settings, const ControlPace &pace) {
    const bool changed = unsettled_;
    unsettled_ = false;
    bool moved = stale_;
    if (stale_) update(grid, true);
    for (const auto &c : controls_)
        if (c->dynamic()) {
            if (changed) moved = c->restart() || moved;
            moved = c->advance(grid, static_, settings, pace) || moved;
        }
    if (moved) sum_dynamic(grid);
    return moved;
}

}  // namespace eg2d
