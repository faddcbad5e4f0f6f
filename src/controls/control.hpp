// A control term (attraction, user arrays, orthogonality, adaptivity) adds its
// share to the ControlFields the operator reads. Adding one is adding a file
// with a Control subclass and the API call that creates it.
#pragma once
#include <memory>
#include <vector>

#include "controls/control_fields.hpp"
#include "grid/grid.hpp"

namespace eg2d {

class Control {
public:
    virtual ~Control() = default;
    virtual std::unique_ptr<Control> clone() const = 0;
    // Adds this term to `fields` for the grid as it is now.
    virtual void add_to(const Grid &grid, ControlFields &fields) const = 0;
    // True for terms that depend on the interior grid and are recomputed
    // between iterations (wall orthogonality); false for terms fixed by the
    // boundary or the user's input, computed once per run.
    virtual bool dynamic() const { return false; }
};

// The controls of a grid and the fields they add up to.
class ControlSet {
public:
    ControlSet() = default;
    ControlSet(const ControlSet &other);
    ControlSet &operator=(const ControlSet &other);
    ControlSet(ControlSet &&) = default;
    ControlSet &operator=(ControlSet &&) = default;

    void add(std::unique_ptr<Control> c) { controls_.push_back(std::move(c)); stale_ = true; }
    void clear() { controls_.clear(); fields_.clear(); stale_ = true; }
    bool empty() const { return controls_.empty(); }
    bool has_dynamic() const;

    // Recomputes the fields if anything changed (or always, for dynamic terms).
    const ControlFields &update(const Grid &grid, bool start_of_run);
    const ControlFields &fields() const { return fields_; }
    void invalidate() { stale_ = true; }

private:
    std::vector<std::unique_ptr<Control>> controls_;
    ControlFields fields_;
    bool stale_ = true;
};

}  // namespace eg2d
