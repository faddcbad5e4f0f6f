// Boundary patches: each side of a grid, or a stretch of one, carries a type
// (wall, far field, ...) and a name, which the solver-ready writers (SU2,
// OpenFOAM, CGNS) turn into markers, patches and boundary conditions. The
// user's patches are kept on the Grid; resolve_patches() completes them with
// the topology's defaults and the cut into a cover of the whole boundary in
// which every boundary edge belongs to exactly one stretch.
#pragma once
#include <string>
#include <vector>

namespace eg2d {

enum class Side;  // base/grid.hpp
class Grid;

// Values are the public EG2D_PATCH_* constants.
enum class PatchType { Wall = 0, FarField = 1, Outflow = 2, Inflow = 3, Symmetry = 4, Cut = 5 };
const char *patch_type_name(PatchType t);

// Nodes first..last (0-based, increasing index along the side) of a side:
// the edges between them, last - first of them.
struct Patch {
    Side side;
    int first, last;
    PatchType type;
    std::string name;
};

// Names are what every target format accepts as an identifier: 1 to 32
// characters (CGNS's name length), a letter first, then letters, digits,
// '_' or '-'; "frontAndBack" is taken by the OpenFOAM writer's empty patch.
constexpr int kMaxPatchName = 32;
void check_patch_name(const char *name);

// The list with p added, or replacing the patch of exactly the same side and
// range. Throws Argument for a side the topology lacks, a range outside the
// side or overlapping another patch, the type Cut, a stretch of a C-grid's
// wake cut (once JMIN is set), a bad name, or a name already used with
// another type.
std::vector<Patch> with_patch(const Grid &g, const std::vector<Patch> &patches, const Patch &p);

// The whole boundary as stretches, side by side (JMIN, IMAX, JMAX, IMIN) in
// increasing index: the user's patches, the topology's defaults on the edges
// they leave (single block: "jmin", "imax", "jmax", "imin", walls; O-grid:
// JMIN "wall" wall, JMAX "farfield" far field, the cut IMIN "cut"; C-grid:
// JMIN's airfoil stretch "wall" wall and its two wake stretches "wake" (Cut),
// JMAX "farfield" far field, IMIN and IMAX "outflow" outflow). An O-grid's
// cut is given as IMIN [0, nj-1] of type Cut. Throws State for a C-grid
// whose JMIN, and so its wake, is not set yet, and Argument for a stored
// patch that lies on the cut of the JMIN set since.
std::vector<Patch> resolve_patches(const Grid &g);

// The resolved stretches grouped by name (Cut stretches left out), in order
// of first appearance: one marker/patch/family per name.
struct PatchGroup {
    std::string name;
    PatchType type;
    std::vector<Patch> stretches;
};
std::vector<PatchGroup> group_patches(const std::vector<Patch> &resolved);

}  // namespace eg2d
