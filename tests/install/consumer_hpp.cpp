// A C++ consumer of the installed eg2d.hpp: the swan, 33 x 33.
#include <eg2d.hpp>

#include <cstdio>
#include <vector>

int main() {
    const int n = 33;
    std::vector<double> s(n), zero(n, 0.0), a(n), b(n);
    for (int i = 0; i < n; ++i) {
        s[i] = (double)i / (n - 1);
        a[i] = 1 + 2 * s[i] - 2 * s[i] * s[i];
        b[i] = 1 - 2 * s[i] + 2 * s[i] * s[i];
    }
    eg2d::grid g(n, n);
    g.set_side(EG2D_SIDE_JMIN, s, zero);
    g.set_side(EG2D_SIDE_IMAX, a, s);
    g.set_side(EG2D_SIDE_JMAX, s, b);
    g.set_side(EG2D_SIDE_IMIN, zero, s);
    g.solve();
    std::printf("hpp swan %dx%d: residual %.2g, %g folded cells\n", n, n, g.get_residual(),
                g.get_quality(EG2D_QUALITY_FOLDED_CELLS));
    return g.get_quality(EG2D_QUALITY_FOLDED_CELLS) == 0 ? 0 : 1;
}
