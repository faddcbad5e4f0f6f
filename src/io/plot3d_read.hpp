// Plot3D whole-grid reader: detects the variant a file holds (see eg2d.h,
// eg2d_read_plot3d) and gives one block's x and y.
#pragma once
#include <string>
#include <vector>

namespace eg2d {

struct Plot3dBlock {
    int ni = 0, nj = 0, nk = 1;
    std::vector<double> x, y;
};

// The layout of a file and one of its blocks. Nothing else of the file is
// kept: what the reader allocates beyond the file's bytes is the block's
// coordinates (and, for ASCII, the header's integers).
struct Plot3dFile {
    int format = 0;  // EG2D_FORMAT_PLOT3D or _ASCII | EG2D_PLOT3D_* flags
    int nblocks = 0;
    Plot3dBlock block;  // the block asked for
};

// Reads the layout and block `block` (>= 0) with its coordinates.
// Throws Io (with the path and what was found) or Argument (bad block).
Plot3dFile read_plot3d(const std::string &path, int block);

}  // namespace eg2d
