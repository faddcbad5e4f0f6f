// A set of blocks solved as one grid (Thompson, Soni & Weatherill 1999,
// ch. 6): single-block grids joined node to node along whole sides or parts
// of sides. The set refers to the blocks' generators (it owns none): each
// block keeps its boundary, size and settings, and receives the set's
// solution.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "base/grid.hpp"

namespace eg2d {

class Generator;

// Nodes first..last (inclusive, along the side in increasing index; first >
// last runs the other way) of a block's side.
struct SideRange {
    int block;
    Side side;
    int first, last;
    int count() const { return (first <= last ? last - first : first - last) + 1; }
    int step() const { return first <= last ? 1 : -1; }
    // The t-th node of the range (t in [0, count)).
    int at(int t) const { return first + t * step(); }
};

// Node t of `a` is node t of `b`. A held join's nodes stay where the
// blocks' sides put them (a boundary between the blocks, as blockMesh's);
// the others move like interior nodes.
struct Join {
    SideRange a, b;
    bool held = false;
};

class BlockSet {
public:
    // The block's index. Throws Argument for a block already in the set.
    int add(Generator *block);
    // The block is gone (its handle was destroyed): the set refuses to run.
    void forget(const Generator *block);
    int size() const { return static_cast<int>(blocks_.size()); }
    Generator *block(int b) const { return blocks_[static_cast<std::size_t>(b)]; }
    const std::vector<Join> &joins() const { return joins_; }

    // Checks what can be checked without coordinates (blocks exist, are
    // single blocks, the sides and ranges fit, counts agree, no node of a
    // side is joined twice); Argument naming the join otherwise. Strong
    // guarantee.
    void join(const Join &j);
    // Block b's name, "block<b>" until named: the zone's in the files that
    // hold a zone a block (CGNS, VTK multiblock) and the merged OpenFOAM
    // mesh's cellZones.
    const std::string &name(int b) const { return names_[static_cast<std::size_t>(b)]; }
    // Names block b: 1 to 32 letters, digits, '_' or '-', a letter first (a
    // CGNS name, an XML attribute, part of a file name), no other block's
    // name, and "block" with digits only as b's own default (a block added
    // later gets that). Argument naming the rule or the other block.
    void rename(int b, const std::string &name);
    // Join `index` (in the order join() took them) held, or free again.
    // Argument for an index the set has not.
    void hold(int index, bool held);

    // Before a solve: every block present, its boundary complete, the same
    // system, no controls; each join's nodes coincide (kCornerTolerance of
    // the set's extent); the set connected. Failure::Argument, Boundary or
    // State naming the block, side and node.
    void check() const;
    // Every block initialised and each join's nodes where both its blocks'
    // grids have them now (within kCornerTolerance of the extent).
    bool grids_agree() const;
    // The diagonal of the bounding box of every block's boundary.
    double extent() const;

private:
    // The distance between join j's node t in its two blocks, on the sides
    // as given or on the grids as they are now; the two nodes in (xa, ya), (xb, yb).
    double join_gap(const Join &j, int t, bool given, double &xa, double &ya, double &xb, double &yb) const;

    std::vector<Generator *> blocks_;  // nullptr: forgotten
    std::vector<std::string> names_;
    std::vector<Join> joins_;
};

// "block 2 side IMIN nodes 0..16" for messages.
std::string describe(const SideRange &r);

}  // namespace eg2d
