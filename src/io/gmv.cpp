// GMV ASCII, Khattri's (2006) viewer format. Khattri's writer leaves out the z
// coordinates GMV requires and numbers the quad corners wrongly; here the
// nodes carry x, y and z = 0, each quad its four 1-based corners counter-
// clockwise in (i, j), and the per-cell quality metrics are cell variables.
#include "io/formats.hpp"
#include "quality/quality.hpp"

namespace eg2d {

void write_gmv(const WriteRequest &r, OutputFile &out) {
    const Grid &g = r.grid;
    const int ni = g.ni(), nj = g.nj();
    out.print("gmvinput ascii\nnodes %zu\n", g.size());
    auto column = [&](const std::vector<double> *v) {
        for (std::size_t k = 0; k < g.size(); ++k)
            out.real(v ? (*v)[k] : 0.0, (k % 6 == 5 || k + 1 == g.size()) ? '\n' : ' ');
    };
    column(&g.x);
    column(&g.y);
    column(nullptr);
    out.print("cells %ld\n", static_cast<long>(ni - 1) * (nj - 1));
    for (int j = 0; j < nj - 1; ++j)
        for (int i = 0; i < ni - 1; ++i) {
            const long a = static_cast<long>(i) + static_cast<long>(ni) * j + 1;
            out.print("quad 4\n%ld %ld %ld %ld\n", a, a + 1, a + 1 + ni, a + ni);
        }
    out.print("variable\n");
    for (const CellField &f : cell_fields(g)) {
        out.print("%s 0\n", f.name.c_str());
        for (std::size_t k = 0; k < f.values.size(); ++k)
            out.real(f.values[k], (k % 6 == 5 || k + 1 == f.values.size()) ? '\n' : ' ');
    }
    out.print("endvars\nendgmv\n");
}

}  // namespace eg2d
