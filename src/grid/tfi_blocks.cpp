// TFI through interior lines (eg2d_set_interior_line): the fixed columns
// and rows cut the grid into sub-blocks, and each is filled by the method
// as a grid of its own whose sides are pieces of the boundary and of the
// lines (piecewise transfinite interpolation, Thompson, Warsi & Mastin
// 1985; the grid-generation lecture notes' remark after eq 2.2, "x and y given on several
// coordinate lines in the interior"). The grid lines
// then pass through the lines' points exactly; the spacing is continuous
// across a line, its slope is not.
#include <vector>

#include "grid/initializers.hpp"

namespace eg2d {

namespace {

// 0, the fixed indices, n-1.
std::vector<int> cuts(std::vector<int> fixed, int n) {
    fixed.insert(fixed.begin(), 0);
    fixed.push_back(n - 1);
    return fixed;
}

// The mask of hermite_sides for a sub-block: a side stays chosen only where
// it lies on the grid's own side (a line is no side to be orthogonal to).
double sub_sides(double mask, bool jmin, bool imax, bool jmax, bool imin) {
    const unsigned m = static_cast<unsigned>(mask);
    const bool on[4] = {jmin, imax, jmax, imin};
    unsigned out = 0;
    for (int s = 0; s < 4; ++s)
        if (on[s]) out |= m & (1u << s);
    return out;
}

}  // namespace

void fill_blocks(Grid &g, const Settings &settings, void (*fill)(Grid &, const Settings &)) {
    const Connectivity &conn = g.connectivity();
    if (!conn.has_fixed()) return fill(g, settings);
    const int ni = g.ni(), nj = g.nj();
    const bool periodic = conn.periodic_i();
    const std::vector<int> ci = cuts(conn.fixed_columns(), ni), cj = cuts(conn.fixed_rows(), nj);
    auto at = [ni](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j; };
    for (std::size_t b = 0; b + 1 < cj.size(); ++b)
        for (std::size_t a = 0; a + 1 < ci.size(); ++a) {
            const int i0 = ci[a], i1 = ci[a + 1], j0 = cj[b], j1 = cj[b + 1];
            if (j1 - j0 < 2 || i1 - i0 < 2) continue;  // no interior node between the lines
            const int mi = i1 - i0 + 1, mj = j1 - j0 + 1;
            std::vector<double> sx(static_cast<std::size_t>(mi) * mj), sy(sx.size());
            for (int j = 0; j < mj; ++j)
                for (int i = 0; i < mi; ++i) {
                    sx[static_cast<std::size_t>(i + mi * j)] = g.x[at(i0 + i, j0 + j)];
                    sy[static_cast<std::size_t>(i + mi * j)] = g.y[at(i0 + i, j0 + j)];
                }
            Grid sub(mi, mj);
            if (periodic) sub.set_topology(Topology::O);
            sub.set_coordinates(sx.data(), sy.data());
            Settings s = settings;
            s.hermite_sides = sub_sides(settings.hermite_sides, j0 == 0, i1 == ni - 1, j1 == nj - 1, i0 == 0);
            // Hermite at chosen sides: a sub-block without one is blended
            // linearly by the same construction, not by the eta-only form.
            if (fill == tfi_hermite && settings.hermite_sides != 0.0) tfi_hermite_sides(sub, s);
            else fill(sub, s);
            for (int j = 1; j < mj - 1; ++j)
                for (int i = periodic ? 0 : 1; i < (periodic ? mi : mi - 1); ++i) {
                    g.x[at(i0 + i, j0 + j)] = sub.x[static_cast<std::size_t>(i + mi * j)];
                    g.y[at(i0 + i, j0 + j)] = sub.y[static_cast<std::size_t>(i + mi * j)];
                }
        }
}

}  // namespace eg2d
