// The faces of a 2D grid as a finite-volume solver sees them, extruded one
// cell thick: OpenFOAM's checkMesh measures (primitiveMeshCheck), so that
// `eg2d airfoil` can say which cells a solver's check would refuse.
//   non-orthogonality: the angle between an internal face's normal and the
//   line joining its two cell centres (Jasak 1996);
//   skewness: the distance from the face centre to where that line (for a
//   boundary face, the face's normal through the cell centre) crosses the
//   face, over the larger of 0.2 of the centres' distance (0.4 of the
//   normal distance on a boundary) and the face's own extent that way.
// Cell centres are the quads' area centroids, as OpenFOAM's for a prism.
#pragma once
#include <vector>

namespace eg2dtool {

struct FaceCheck {
    double nonorth_max = 0, skew_max = 0;
    int past = 0;                    // faces past either limit
    int worst_i = -1, worst_j = -1;  // the owner cell (i, j) of the face furthest past its limit
    double worst_nonorth = 0, worst_skew = 0;  // that face's figures
};

// x, y: ni*nj nodes, i fastest. An O-grid's i = 0 and ni-1 are one line; a
// C-grid's first `wake` cells of row 0 face the last `wake` across the cut.
FaceCheck check_faces(int ni, int nj, const std::vector<double> &x, const std::vector<double> &y, bool ogrid, int wake,
                      double nonorth_limit, double skew_limit);

}  // namespace eg2dtool
