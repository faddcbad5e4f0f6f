#include "face_check.hpp"

#include <algorithm>
#include <cmath>

namespace eg2dtool {

namespace {

struct V {
    double x, y;
};

V operator-(V a, V b) { return {a.x - b.x, a.y - b.y}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y; }
double norm(V a) { return std::hypot(a.x, a.y); }

struct Grid2 {
    int ni, nj;
    const std::vector<double> &x, &y;
    V node(int i, int j) const {
        const std::size_t k = static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j;
        return {x[k], y[k]};
    }
    // The area centroid of cell (i, j).
    V centre(int i, int j) const {
        const V q[4] = {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
        double a = 0, cx = 0, cy = 0;
        for (int k = 0; k < 4; ++k) {
            const V p = q[k], r = q[(k + 1) % 4];
            const double c = p.x * r.y - r.x * p.y;
            a += c, cx += (p.x + r.x) * c, cy += (p.y + r.y) * c;
        }
        if (!(a != 0.0)) return {0.25 * (q[0].x + q[1].x + q[2].x + q[3].x), 0.25 * (q[0].y + q[1].y + q[2].y + q[3].y)};
        return {cx / (3 * a), cy / (3 * a)};
    }
};

// The face a -> b of cell `own`, internal (the neighbour's centre nei) or
// on the boundary (nei null): its non-orthogonality (degrees) and skewness.
void measure(V a, V b, V own, const V *nei, double &nonorth, double &skew) {
    const V fc{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}, edge = b - a, n{edge.y, -edge.x};
    const V cpf = fc - own;
    V d;
    nonorth = 0;
    if (nei) {
        d = *nei - own;
        const double nd = norm(n) * norm(d);
        nonorth = nd > 0 ? std::acos(std::min(1.0, std::fabs(dot(n, d)) / nd)) * (180.0 / 3.14159265358979323846) : 90.0;
    } else {
        const double along = dot(n, n) > 0 ? dot(n, cpf) / dot(n, n) : 0.0;
        d = {n.x * along, n.y * along};
    }
    const double t = dot(n, cpf) / (dot(n, d) + 1e-300);
    const V sv{cpf.x - t * d.x, cpf.y - t * d.y};
    const double s = norm(sv);
    double fd = (nei ? 0.2 : 0.4) * norm(d);
    if (s > 0) fd = std::max(fd, std::fabs(dot(sv, edge)) * 0.5 / s);
    skew = fd > 0 ? s / fd : 0;
}

}  // namespace

FaceCheck check_faces(int ni, int nj, const std::vector<double> &x, const std::vector<double> &y, bool ogrid, int wake,
                      double nonorth_limit, double skew_limit) {
    const Grid2 g{ni, nj, x, y};
    const int ci = ni - 1, cj = nj - 1;
    std::vector<V> c(static_cast<std::size_t>(ci) * cj);
    for (int j = 0; j < cj; ++j)
        for (int i = 0; i < ci; ++i) c[static_cast<std::size_t>(i) + static_cast<std::size_t>(ci) * j] = g.centre(i, j);
    auto C = [&](int i, int j) { return &c[static_cast<std::size_t>(i) + static_cast<std::size_t>(ci) * j]; };
    FaceCheck out;
    double worst = 1.0;  // the largest share of a limit
    auto face = [&](V a, V b, int i, int j, const V *nei) {
        double no, sk;
        measure(a, b, *C(i, j), nei, no, sk);
        out.nonorth_max = std::max(out.nonorth_max, no);
        out.skew_max = std::max(out.skew_max, sk);
        const double share = std::max(no / nonorth_limit, sk / skew_limit);
        if (share > 1.0) ++out.past;
        if (share > worst) worst = share, out.worst_i = i, out.worst_j = j, out.worst_nonorth = no, out.worst_skew = sk;
    };
    for (int j = 0; j < cj; ++j)
        for (int i = 0; i < ci; ++i) {
            // The face at i+1 (to the next cell, or round an O-grid's cut).
            if (i + 1 < ci || ogrid) face(g.node(i + 1, j), g.node(i + 1, j + 1), i, j, C((i + 1) % ci, j));
            else face(g.node(i + 1, j), g.node(i + 1, j + 1), i, j, nullptr);
            if (i == 0 && !ogrid) face(g.node(0, j + 1), g.node(0, j), i, j, nullptr);
            if (j + 1 < cj) face(g.node(i, j + 1), g.node(i + 1, j + 1), i, j, C(i, j + 1));
            else face(g.node(i, j + 1), g.node(i + 1, j + 1), i, j, nullptr);
            if (j == 0) {
                const bool cut = !ogrid && (i < wake || i >= ci - wake);
                if (!cut) face(g.node(i + 1, 0), g.node(i, 0), i, j, nullptr);
                else if (i < wake) face(g.node(i + 1, 0), g.node(i, 0), i, j, C(ci - 1 - i, 0));
            }
        }
    return out;
}

}  // namespace eg2dtool
