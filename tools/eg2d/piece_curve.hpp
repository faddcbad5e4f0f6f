// The nodes of a side piece placed by the library's curves and distributions
// (eg2d_curve_*, eg2d_curve_points): formulas, points, NACA sections and
// airfoil files, by arc length. Refused as "not available in this build" when
// the library has no curves.
#pragma once

#include <memory>
#include <vector>

#include "formula.hpp"

typedef struct eg2d_grid eg2d_grid;
#include "side_spec.hpp"

namespace eg2dtool {

// True when the piece needs a library curve (a distribution, a curve kind, an airfoil).
bool needs_curve(const SidePiece &piece);

// The distribution named by a case file: "uniform" or a table {kind = ..., ...}.
Distribution parse_distribution(const toml::node &node, const Location &where, const Constants &constants);

// n >= 2 nodes of the piece along its curve.
void curve_nodes(const SidePiece &piece, int n, const Constants &constants, std::vector<double> &x,
                 std::vector<double> &y);

// A side whose nodes slide along its curve during the run (EG2D_CURVE_SLIDING,
// eg2d_set_side_curve): a single piece. Keeps the curve (and a formula's
// callback) alive as long as the run may use it.
class SlidingSide {
public:
    SlidingSide(eg2d_grid *grid, const SideSpec &spec, const Constants &constants);

private:
    std::shared_ptr<void> keep_;
};

}  // namespace eg2dtool
