// The C-grid wake cut in Connectivity: the stencil across the cut, the cut
// unknowns and the sync of the upper half, and their coarsening.
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "base/connectivity.hpp"

using namespace eg2d;

static int failures = 0, passes = 0;
#define CHECK(c)                                                           \
    do {                                                                   \
        if (!(c)) {                                                        \
            std::printf("FAILED %s:%d: %s\n", __FILE__, __LINE__, #c);     \
            ++failures;                                                    \
        } else {                                                           \
            ++passes;                                                      \
        }                                                                  \
    } while (0)

int main() {
    const int ni = 13, nj = 5, wake = 4;
    Connectivity c(ni, nj, Topology::C, wake);
    auto k = [&](int i, int j) { return static_cast<std::ptrdiff_t>(i + ni * j); };
    // Unknowns on the cut: (1..wake-1, 0).
    CHECK(c.extra_unknowns().size() == 3);
    CHECK(c.extra_unknowns()[0].i == 1 && c.extra_unknowns()[2].i == 3 && c.extra_unknowns()[0].j == 0);
    CHECK(c.on_cut(2, 0) && !c.on_cut(0, 0) && !c.on_cut(wake, 0) && !c.on_cut(2, 1));
    // Across the cut: south of (2, 0) is (ni-1-2, 1), and the diagonals follow the reversed upper half.
    const Stencil s = c.stencil(2, 0);
    CHECK(s.c == k(2, 0) && s.e == k(3, 0) && s.w == k(1, 0) && s.n == k(2, 1));
    CHECK(s.s == k(10, 1) && s.se == k(9, 1) && s.sw == k(11, 1) && s.ne == k(3, 1) && s.nw == k(1, 1));
    // Off the cut the stencil is the plain one.
    const Stencil t = c.stencil(6, 1);
    CHECK(t.s == k(6, 0) && t.e == k(7, 1) && t.sw == k(5, 0));
    // sync_node copies a cut node to its upper twin; sync() does all of them.
    std::vector<double> f(ni * nj, 0.0);
    f[2] = 7.0;
    c.sync_node(f.data(), 2, 0);
    CHECK(f[10] == 7.0);
    f[1] = 3.0;
    f[3] = 5.0;
    c.sync(f.data());
    CHECK(f[11] == 3.0 && f[9] == 5.0 && f[12] == 0.0);
    // Coarsening by 2 keeps the cut (wake 4 -> 2); by 3 it ends at the last
    // coarse column before the trailing edge (wake 4 -> 1: no cut unknowns).
    const Connectivity c2 = c.coarsened(2, 2);
    CHECK(c2.ni() == 7 && c2.nj() == 3 && c2.wake() == 2 && c2.extra_unknowns().size() == 1);
    CHECK(c.coarsened(3, 2).wake() == 1 && c.coarsened(3, 2).extra_unknowns().empty());
    // An odd wake: the coarse cut stops one fine node short (wake 5 -> 2).
    const Connectivity odd = Connectivity(ni, nj, Topology::C, 5).coarsened(2, 1);
    CHECK(odd.ni() == 7 && odd.nj() == nj && odd.wake() == 2 && odd.extra_unknowns().size() == 1);
    // Other topologies have no cut.
    CHECK(Connectivity(ni, nj, Topology::Single, 4).wake() == 0);
    std::printf("%d passed, %d failed\n", passes, failures);
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
