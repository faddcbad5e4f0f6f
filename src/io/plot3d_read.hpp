// Plot3D whole-grid reader: detects the variant a file holds (see eg2d.h,
// eg2d_read_plot3d) and gives one block's x and y.
#pragma once
#include <string>
#include <vector>

namespace eg2d {

struct Plot3dBlock {
    int ni = 0, nj = 0, nk = 1;
    std::vector<double> x, y;  // filled by read_plot3d for the requested block only
};

struct Plot3dFile {
    int format = 0;  // EG2D_FORMAT_PLOT3D or _ASCII | EG2D_PLOT3D_* flags
    std::vector<Plot3dBlock> blocks;
};

// Reads the layout and, when block >= 0, that block's coordinates.
// Throws Io (with the path and what was found) or Argument (bad block).
Plot3dFile read_plot3d(const std::string &path, int block);

}  // namespace eg2d
