// VTK XML StructuredGrid (.vts), ASCII with 17 significant digits so that a
// reader gets the coordinates back exactly; every per-cell quality metric is
// a CellData array. VTK's cell order (i fastest) is eg2d's.
#include "eg2d.h"
#include "io/formats.hpp"
#include "quality/quality.hpp"

namespace eg2d {

void write_vts(const WriteRequest &r, OutputFile &out) {
    const Grid &g = r.grid;
    const std::vector<CellField> fields = cell_fields(g);
    out.print("<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"StructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
              "  <StructuredGrid WholeExtent=\"0 %d 0 %d 0 0\">\n"
              "    <Piece Extent=\"0 %d 0 %d 0 0\">\n",
              g.ni() - 1, g.nj() - 1, g.ni() - 1, g.nj() - 1);
    out.print("      <CellData Scalars=\"%s\">\n", fields.empty() ? "" : fields.front().name.c_str());
    for (const CellField &f : fields) {
        out.print("        <DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", f.name.c_str());
        for (std::size_t k = 0; k < f.values.size(); ++k)
            out.real(f.values[k], (k % 6 == 5 || k + 1 == f.values.size()) ? '\n' : ' ');
        out.print("        </DataArray>\n");
    }
    out.print("      </CellData>\n"
              "      <Points>\n"
              "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for (std::size_t k = 0; k < g.size(); ++k) {
        out.real(g.x[k], ' ');
        out.real(g.y[k], ' ');
        out.print("0\n");
    }
    out.print("        </DataArray>\n"
              "      </Points>\n"
              "    </Piece>\n"
              "  </StructuredGrid>\n"
              "</VTKFile>\n");
}

}  // namespace eg2d
