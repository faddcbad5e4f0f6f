// A control term (attraction, user arrays, orthogonality, adaptivity) adds its
// share to the ControlFields the operator reads. Adding one is adding a file
// with a Control subclass and the API call that creates it.
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "operator/control_fields.hpp"
#include "base/settings.hpp"
#include "base/grid.hpp"
#include "grid/wall_layer.hpp"

namespace eg2d {

// Which API call owns a control: a grid has at most one control of each kind
// (line and point sources share one); Other is any number of unnamed terms.
enum class ControlKind { Other, Sources, Arrays, Orthogonality, ParameterGrid, Weight };

// How far a dynamic term moves per update, as multiples of its own pace
// (tuned for solvers that move the grid a little per iteration). A solver
// that converges the grid for the current fields in every iteration (a
// multigrid cycle) can take larger steps: the grid has caught up with the
// last one by the time of the next (generator.cpp).
struct ControlPace {
    double relaxation = 1.0;  // times the under-relaxation of the update
    double step = 1.0;        // times the largest change per update
    // Accelerate the updates (Anderson, anderson.hpp): only meaningful when
    // the grid is converged for the last update, so that the control's
    // fixed-point map is a function of the control alone.
    bool accelerate = false;
    // One relaxation gain per node for both coefficients (why: wall.cpp,
    // damped_update). Set from Solver::marches_in_time.
    bool one_gain = false;
};

class Control {
public:
    virtual ~Control() = default;
    virtual std::unique_ptr<Control> clone() const = 0;
    virtual ControlKind kind() const { return ControlKind::Other; }
    // Adds this term to `fields` for the grid as it is now. Never changes the
    // control's state: the residual and the run see the same fields.
    virtual void add_to(const Grid &grid, ControlFields &fields) const = 0;
    // True for terms that depend on the interior grid and are updated
    // between iterations (wall orthogonality); false for terms fixed by the
    // boundary or the user's input, computed once per run.
    virtual bool dynamic() const { return false; }
    // Dynamic terms: one update of the state from the grid, given the sum of
    // every static term (`others`). Called by the run before each iteration.
    // Returns whether what add_to adds changed (false: a state that already
    // meets its targets is left as it is, and the residual still holds).
    virtual bool advance(const Grid &, const ControlFields & /*others*/, const Settings &, const ControlPace &) {
        return false;
    }
    // Dynamic terms, after advance(): how far the state still is from the
    // state the grid asks for, as the largest change |dR|/diag of a node
    // equation that closing the gap would make (NUMERICS.md's residual
    // before the division by L). A run is converged only when this is below
    // the tolerance too: the residual alone cannot see a control that moves
    // slowly (an under-relaxed node that oscillated and was damped).
    virtual double mismatch() const { return 0.0; }
    // Dynamic terms, after advance(): whether what the term holds besides
    // the mismatch is met (the graded wall layer's first cells and angles,
    // measured against the cells' own height, not the domain's extent).
    virtual bool settled() const { return true; }
    // Dynamic terms: the grid, boundary or controls changed since the last
    // update (ControlSet::dynamic_pending): start again from the state of a
    // new term. The old state belongs to another grid; kept, the wall
    // control's converged coefficients applied to a re-initialised TFI start
    // folded it (NACA0012 129x33, first cell 1e-5: not converged in 100000
    // iterations, 9 folded cells; the same on a new far field).
    // Returns whether what add_to adds changed.
    virtual bool restart() { return false; }
    // Builds into the grid what this control fixes before the solve (the
    // wall control's marched layer, held by Grid::hold_rows), with the rows
    // above filled as a start when `fill_above`. The run calls it after an
    // initialisation and after any change of grid, boundary or controls.
    // Default: nothing.
    virtual WallLayerShape shape_start(Grid &, const Settings &, bool /*fill_above*/) { return {}; }
    // Throws Argument when the control cannot act on this grid (a wall's
    // first cell below what double precision resolves); called before a
    // start grid or a run changes anything.
    virtual void check(const Grid &) const {}
    // True when shape_start re-spaces the start's lines (the graded wall
    // layer): the run then gives it the Winslow grid without controls.
    virtual bool grades(const Grid &, const Settings &) const { return false; }
    // True when shape_start's shape needs a multigrid cycle of the solve on
    // the fields it set, whatever the run's solver, before shape_after_cycle
    // finishes it on the grid that cycle made (the graded layer's start not
    // kept: grid/graded_layer.hpp's reshape_graded_layer).
    // The first-cell height asked of each side (EG2D_SIDE_* order): > 0 a
    // wall with that height, 0 the angle alone, < 0 none (a set of blocks
    // grades its lines across the blocks from these: blocks/set_wall_layer.hpp).
    virtual std::array<double, 4> wall_heights() const { return {-1.0, -1.0, -1.0, -1.0}; }
    virtual bool shapes_after_cycle() const { return false; }
    virtual void shape_after_cycle(Grid &) {}
};

// The controls of a grid and the fields they add up to.
class ControlSet {
public:
    ControlSet() = default;
    ControlSet(const ControlSet &other);
    ControlSet &operator=(const ControlSet &other);
    ControlSet(ControlSet &&) = default;
    ControlSet &operator=(ControlSet &&) = default;

    // Adds a term; put() replaces the control of the same kind, if any.
    void add(std::unique_ptr<Control> c) { controls_.push_back(std::move(c)); stale_ = unsettled_ = true; }
    void put(std::unique_ptr<Control> c);
    void remove(ControlKind k);
    Control *find(ControlKind k);
    void clear() { controls_.clear(); fields_.clear(); static_.clear(); stale_ = unsettled_ = true; }
    bool empty() const { return controls_.empty(); }
    bool has_dynamic() const;

    // Recomputes the fields if anything changed (or always at the start of a run).
    const ControlFields &update(const Grid &grid, bool start_of_run);
    // One update of the dynamic terms, then the fields (same object as
    // fields()); returns whether the fields changed.
    bool advance(const Grid &grid, const Settings &settings, const ControlPace &pace);
    const ControlFields &fields() const { return fields_; }
    // The largest mismatch() of the dynamic terms (0 without any).
    double mismatch() const;
    // Every dynamic term settled().
    bool settled() const;
    void invalidate() { stale_ = unsettled_ = true; }
    // True while a dynamic term has not been updated since the controls, the
    // boundary or the start grid last changed: its fields are still those of
    // another grid (a wall control starts from zero), so a residual computed
    // with them cannot say the run has converged.
    bool dynamic_pending() const { return unsettled_ && has_dynamic(); }

private:
    void sum_dynamic(const Grid &grid);

    std::vector<std::unique_ptr<Control>> controls_;
    ControlFields static_;  // the static terms alone
    ControlFields fields_;  // everything
    bool stale_ = true;
    bool unsettled_ = true;  // see dynamic_pending()
};

}  // namespace eg2d
