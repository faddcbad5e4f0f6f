#include "io/formats.hpp"

#include "base/error.hpp"
#include "eg2d.h"

namespace eg2d {

// The writers, each in its own file.
void write_plot3d(const WriteRequest &r, OutputFile &out);        // plot3d_write.cpp
void write_plot3d_ascii(const WriteRequest &r, OutputFile &out);
void write_plot3d_blocks(const BlocksRequest &r, OutputFile &out);
void write_plot3d_ascii_blocks(const BlocksRequest &r, OutputFile &out);
void write_vts(const WriteRequest &r, OutputFile &out);           // vts.cpp
void write_vtm(const BlocksRequest &r, const std::string &path);  // vtm.cpp
void write_cgns(const WriteRequest &r, OutputFile &out);          // cgns_loader.cpp
void write_cgns_blocks(const BlocksRequest &r, OutputFile &out);
void write_gmv(const WriteRequest &r, OutputFile &out);           // gmv.cpp
void write_matlab(const WriteRequest &r, OutputFile &out);        // matlab.cpp
void write_svg(const WriteRequest &r, OutputFile &out);           // svg.cpp
void write_su2(const WriteRequest &r, OutputFile &out);           // su2.cpp
void write_report(const WriteRequest &r, OutputFile &out);        // report.cpp
void write_report_json(const WriteRequest &r, OutputFile &out);
void write_su2_mesh(const MeshRequest &r, OutputFile &out);
void write_openfoam(const WriteRequest &r, const std::string &dir);  // openfoam.cpp
void write_openfoam_mesh(const MeshRequest &r, const std::string &dir);

namespace {
constexpr int kFormatMask = 0xff;
constexpr int kPlot3dFlags = EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI | EG2D_PLOT3D_SINGLE | EG2D_PLOT3D_BIG_ENDIAN |
                             EG2D_PLOT3D_NO_MARKERS | EG2D_PLOT3D_EXTRUDED;

// In id order; a format that is a directory of files (an OpenFOAM case) has
// write_directory instead of write; one written from the unstructured mesh
// has its mesh writer too (sets of blocks).
//
// VTK's multiblock form is a row of its own (vtm), not a set writer on the
// vts row as Plot3D's and CGNS's zones are on theirs: a set writer writes
// the row's own kind of file (a .cgns of zones is a .cgns), where a .vtm is
// another kind (a vtkMultiBlockDataSet naming one .vts a block, in a
// directory beside it) with a suffix of its own, which ParaView and VTK's
// readers go by. Under the vts id, eg2d_blocks_write would put a .vtm where
// the command and the user name a .vts. Its one writer serves a grid too
// (a set of one block), so that eg2d_write takes every listed format.
const FileFormat kFormats[] = {
    {EG2D_FORMAT_PLOT3D, "plot3d", ".xyz", kPlot3dFlags, write_plot3d, nullptr, nullptr, nullptr, write_plot3d_blocks},
    {EG2D_FORMAT_PLOT3D_ASCII, "plot3d-ascii", ".p3d", EG2D_PLOT3D_3D | EG2D_PLOT3D_MULTI | EG2D_PLOT3D_EXTRUDED,
     write_plot3d_ascii, nullptr, nullptr, nullptr, write_plot3d_ascii_blocks},
    {EG2D_FORMAT_VTS, "vts", ".vts", 0, write_vts},
    {EG2D_FORMAT_CGNS, "cgns", ".cgns", 0, write_cgns, nullptr, nullptr, nullptr, write_cgns_blocks},
    {EG2D_FORMAT_GMV, "gmv", ".gmv", 0, write_gmv},
    {EG2D_FORMAT_MATLAB, "matlab", ".m", 0, write_matlab},
    {EG2D_FORMAT_SVG, "svg", ".svg", 0, write_svg},
    {EG2D_FORMAT_SU2, "su2", ".su2", 0, write_su2, nullptr, write_su2_mesh},
    {EG2D_FORMAT_OPENFOAM, "openfoam", "_foam", 0, nullptr, write_openfoam, nullptr, write_openfoam_mesh},
    {EG2D_FORMAT_REPORT, "report", ".report.txt", 0, write_report},
    {EG2D_FORMAT_REPORT_JSON, "report-json", ".report.json", 0, write_report_json},
    {EG2D_FORMAT_VTM, "vtm", ".vtm", 0, nullptr, nullptr, nullptr, nullptr, nullptr, write_vtm},
};
}  // namespace

Table<FileFormat> format_table() { return table_of(kFormats); }

const FileFormat *find_format(int id) { return format_table().find(id); }

std::vector<FileFormat> set_formats() {
    std::vector<FileFormat> out;
    for (const FileFormat &k : format_table())
        if (k.write_mesh || k.write_mesh_directory || k.write_blocks || k.write_blocks_files) out.push_back(k);
    return out;
}

SetWriting set_writing(int id) {
    const FileFormat *f = id >= 0 ? find_format(id & kFormatMask) : nullptr;
    if (!f) fail(Failure::Argument, format("format = %d: no such file format", id));
    if (f->write_mesh || f->write_mesh_directory) return SetWriting::Mesh;
    if (f->write_blocks || f->write_blocks_files) return SetWriting::Zones;
    std::string can;
    for (const FileFormat &k : set_formats()) can += std::string(can.empty() ? "" : ", ") + k.name;
    fail(Failure::Unsupported, format("the %s format cannot hold a set of blocks (%s can; or write each block's grid)",
                                      f->name, can.c_str()));
}

void write_mesh(const UnstructuredMesh &mesh, const Settings &settings, const std::string &title, const char *path,
                int id) {
    const FileFormat *f = find_format(id & kFormatMask);
    if (id & ~kFormatMask) fail(Failure::Argument, format("format = %#x: the %s format takes no flags", id, f->name));
    if (!*path) fail(Failure::Argument, "path is empty");
    const MeshRequest r{mesh, settings, title};
    if (f->write_mesh_directory) {
        f->write_mesh_directory(r, path);
        return;
    }
    OutputFile out(path);
    f->write_mesh(r, out);
    out.commit();
}

void write_blocks(const std::vector<const Grid *> &grids, const std::vector<ZoneJoin> &joins,
                  const std::vector<std::string> &names, const Settings &settings, const char *path, int id) {
    const FileFormat *f = find_format(id & kFormatMask);
    const int flags = id & ~kFormatMask;
    if (flags & ~f->allowed_flags)
        fail(Failure::Argument, format("format = %#x: flags %#x do not apply to the %s format", id,
                                       flags & ~f->allowed_flags, f->name));
    const BlocksRequest r{grids, settings, flags, joins, names};
    if (f->write_blocks_files) {
        if (!*path) fail(Failure::Argument, "path is empty");
        f->write_blocks_files(r, path);
        return;
    }
    OutputFile out(path);
    f->write_blocks(r, out);
    out.commit();
}

void write_grid(const Grid &grid, const Settings &settings, const char *path, int id, const RunSummary *run) {
    const FileFormat *f = id >= 0 ? find_format(id & kFormatMask) : nullptr;
    if (!f) fail(Failure::Argument, format("format = %d: no such file format", id));
    if (f->write_directory) {
        if (id & ~kFormatMask)
            fail(Failure::Argument, format("format = %#x: the %s format takes no flags", id, f->name));
        if (!*path) fail(Failure::Argument, "path is empty");
        f->write_directory(WriteRequest{grid, settings, 0, run}, path);
        return;
    }
    const int flags = id & ~kFormatMask;
    if (flags & ~f->allowed_flags)
        fail(Failure::Argument, format("format = %#x: flags %#x do not apply to the %s format", id,
                                             flags & ~f->allowed_flags, f->name));
    if (f->write_blocks_files) {  // a set of one block
        if (!*path) fail(Failure::Argument, "path is empty");
        f->write_blocks_files(BlocksRequest{{&grid}, settings, flags}, path);
        return;
    }
    OutputFile out(path);
    f->write(WriteRequest{grid, settings, flags, run}, out);
    out.commit();
}

}  // namespace eg2d
