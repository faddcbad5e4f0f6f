// SU2 native mesh (.su2), 2-D: quadrilaterals (VTK type 9) counter-
// clockwise, the points with the cut's duplicates merged (so the wake or
// the O-grid's cut is interior to the mesh, as SU2 needs; a set's joins
// likewise), and one marker per patch name with its boundary edges as
// lines (VTK type 3). Every boundary edge is in exactly one marker
// (io/unstructured.hpp checks).
#include "base/error.hpp"
#include "eg2d.h"
#include "io/formats.hpp"
#include "io/unstructured.hpp"

namespace eg2d {

void write_su2_mesh(const MeshRequest &r, OutputFile &out) {
    const UnstructuredMesh &m = r.mesh;
    internal_edges(m);  // checks the markers cover the boundary exactly
    out.print("%% SU2 mesh written by eg2d: %s\n", r.title.c_str());
    out.print("NDIME= 2\nNELEM= %zu\n", m.cells());
    for (std::size_t id = 0; id < m.cells(); ++id) {
        const auto &c = m.quads[id];
        out.print("9 %d %d %d %d %zu\n", c[0], c[1], c[2], c[3], id);
    }
    out.print("NPOIN= %zu\n", m.points());
    for (std::size_t p = 0; p < m.points(); ++p) {
        out.real(m.x[p], ' ');
        out.real(m.y[p], ' ');
        out.print("%zu\n", p);
    }
    out.print("NMARK= %zu\n", m.patches.size());
    for (const MeshPatch &p : m.patches) {
        out.print("MARKER_TAG= %s\nMARKER_ELEMS= %zu\n", p.name.c_str(), p.edges.size());
        for (const MeshEdge &e : p.edges) out.print("3 %d %d\n", e.a, e.b);
    }
}

void write_su2(const WriteRequest &r, OutputFile &out) {
    const Grid &g = r.grid;
    const std::string title = format("%d x %d nodes, %s", g.ni(), g.nj(), topology_name(g.topology()));
    write_su2_mesh(MeshRequest{unstructured_mesh(g), r.settings, title}, out);
}

}  // namespace eg2d
