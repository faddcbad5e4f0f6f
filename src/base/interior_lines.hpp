// Interior grid lines held on the user's curves (eg2d_set_interior_line): a
// column i = index (a xi = const line, nj points) or a row j = index (an eta
// = const line, ni points) whose nodes TFI passes through and the solvers
// keep fixed, as an interior boundary.
#pragma once
#include <vector>

namespace eg2d {

struct InteriorLine {
    bool xi = false;  // a xi = const line: column `index`; else row `index`
    int index = 0;
    std::vector<double> x, y;  // the line's nodes in increasing index, ends included
};

}  // namespace eg2d
