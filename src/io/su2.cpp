// SU2 native mesh (.su2), 2-D: quadrilaterals (VTK type 9) counter-
// clockwise, the points with the cut's duplicates merged (so the wake or
// the O-grid's cut is interior to the mesh, as SU2 needs), and one marker
// per patch name with its boundary edges as lines (VTK type 3). Every
// boundary edge is in exactly one marker (io/unstructured.hpp checks).
#include "eg2d.h"
#include "io/formats.hpp"
#include "io/unstructured.hpp"

namespace eg2d {

void write_su2(const WriteRequest &r, OutputFile &out) {
    const Grid &g = r.grid;
    const UnstructuredMesh m = unstructured_mesh(g);
    internal_edges(m);  // checks the markers cover the boundary exactly
    out.print("%% SU2 mesh written by eg2d: %d x %d nodes, %s\n", g.ni(), g.nj(), topology_name(g.topology()));
    out.print("NDIME= 2\nNELEM= %zu\n", m.cells());
    std::size_t id = 0;
    for (int j = 0; j + 1 < g.nj(); ++j)
        for (int i = 0; i + 1 < g.ni(); ++i) {
            const auto c = m.cell(i, j);
            out.print("9 %d %d %d %d %zu\n", c[0], c[1], c[2], c[3], id++);
        }
    out.print("NPOIN= %zu\n", m.points());
    for (std::size_t p = 0; p < m.points(); ++p) {
        out.real(g.x[m.node_of[p]], ' ');
        out.real(g.y[m.node_of[p]], ' ');
        out.print("%zu\n", p);
    }
    out.print("NMARK= %zu\n", m.patches.size());
    for (const MeshPatch &p : m.patches) {
        out.print("MARKER_TAG= %s\nMARKER_ELEMS= %zu\n", p.name.c_str(), p.edges.size());
        for (const MeshEdge &e : p.edges) out.print("3 %d %d\n", e.a, e.b);
    }
}

}  // namespace eg2d
