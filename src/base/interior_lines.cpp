// The Grid's interior lines: setting, checking against the boundary, and
// writing them into the coordinates (base/interior_lines.hpp).
#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "base/grid.hpp"
#include "base/plane.hpp"

namespace eg2d {

namespace {

const char *family(bool xi) { return xi ? "xi" : "eta"; }

// Node (i, j) of the p-th point of a line.
NodeIJ line_node(const InteriorLine &l, int p) { return l.xi ? NodeIJ{l.index, p} : NodeIJ{p, l.index}; }

}  // namespace

void Grid::set_interior_line(bool xi, int index, const double *px, const double *py) {
    const int along = xi ? nj_ : ni_, across = xi ? ni_ : nj_;
    if (xi && topology() != Topology::Single)
        fail(Failure::Unsupported, format("a xi line (column %d) on the %s topology: interior columns are "
                                          "supported on single blocks only (rows on all three)",
                                          index, topology_name(topology())));
    if (index < 1 || index > across - 2)
        fail(Failure::Argument, format("%s line %d: the index must be in [1, %d] (an interior %s)", family(xi), index,
                                       across - 2, xi ? "column" : "row"));
    const std::size_t n = static_cast<std::size_t>(along);
    check_coordinates("interior line x", px, n);
    check_coordinates("interior line y", py, n);
    if (topology() == Topology::O) {
        const double L = bounding_diagonal(px, py, n);
        if (std::hypot(px[n - 1] - px[0], py[n - 1] - py[0]) > kCornerTolerance * L)
            fail(Failure::Boundary, format("eta line %d of an O-grid is not closed: first point (%.17g, %.17g) vs "
                                           "last (%.17g, %.17g)",
                                           index, px[0], py[0], px[n - 1], py[n - 1]));
    }
    Grid trial(*this);
    InteriorLine line{xi, index, std::vector<double>(px, px + n), std::vector<double>(py, py + n)};
    auto same = [&](const InteriorLine &l) { return l.xi == xi && l.index == index; };
    trial.lines_.erase(std::remove_if(trial.lines_.begin(), trial.lines_.end(), same), trial.lines_.end());
    trial.lines_.push_back(std::move(line));
    trial.check_interior_lines();
    trial.rebuild_connectivity();
    if (trial.initialized_) trial.restore_interior_lines();
    *this = std::move(trial);
}

void Grid::clear_interior_lines() {
    lines_.clear();
    rebuild_connectivity();
}

void Grid::check_interior_lines() const {
    Bounds box;
    for (const InteriorLine &l : lines_)
        for (std::size_t p = 0; p < l.x.size(); ++p) box.add(l.x[p], l.y[p]);
    const double tol = kCornerTolerance * std::max(box.diagonal(), extent());
    for (const InteriorLine &l : lines_) {
        const int n = static_cast<int>(l.x.size());
        // The ends lie on the sides the line runs between (an O-grid's rows
        // are closed curves with no ends on a side).
        if (topology() != Topology::O)
            for (int end : {0, n - 1}) {
                const Side side = l.xi ? (end == 0 ? Side::JMin : Side::JMax) : (end == 0 ? Side::IMin : Side::IMax);
                if (!side_set(side)) continue;
                const std::size_t k = static_cast<std::size_t>(l.index);
                const std::size_t e = static_cast<std::size_t>(end);
                const double bx = user_x_[static_cast<int>(side)][k], by = user_y_[static_cast<int>(side)][k];
                if (std::hypot(l.x[e] - bx, l.y[e] - by) > tol)
                    fail(Failure::Boundary,
                         format("%s line %d: its %s point (%.17g, %.17g) is not side %s's node %d (%.17g, %.17g)",
                                family(l.xi), l.index, end == 0 ? "first" : "last", l.x[e], l.y[e], side_name(side),
                                l.index, bx, by));
            }
        for (const InteriorLine &m : lines_) {  // a column and a row share one node
            if (!l.xi || m.xi) continue;
            const std::size_t a = static_cast<std::size_t>(m.index), b = static_cast<std::size_t>(l.index);
            if (std::hypot(l.x[a] - m.x[b], l.y[a] - m.y[b]) > tol)
                fail(Failure::Boundary, format("xi line %d and eta line %d cross at node (%d, %d), but their points "
                                               "there differ: (%.17g, %.17g) vs (%.17g, %.17g)",
                                               l.index, m.index, l.index, m.index, l.x[a], l.y[a], m.x[b], m.y[b]));
        }
    }
}

void Grid::restore_interior_lines() {
    for (const InteriorLine &l : lines_) {
        const int n = static_cast<int>(l.x.size());
        const bool closed = topology() == Topology::O;  // all of a closed row; column ni-1 is column 0
        for (int p = closed ? 0 : 1; p < n - 1; ++p) {
            const NodeIJ q = line_node(l, p);
            const std::size_t k = static_cast<std::size_t>(q.i) + static_cast<std::size_t>(ni_) * q.j;
            x[k] = l.x[static_cast<std::size_t>(p)];
            y[k] = l.y[static_cast<std::size_t>(p)];
        }
    }
    connectivity_.sync(x.data());
    connectivity_.sync(y.data());
}

}  // namespace eg2d
