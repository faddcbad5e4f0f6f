// Plane geometry every layer needs, written once: the bounding box of points
// (its diagonal is the domain size L of NUMERICS.md and the scale of every
// relative tolerance) and the shoelace sum of a closed polygon (the sign of
// its area: which way it turns).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace eg2d {

// Bounding box of the points added to it; empty until the first.
struct Bounds {
    double xmin = std::numeric_limits<double>::infinity();
    double xmax = -std::numeric_limits<double>::infinity();
    double ymin = std::numeric_limits<double>::infinity();
    double ymax = -std::numeric_limits<double>::infinity();

    void add(double x, double y) {
        xmin = std::min(xmin, x); xmax = std::max(xmax, x);
        ymin = std::min(ymin, y); ymax = std::max(ymax, y);
    }
    void add(const double *x, const double *y, std::size_t n) {
        for (std::size_t k = 0; k < n; ++k) add(x[k], y[k]);
    }
    bool empty() const { return !(xmax >= xmin); }
    // The box's diagonal; 0 when empty.
    double diagonal() const { return empty() ? 0.0 : std::hypot(xmax - xmin, ymax - ymin); }
};

// Diagonal of the bounding box of n points (0 for none).
inline double bounding_diagonal(const double *x, const double *y, std::size_t n) {
    Bounds b;
    b.add(x, y, n);
    return b.diagonal();
}

// Twice the signed area of the closed polygon through the n points (the
// edge from the last point back to the first included): positive when the
// polygon runs counter-clockwise.
inline double shoelace(const double *x, const double *y, std::size_t n) {
    double a = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t m = (k + 1) % n;
        a += x[k] * y[m] - x[m] * y[k];
    }
    return a;
}

}  // namespace eg2d
