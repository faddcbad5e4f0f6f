// Khattri's (2006) clustering maps of [0, 1] onto itself (Cluster_X_Near,
// Cluster_Two_Lines_X with Eriksson_1, Bound_Clust_X), written as functions
// of the uniform coordinate u (the listing applies its branches in sequence
// to already-mapped values and has typos; these are its formulas, once each).
// Every map is increasing, fixes 0 and 1, and its slope at the attracting
// points is strength / (e^strength - 1).
#include <cmath>

#include "controls/controls.hpp"

namespace eg2d {

namespace {
// Eriksson_1: (e^(a u) - 1) / (e^a - 1), dense at u = 0.
double eriksson(double a, double u) { return std::expm1(a * u) / std::expm1(a); }
}  // namespace

double clustering_map(Clustering kind, double a, double b, double k, double u) {
    switch (kind) {
    case Clustering::Line:  // dense at u = a (Cluster_X_Near)
        if (u <= a) return a * (1.0 - eriksson(k, 1.0 - u / a));
        return a + (1.0 - a) * eriksson(k, (u - a) / (1.0 - a));
    case Clustering::TwoLines: {  // dense at u = a and u = b (Cluster_Two_Lines_X)
        const double m = 0.5 * (a + b);
        if (u <= a) return a * (1.0 - eriksson(k, 1.0 - u / a));
        if (u <= m) return a + (m - a) * eriksson(k, (u - a) / (m - a));
        if (u <= b) return m + (b - m) * (1.0 - eriksson(k, (b - u) / (b - m)));
        return b + (1.0 - b) * eriksson(k, (u - b) / (1.0 - b));
    }
    case Clustering::Boundaries:  // dense at 0 and 1, split at a (Bound_Clust_X)
        if (u <= a) return a * eriksson(k, u / a);
        return 1.0 - (1.0 - a) * eriksson(k, (1.0 - u) / (1.0 - a));
    }
    return u;
}

}  // namespace eg2d
