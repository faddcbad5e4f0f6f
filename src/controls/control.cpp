#include "controls/control.hpp"

namespace eg2d {

ControlSet::ControlSet(const ControlSet &other) : fields_(other.fields_), stale_(other.stale_) {
    for (const auto &c : other.controls_) controls_.push_back(c->clone());
}

ControlSet &ControlSet::operator=(const ControlSet &other) {
    if (this != &other) {
        ControlSet copy(other);
        *this = std::move(copy);
    }
    return *this;
}

bool ControlSet::has_dynamic() const {
    for (const auto &c : controls_)
        if (c->dynamic()) return true;
    return false;
}

const ControlFields &ControlSet::update(const Grid &grid, bool start_of_run) {
    if (stale_ || start_of_run || has_dynamic()) {
        ControlFields next;
        for (const auto &c : controls_) c->add_to(grid, next);
        fields_ = std::move(next);
        stale_ = false;
    }
    return fields_;
}

}  // namespace eg2d
