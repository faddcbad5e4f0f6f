// Cell quality of a grid. Scalar metrics are found by their EG2D_QUALITY_* id
// in quality.cpp's table; adding a metric is adding a function and a line.
#pragma once
#include "grid/grid.hpp"

namespace eg2d {

// Orientation and folding of the cells (i, j), i < ni-1, j < nj-1.
struct FoldSummary {
    int orientation = 1;      // +1 right-handed (counter-clockwise cells), -1 left-handed
    long folded = 0;          // cells with a corner turning against the orientation
    int first_i = -1, first_j = -1;  // the first folded cell in storage order
    double min_area = 0.0;    // smallest cell area times the orientation
};

FoldSummary fold_summary(const Grid &grid);

struct QualityMetric {
    int id;             // EG2D_QUALITY_*
    const char *name;
    double (*summary)(const Grid &grid);
};

// nullptr if there is no metric with that id.
const QualityMetric *find_quality_metric(int id);

}  // namespace eg2d
