// The grid, or a set of blocks, as an unstructured mesh, for the
// solver-ready formats (SU2, OpenFOAM): points with duplicates merged (an
// O-grid's column ni-1 is column 0, a C-grid's upper wake node (ni-1-i, 0)
// is the lower wake node (i, 0), a set's joined nodes are one point),
// quadrilateral cells with their corners counter-clockwise (a grid's cells
// in the order i + (ni-1) j, a set's block after block), and the boundary
// edges grouped by patch name (base/patches.hpp; a set's blocks' patches of
// the same name are one patch, its joins are no patch), each edge running
// counter-clockwise round its cell so that its right-hand normal points out
// of the domain.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "base/grid.hpp"
#include "base/patches.hpp"

namespace eg2d {

struct MeshEdge {
    int a, b;  // point ids, counter-clockwise round `cell`
    int cell;
};

struct MeshPatch {
    std::string name;
    PatchType type;
    std::vector<MeshEdge> edges;
};

// Cells first..first+count-1 of a mesh, named: a set's block.
struct CellZone {
    std::string name;
    std::size_t first, count;
};

struct UnstructuredMesh {
    std::vector<double> x, y;                // per point
    std::vector<std::array<int, 4>> quads;   // per cell, counter-clockwise
    std::vector<MeshPatch> patches;          // every boundary edge in exactly one
    std::vector<CellZone> zones;             // a set's blocks (none for one grid)
    std::size_t points() const { return x.size(); }
    std::size_t cells() const { return quads.size(); }
};

// Throws what resolve_patches throws (a C-grid without JMIN, a patch on the
// cut).
UnstructuredMesh unstructured_mesh(const Grid &g);

// A set of blocks: each block's grid and which edges of its sides lie on a
// join (joined[side][q]: the edge from node q to q+1; those edges are
// interior); twins: pairs of nodes (block, node index k = i + ni j) that are
// one point.
struct MeshBlock {
    const Grid *grid;
    std::array<std::vector<char>, 4> joined;
};
struct MeshTwin {
    int block_a;
    std::size_t node_a;
    int block_b;
    std::size_t node_b;
};
UnstructuredMesh unstructured_mesh(const std::vector<MeshBlock> &blocks, const std::vector<MeshTwin> &twins);

// Internal edges between two cells (the cut's and the joins' included),
// each once, from the lower-numbered cell (owner) to the higher
// (neighbour), counter-clockwise round the owner; sorted by owner, then
// neighbour (OpenFOAM's upper-triangular order). Throws Failure::Argument
// naming the edge if the boundary edges found are not exactly those of the
// patches.
struct InternalEdge {
    int a, b, owner, neighbour;
};
std::vector<InternalEdge> internal_edges(const UnstructuredMesh &m);

}  // namespace eg2d
