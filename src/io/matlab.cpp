// Matlab/Octave script, Khattri's (2006) second format: assigns xl(i,j), yl(i,j)
// (1-based) and plots the boundary in red and the interior lines in blue.
// The coordinates are whole matrices in one statement each (faster to
// parse than Khattri's one assignment per node), 17 significant digits.
#include "io/formats.hpp"

namespace eg2d {

namespace {
void matrix(OutputFile &out, const char *name, const Grid &g, const std::vector<double> &v) {
    // Rows are i, columns j, as Khattri's xl(i+1, j+1).
    out.print("%s = [\n", name);
    for (int i = 0; i < g.ni(); ++i) {
        for (int j = 0; j < g.nj(); ++j)
            out.real(v[static_cast<std::size_t>(i) + static_cast<std::size_t>(g.ni()) * j], j + 1 == g.nj() ? ';' : ' ');
        out.print("\n");
    }
    out.print("];\n");
}
}  // namespace

void write_matlab(const WriteRequest &r, OutputFile &out) {
    const Grid &g = r.grid;
    out.print("%% eg2d grid, %d x %d nodes: xl(i,j), yl(i,j) of node (i-1, j-1)\n", g.ni(), g.nj());
    out.print("holdon = ishold;\n");
    matrix(out, "xl", g, g.x);
    matrix(out, "yl", g, g.y);
    out.print("m = %d;\nn = %d;\n", g.ni(), g.nj());
    out.print("plot(xl(1,:), yl(1,:), 'r'); hold on\n"
              "plot(xl(m,:), yl(m,:), 'r');\n"
              "plot(xl(:,1), yl(:,1), 'r');\n"
              "plot(xl(:,n), yl(:,n), 'r');\n"
              "%% interior grid lines\n"
              "for i = 2:m-1, plot(xl(i,:), yl(i,:), 'b'); end\n"
              "for j = 2:n-1, plot(xl(:,j), yl(:,j), 'b'); end\n"
              "if (~holdon), hold off, end\n"
              "axis equal; axis off;\n");
}

}  // namespace eg2d
