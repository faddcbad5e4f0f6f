// Every solver honours the control fields: with a TTM source Q (d_eta, the
// attraction of Ly & Norrison 2007 eq 14 toward the inner wall) and a Thomas-Middlecoff-like
// Phi (a_xi) on the annulus O-grid, each solver converges to the same grid as
// PSOR, and that grid is not the uncontrolled one. The control terms are put
// in through the core (no public control API exists yet), the rest through
// the C API. Also: ControlSet restarts a dynamic term when the grid,
// boundary or controls change.
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "api/handle.hpp"
#include "controls/control.hpp"
#include "domains.h"

namespace {

int failures = 0;
void check(bool ok, const char *what) {
    std::printf("%-70s %s\n", what, ok ? "ok" : "FAILED");
    if (!ok) ++failures;
}

class TestControl final : public eg2d::Control {
public:
    std::unique_ptr<eg2d::Control> clone() const override { return std::make_unique<TestControl>(*this); }
    void add_to(const eg2d::Grid &g, eg2d::ControlFields &f) const override {
        const int ni = g.ni(), nj = g.nj();
        const std::size_t n = static_cast<std::size_t>(ni) * nj;
        std::vector<double> &q = f.at(eg2d::Term::DEta, n), &phi = f.at(eg2d::Term::AXi, n);
        for (int j = 0; j < nj; ++j)
            for (int i = 0; i < ni; ++i) {
                const std::size_t k = i + static_cast<std::size_t>(ni) * j;
                q[k] += -40.0 * std::exp(-0.3 * j);  // pulls eta lines toward j = 0
                phi[k] += 0.1 * std::sin(2 * 3.14159265358979323846 * i / (ni - 1));
            }
    }
};

// Solves the annulus 33x17 with `solver`, with or without the controls.
std::vector<double> solve(int solver, bool controls, double *first_gap) {
    const int ni = 33, nj = 17;
    eg2d_grid *g = nullptr;
    eg2d_create(ni, nj, &g);
    domain_set_annulus(g, 1.0, 3.0);
    if (controls) {
        g->gen.controls().add(std::make_unique<TestControl>());
        g->gen.changed_controls();
    }
    eg2d_set_solver(g, solver);
    eg2d_set_tolerance(g, 1e-12);
    const int status = eg2d_solve(g);
    if (status != EG2D_OK) std::printf("  %s: %s\n", eg2d_solver_name(solver), eg2d_last_error(g));
    std::vector<double> xy(2 * static_cast<std::size_t>(ni) * nj);
    eg2d_get_coordinates(g, xy.data(), xy.data() + ni * nj);
    *first_gap = std::hypot(xy[ni] - xy[0], xy[ni * nj + ni] - xy[ni * nj]);  // node (0,1) - (0,0)
    eg2d_destroy(g);
    return status == EG2D_OK ? xy : std::vector<double>();
}

// A dynamic term that counts the calls the run makes on it.
class ProbeControl final : public eg2d::Control {
public:
    explicit ProbeControl(int *restarts) : restarts_(restarts) {}
    std::unique_ptr<eg2d::Control> clone() const override { return std::make_unique<ProbeControl>(*this); }
    void add_to(const eg2d::Grid &, eg2d::ControlFields &) const override {}
    bool dynamic() const override { return true; }
    bool restart() override {
        ++*restarts_;
        return false;
    }

private:
    int *restarts_;
};

// ControlSet restarts a dynamic term exactly when the grid, boundary or
// controls changed since its last update (its state belongs to the old
// grid), and not between updates of one grid (each eg2d_iterate call is a
// run: the state must carry over).
void restarts_on_change() {
    int restarts = 0;
    eg2d::Grid grid(9, 5);
    eg2d::Settings settings;
    eg2d::ControlSet set;
    set.add(std::make_unique<ProbeControl>(&restarts));
    set.advance(grid, settings, eg2d::ControlPace{});
    check(restarts == 1, "dynamic control: restarted at its first update");
    set.advance(grid, settings, eg2d::ControlPace{});
    set.advance(grid, settings, eg2d::ControlPace{});
    check(restarts == 1, "dynamic control: kept between updates of one grid");
    set.invalidate();
    set.advance(grid, settings, eg2d::ControlPace{});
    check(restarts == 2, "dynamic control: restarted after a change (invalidate)");
}

}  // namespace

int main() {
    restarts_on_change();
    double gap_plain = 0, gap_ref = 0;
    const std::vector<double> plain = solve(EG2D_SOLVER_PSOR, false, &gap_plain);
    const std::vector<double> ref = solve(EG2D_SOLVER_PSOR, true, &gap_ref);
    char what[160];
    std::snprintf(what, sizeof what, "psor: attraction shrinks the wall gap (%.4f -> %.4f)", gap_plain, gap_ref);
    check(!ref.empty() && gap_ref < 0.8 * gap_plain, what);
    for (int id = 0; id < 100; ++id) {
        if (!eg2d_solver_name(id) || id == EG2D_SOLVER_PSOR) continue;
        double gap = 0;
        const std::vector<double> xy = solve(id, true, &gap);
        double dev = 1e300;
        if (!xy.empty() && !ref.empty()) {
            dev = 0;
            for (std::size_t k = 0; k < xy.size(); ++k) dev = std::fmax(dev, std::fabs(xy[k] - ref[k]));
        }
        std::snprintf(what, sizeof what, "%s with controls: same grid as psor (max diff %.2e)", eg2d_solver_name(id),
                      dev);
        check(dev < 1e-9, what);
    }
    std::printf("%d failed\n", failures);
    return failures == 0 ? 0 : 1;
}
