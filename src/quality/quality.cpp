#include "quality/quality.hpp"

#include "eg2d.h"

namespace eg2d {

namespace {
double folded_cells(const Grid &g) { return static_cast<double>(fold_summary(g).folded); }
double min_area(const Grid &g) { return fold_summary(g).min_area; }

const QualityMetric kMetrics[] = {
    {EG2D_QUALITY_FOLDED_CELLS, "folded_cells", folded_cells},
    {EG2D_QUALITY_MIN_AREA, "min_area", min_area},
};
}  // namespace

const QualityMetric *find_quality_metric(int id) {
    for (const QualityMetric &m : kMetrics)
        if (m.id == id) return &m;
    return nullptr;
}

}  // namespace eg2d
