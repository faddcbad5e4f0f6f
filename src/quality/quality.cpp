#include "quality/quality.hpp"

#include <algorithm>

#include "eg2d.h"
#include "base/cell.hpp"

namespace eg2d {

void cell_scaled_jacobian(const Grid &grid, double *out);  // scaled_jacobian.cpp

namespace {
double folded_cells(const Grid &g) { return static_cast<double>(fold_summary(g).folded); }
double min_area(const Grid &g) { return fold_summary(g).min_area; }

template <void (*Cells)(const Grid &, double *)>
double largest(const Grid &g) {
    std::vector<double> v(cell_count(g));
    Cells(g, v.data());
    return *std::max_element(v.begin(), v.end());
}

template <void (*Cells)(const Grid &, double *)>
double smallest(const Grid &g) {
    std::vector<double> v(cell_count(g));
    Cells(g, v.data());
    return *std::min_element(v.begin(), v.end());
}

template <Side S>
double ortho_max(const Grid &g) { return boundary_orthogonality(g, S).max; }
template <Side S>
double ortho_mean(const Grid &g) { return boundary_orthogonality(g, S).mean; }

// Ids are fixed with gaps between families (see eg2d.h). A per-cell field
// shared by two summaries (the area) is written to files once, by the first.
const QualityMetric kMetrics[] = {
    {EG2D_QUALITY_FOLDED_CELLS, "folded_cells", "folded", folded_cells, cell_folded},
    {EG2D_QUALITY_MIN_AREA, "min_area", "area", min_area, cell_area},
    {EG2D_QUALITY_MAX_AREA, "max_area", "area", largest<cell_area>, cell_area},
    {EG2D_QUALITY_SKEWNESS, "skewness", "skewness", largest_skewness, cell_skewness},
    {EG2D_QUALITY_ASPECT_RATIO, "aspect_ratio", "aspect_ratio", largest<cell_aspect_ratio>, cell_aspect_ratio},
    {EG2D_QUALITY_SMOOTHNESS_I, "smoothness_i", "smoothness_i", largest<cell_smoothness_i>, cell_smoothness_i},
    {EG2D_QUALITY_SMOOTHNESS_J, "smoothness_j", "smoothness_j", largest<cell_smoothness_j>, cell_smoothness_j},
    {EG2D_QUALITY_ORTHO_MAX_JMIN, "ortho_max_jmin", nullptr, ortho_max<Side::JMin>, nullptr},
    {EG2D_QUALITY_ORTHO_MAX_IMAX, "ortho_max_imax", nullptr, ortho_max<Side::IMax>, nullptr},
    {EG2D_QUALITY_ORTHO_MAX_JMAX, "ortho_max_jmax", nullptr, ortho_max<Side::JMax>, nullptr},
    {EG2D_QUALITY_ORTHO_MAX_IMIN, "ortho_max_imin", nullptr, ortho_max<Side::IMin>, nullptr},
    {EG2D_QUALITY_ORTHO_MEAN_JMIN, "ortho_mean_jmin", nullptr, ortho_mean<Side::JMin>, nullptr},
    {EG2D_QUALITY_ORTHO_MEAN_IMAX, "ortho_mean_imax", nullptr, ortho_mean<Side::IMax>, nullptr},
    {EG2D_QUALITY_ORTHO_MEAN_JMAX, "ortho_mean_jmax", nullptr, ortho_mean<Side::JMax>, nullptr},
    {EG2D_QUALITY_ORTHO_MEAN_IMIN, "ortho_mean_imin", nullptr, ortho_mean<Side::IMin>, nullptr},
    {EG2D_QUALITY_SCALED_JACOBIAN, "scaled_jacobian", "scaled_jacobian", smallest<cell_scaled_jacobian>,
     cell_scaled_jacobian},
};
}  // namespace

Table<QualityMetric> quality_table() { return table_of(kMetrics); }

const QualityMetric *find_quality_metric(int id) { return quality_table().find(id); }

std::vector<CellField> cell_fields(const Grid &grid) {
    std::vector<CellField> out;
    for (const QualityMetric &m : kMetrics) {
        if (!m.cells) continue;
        if (std::any_of(out.begin(), out.end(), [&](const CellField &f) { return f.name == m.cell_field; })) continue;
        CellField f{m.cell_field, std::vector<double>(cell_count(grid))};
        m.cells(grid, f.values.data());
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace eg2d
