// The grid as an unstructured mesh, for the solver-ready formats (SU2,
// OpenFOAM): points with the cut's duplicate nodes merged (an O-grid's
// column ni-1 is column 0, a C-grid's upper wake node (ni-1-i, 0) is the
// lower wake node (i, 0)), quadrilateral cells with their corners
// counter-clockwise, and the boundary edges grouped by patch name
// (base/patches.hpp), each edge running counter-clockwise round its cell so
// that its right-hand normal points out of the domain.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "base/grid.hpp"
#include "base/patches.hpp"

namespace eg2d {

struct MeshEdge {
    int a, b;  // merged point ids, counter-clockwise round `cell`
    int cell;  // i + (ni-1) j
};

struct MeshPatch {
    std::string name;
    PatchType type;
    std::vector<MeshEdge> edges;
};

struct UnstructuredMesh {
    int ni, nj;
    std::vector<int> point_of;           // node k = i + ni j -> merged point id
    std::vector<std::size_t> node_of;    // point id -> its first node k (for x, y)
    bool counter_clockwise;              // whether (i,j),(i+1,j),(i+1,j+1),(i,j+1) runs so
    std::vector<MeshPatch> patches;      // every boundary edge in exactly one
    std::size_t points() const { return node_of.size(); }
    std::size_t cells() const { return static_cast<std::size_t>(ni - 1) * static_cast<std::size_t>(nj - 1); }
    // Corners of cell (i, j) as merged point ids, counter-clockwise.
    std::array<int, 4> cell(int i, int j) const;
};

// Throws what resolve_patches throws (a C-grid without JMIN, a patch on the
// cut).
UnstructuredMesh unstructured_mesh(const Grid &g);

// Internal edges between two cells (the cut's included), each once, from
// the lower-numbered cell (owner) to the higher (neighbour), counter-
// clockwise round the owner; sorted by owner, then neighbour (OpenFOAM's
// upper-triangular order). Throws Failure::Argument naming the edge if the
// boundary edges found are not exactly those of the patches.
struct InternalEdge {
    int a, b, owner, neighbour;
};
std::vector<InternalEdge> internal_edges(const UnstructuredMesh &m);

}  // namespace eg2d
