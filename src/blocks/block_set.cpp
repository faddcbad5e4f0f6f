#include "blocks/block_set.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "base/plane.hpp"
#include "generator/generator.hpp"
#include "operator/system.hpp"

namespace eg2d {

std::string describe(const SideRange &r) {
    return format("block %d side %s nodes %d..%d", r.block, side_name(r.side), r.first, r.last);
}

int BlockSet::add(Generator *block) {
    if (std::find(blocks_.begin(), blocks_.end(), block) != blocks_.end())
        fail(Failure::Argument, format("the grid is block %d of this set already",
                                       static_cast<int>(std::find(blocks_.begin(), blocks_.end(), block) - blocks_.begin())));
    names_.reserve(names_.size() + 1);
    blocks_.push_back(block);
    names_.push_back(format("block%d", size() - 1));
    return size() - 1;
}

void BlockSet::rename(int b, const std::string &name) {
    if (b < 0 || b >= size())
        fail(Failure::Argument, format("block = %d: the set has %s", b,
                                       size() ? format("blocks 0..%d", size() - 1).c_str() : "no blocks"));
    bool good = !name.empty() && name.size() <= 32 && std::isalpha(static_cast<unsigned char>(name[0]));
    for (char ch : name) good = good && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-');
    if (!good)
        fail(Failure::Argument, format("name \"%.40s\": a block's name is 1 to 32 letters, digits, '_' or '-', a "
                                       "letter first", name.c_str()));
    if (name.size() > 5 && name.compare(0, 5, "block") == 0 &&
        name.find_first_not_of("0123456789", 5) == std::string::npos && name != format("block%d", b))
        fail(Failure::Argument, format("name \"%s\": \"block\" and a number name blocks by their index (this is "
                                       "block %d)", name.c_str(), b));
    for (int o = 0; o < size(); ++o)
        if (o != b && names_[static_cast<std::size_t>(o)] == name)
            fail(Failure::Argument, format("name \"%s\": block %d has that name", name.c_str(), o));
    names_[static_cast<std::size_t>(b)] = name;
}

void BlockSet::forget(const Generator *block) {
    for (Generator *&b : blocks_)
        if (b == block) b = nullptr;
}

namespace {

void check_range(const BlockSet &set, const SideRange &r, const char *which) {
    if (r.block < 0 || r.block >= set.size())
        fail(Failure::Argument, format("join: block_%s = %d: the set has blocks 0..%d", which, r.block, set.size() - 1));
    if (static_cast<int>(r.side) < 0 || static_cast<int>(r.side) > 3)
        fail(Failure::Argument, format("join: side_%s = %d: not EG2D_SIDE_JMIN, IMAX, JMAX or IMIN", which,
                                       static_cast<int>(r.side)));
    const Generator *g = set.block(r.block);
    if (!g) fail(Failure::State, format("join: block %d was destroyed", r.block));
    if (g->grid().topology() != Topology::Single)
        fail(Failure::Unsupported, format("join: block %d is an %s: a set joins single blocks (a block's own cut is "
                                          "its O- or C-grid topology)", r.block, topology_name(g->grid().topology())));
    const int n = g->grid().side_length(r.side);
    if (std::min(r.first, r.last) < 0 || std::max(r.first, r.last) > n - 1)
        fail(Failure::Argument, format("join: %s: side %s of block %d has nodes 0..%d", describe(r).c_str(),
                                       side_name(r.side), r.block, n - 1));
    if (r.first == r.last)
        fail(Failure::Argument, format("join: %s: a join spans at least two nodes", describe(r).c_str()));
}

// Do the ranges share a node of the same side, other than an end node they
// may share (two joins meeting at a vertex)?
bool overlap(const SideRange &p, const SideRange &q) {
    if (p.block != q.block || p.side != q.side) return false;
    const int p0 = std::min(p.first, p.last), p1 = std::max(p.first, p.last);
    const int q0 = std::min(q.first, q.last), q1 = std::max(q.first, q.last);
    return std::max(p0, q0) < std::min(p1, q1);
}

}  // namespace

void BlockSet::join(const Join &j) {
    check_range(*this, j.a, "a");
    check_range(*this, j.b, "b");
    if (j.a.count() != j.b.count())
        fail(Failure::Argument, format("join: %s has %d nodes, %s has %d: joins match node to node", describe(j.a).c_str(),
                                       j.a.count(), describe(j.b).c_str(), j.b.count()));
    if (overlap(j.a, j.b))
        fail(Failure::Argument, format("join: %s and %s share nodes of the same side", describe(j.a).c_str(),
                                       describe(j.b).c_str()));
    for (const Join &o : joins_)
        for (const SideRange &mine : {j.a, j.b})
            for (int k = 0; k < 2; ++k)
                if (overlap(mine, k == 0 ? o.a : o.b))
                    fail(Failure::Argument, format("join: %s is joined already (to %s)", describe(mine).c_str(),
                                                   describe(k == 0 ? o.b : o.a).c_str()));
    joins_.push_back(j);
}

void BlockSet::hold(int index, bool held) {
    if (index < 0 || index >= static_cast<int>(joins_.size()))
        fail(Failure::Argument, joins_.empty() ? format("join = %d: the set has no joins", index)
                                               : format("join = %d: the set has joins 0..%d", index,
                                                        static_cast<int>(joins_.size()) - 1));
    joins_[static_cast<std::size_t>(index)].held = held;
}

double BlockSet::join_gap(const Join &j, int t, bool given, double &xa, double &ya, double &xb, double &yb) const {
    const Grid &ga = blocks_[static_cast<std::size_t>(j.a.block)]->grid();
    const Grid &gb = blocks_[static_cast<std::size_t>(j.b.block)]->grid();
    const int pa = j.a.at(t), pb = j.b.at(t);
    const std::size_t ka = side_node(ga, j.a.side, pa), kb = side_node(gb, j.b.side, pb);
    xa = given ? ga.given_x(j.a.side, pa) : ga.x[ka];
    ya = given ? ga.given_y(j.a.side, pa) : ga.y[ka];
    xb = given ? gb.given_x(j.b.side, pb) : gb.x[kb];
    yb = given ? gb.given_y(j.b.side, pb) : gb.y[kb];
    return std::hypot(xa - xb, ya - yb);
}

bool BlockSet::grids_agree() const {
    const double tol = kCornerTolerance * extent();
    for (const Join &j : joins_) {
        if (!blocks_[static_cast<std::size_t>(j.a.block)]->grid().initialized() ||
            !blocks_[static_cast<std::size_t>(j.b.block)]->grid().initialized())
            return false;
        double xa, ya, xb, yb;
        for (int t = 0; t < j.a.count(); ++t)
            if (!(join_gap(j, t, false, xa, ya, xb, yb) <= tol)) return false;
    }
    return true;
}

double BlockSet::extent() const {
    double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
    for (const Generator *g : blocks_) {
        if (!g) continue;
        const Grid &grid = g->grid();
        for (int s = 0; s < 4; ++s)
            for (int p = 0; p < grid.side_length(Side(s)); ++p) {
                const std::size_t k = side_node(grid, Side(s), p);
                lo_x = std::min(lo_x, grid.x[k]);
                hi_x = std::max(hi_x, grid.x[k]);
                lo_y = std::min(lo_y, grid.y[k]);
                hi_y = std::max(hi_y, grid.y[k]);
            }
    }
    return std::hypot(hi_x - lo_x, hi_y - lo_y);
}

void BlockSet::check() const {
    if (blocks_.empty()) fail(Failure::State, "the set has no blocks (eg2d_blocks_add)");
    for (int b = 0; b < size(); ++b) {
        const Generator *g = blocks_[static_cast<std::size_t>(b)];
        if (!g) fail(Failure::State, format("block %d was destroyed", b));
        if (g->grid().topology() != Topology::Single)
            fail(Failure::Unsupported, format("block %d is an %s: a set joins single blocks", b,
                                              topology_name(g->grid().topology())));
        if (!g->grid().boundary_complete()) fail(Failure::State, format("block %d: its boundary is not complete", b));
        if (g->system() != blocks_[0]->system())
            fail(Failure::State, format("block %d solves the %s system, block 0 the %s: a set solves one system", b,
                                        system_name(g->system()), system_name(blocks_[0]->system())));
        if (g->system() == System::Variational)
            fail(Failure::Unsupported, format("block %d: the variational system on a set of blocks is not available "
                                              "yet (EG2D_SYSTEM_LAPLACE or EG2D_SYSTEM_WINSLOW)", b));
        // (a wall control is the graded layer across the set: set_wall_layer.hpp)
        const ControlSet &controls = g->controls();
        if (!controls.empty() && g->system() != System::Winslow)
            fail(Failure::State, format("block %d has control terms but the system is %s: controls need "
                                        "EG2D_SYSTEM_WINSLOW (or clear the controls)", b, system_name(g->system())));
        if (!g->grid().interior_lines().empty())
            fail(Failure::Unsupported, format("block %d has interior lines: not available on a set of blocks yet", b));
    }
    const double tol = kCornerTolerance * extent();
    for (const Join &j : joins_) {
        // The sides as given: a solve moves the joined nodes, and a block
        // initialised again after one has them back where its sides put them.
        for (int t = 0; t < j.a.count(); ++t) {
            double xa, ya, xb, yb;
            const double d = join_gap(j, t, true, xa, ya, xb, yb);
            if (!(d <= tol))
                fail(Failure::Boundary,
                     format("join %s to %s: node %d of block %d's side %s = (%.17g, %.17g) and node %d of block %d's "
                            "side %s = (%.17g, %.17g) are %.3g apart (tolerance %.3g)", describe(j.a).c_str(),
                            describe(j.b).c_str(), j.a.at(t), j.a.block, side_name(j.a.side), xa, ya, j.b.at(t),
                            j.b.block, side_name(j.b.side), xb, yb, d, tol));
        }
    }
    // Connected: a union-find over the joins.
    std::vector<int> root(blocks_.size());
    for (std::size_t b = 0; b < root.size(); ++b) root[b] = static_cast<int>(b);
    auto find = [&](int b) {
        while (root[static_cast<std::size_t>(b)] != b) b = root[static_cast<std::size_t>(b)];
        return b;
    };
    for (const Join &j : joins_) root[static_cast<std::size_t>(find(j.a.block))] = find(j.b.block);
    for (int b = 1; b < size(); ++b)
        if (find(b) != find(0))
            fail(Failure::State, format("the set is not connected: no chain of joins from block 0 to block %d", b));
}

}  // namespace eg2d
