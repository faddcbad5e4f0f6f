// Cell quality of a grid. Metrics are found by their EG2D_QUALITY_* id in
// quality.cpp's table; adding a metric is adding a function (in the file of
// its family) and a line there.
#pragma once
#include <string>
#include <vector>

#include "base/folds.hpp"
#include "base/grid.hpp"
#include "base/table.hpp"

namespace eg2d {


// Per-cell families: each writes (ni-1)*(nj-1) values, cell (i, j) at i + (ni-1)*j.
void cell_folded(const Grid &grid, double *out);        // folding.cpp: 1 folded, 0 not
void cell_area(const Grid &grid, double *out);          // area.cpp: signed by the orientation
void cell_skewness(const Grid &grid, double *out);      // skewness.cpp: degrees
double largest_skewness(const Grid &grid);              // skewness.cpp: the largest of cell_skewness
void cell_aspect_ratio(const Grid &grid, double *out);  // aspect_ratio.cpp
void cell_smoothness_i(const Grid &grid, double *out);  // smoothness.cpp
void cell_smoothness_j(const Grid &grid, double *out);

// orthogonality.cpp: deviation from 90 degrees of the grid lines meeting a side.
struct OrthogonalitySummary {
    double max = 0.0, mean = 0.0;
};
// Throws Argument for a side the topology does not have.
OrthogonalitySummary boundary_orthogonality(const Grid &grid, Side side);

struct QualityMetric {
    int id;             // EG2D_QUALITY_*
    const char *name;   // list name: "min_area"
    const char *cell_field;  // the per-cell field's name in files ("area"); nullptr: none
    double (*summary)(const Grid &grid);
    void (*cells)(const Grid &grid, double *out);  // nullptr: a boundary metric with no per-cell values
};

Table<QualityMetric> quality_table();  // in increasing id order
// nullptr if there is no metric with that id.
const QualityMetric *find_quality_metric(int id);

// The metrics that have per-cell values, each once (the fields a file carries).
struct CellField {
    std::string name;
    std::vector<double> values;
};
std::vector<CellField> cell_fields(const Grid &grid);

}  // namespace eg2d
