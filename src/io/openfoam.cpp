// EG2D_FORMAT_OPENFOAM: an OpenFOAM case directory for a 2-D run: the grid
// as one layer of hexahedra (z = 0 and z = EG2D_PARAM_SPAN) in
// constant/polyMesh, the cut's duplicate nodes merged so that its faces are
// internal, one patch per boundary patch name (walls `wall`, symmetry
// `symmetry`, the rest `patch`) and the front and back faces in one `empty`
// patch "frontAndBack", which makes OpenFOAM solve in 2-D. Faces are in
// OpenFOAM's order (the polyMesh description of the OpenFOAM User Guide):
// internal faces first, upper-triangular (by owner, then neighbour), each
// pointing from owner to neighbour; then each patch's faces together,
// pointing out of the domain. system/ gets a minimal controlDict, fvSchemes
// and fvSolution, which checkMesh and the other utilities need to run, but
// only where the case has none: a case the user has set up keeps its own.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <sys/stat.h>

#include "base/error.hpp"
#include "eg2d.h"
#include "io/formats.hpp"
#include "io/unstructured.hpp"

namespace eg2d {

namespace {
void header(OutputFile &out, const char *cls, const char *location, const char *object, const std::string &note = "") {
    out.print("/*--------------------------------*- C++ -*----------------------------------*\\\n"
              "  Written by eg2d (elliptic grid generation).\n"
              "\\*---------------------------------------------------------------------------*/\n"
              "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       %s;\n",
              cls);
    if (!note.empty()) out.print("    note        \"%s\";\n", note.c_str());
    out.print("    location    \"%s\";\n    object      %s;\n}\n\n", location, object);
}

const char *foam_type(PatchType t) {
    switch (t) {
    case PatchType::Wall: return "wall";
    case PatchType::Symmetry: return "symmetry";
    default: return "patch";
    }
}

bool exists(const std::string &path) {
    struct stat st;
    return stat(path.c_str(), &st) == 0;
}

const char kControlDict[] =
    "// Enough for checkMesh and the other utilities; set the solver and its\n"
    "// run here, and its fields in 0/, before a run.\n"
    "application     simpleFoam;\n"
    "startFrom       startTime;\n"
    "startTime       0;\n"
    "stopAt          endTime;\n"
    "endTime         1000;\n"
    "deltaT          1;\n"
    "writeControl    timeStep;\n"
    "writeInterval   100;\n"
    "purgeWrite      0;\n"
    "writeFormat     ascii;\n"
    "writePrecision  12;\n"
    "writeCompression off;\n"
    "timeFormat      general;\n"
    "timePrecision   6;\n"
    "runTimeModifiable true;\n";

const char kFvSchemes[] =
    "ddtSchemes           { default steadyState; }\n"
    "gradSchemes          { default Gauss linear; }\n"
    "divSchemes           { default none; }\n"
    "laplacianSchemes     { default Gauss linear corrected; }\n"
    "interpolationSchemes { default linear; }\n"
    "snGradSchemes        { default corrected; }\n"
    "wallDist             { method meshWave; }\n";

const char kFvSolution[] =
    "solvers\n{\n}\n"
    "SIMPLE\n{\n    nNonOrthogonalCorrectors 0;\n}\n";
}  // namespace

void write_openfoam_mesh(const MeshRequest &r, const std::string &dir) {
    const UnstructuredMesh &m = r.mesh;
    const double span = r.settings.span;
    const std::vector<InternalEdge> internal = internal_edges(m);
    const int n = static_cast<int>(m.points()), cells = static_cast<int>(m.cells());
    std::size_t boundary_faces = 0;
    for (const MeshPatch &p : m.patches) boundary_faces += p.edges.size();
    const std::size_t faces = internal.size() + boundary_faces + 2 * m.cells();

    MadeDirectories made;
    made.make(dir);
    made.make(dir + "/constant");
    made.make(dir + "/constant/polyMesh");
    made.make(dir + "/system");
    const std::string mesh = dir + "/constant/polyMesh/";
    const char *loc = "constant/polyMesh";
    const std::string note = format("nPoints:%d  nCells:%d  nFaces:%zu  nInternalFaces:%zu", 2 * n, cells, faces,
                                    internal.size());

    OutputFile points(mesh + "points");
    header(points, "vectorField", loc, "points");
    points.print("%d\n(\n", 2 * n);
    for (double z : {0.0, span})
        for (std::size_t p = 0; p < m.points(); ++p) {
            points.print("(");
            points.real(m.x[p], ' ');
            points.real(m.y[p], ' ');
            points.real(z, ')');
            points.print("\n");
        }
    points.print(")\n");

    // An edge a -> b, counter-clockwise round its owner, extruded: its
    // right-hand normal points out of the owner.
    OutputFile face_file(mesh + "faces"), owner(mesh + "owner"), neighbour(mesh + "neighbour");
    header(face_file, "faceList", loc, "faces");
    header(owner, "labelList", loc, "owner", note);
    header(neighbour, "labelList", loc, "neighbour", note);
    face_file.print("%zu\n(\n", faces);
    owner.print("%zu\n(\n", faces);
    neighbour.print("%zu\n(\n", internal.size());
    auto side_face = [&](int a, int b, int cell) {
        face_file.print("4(%d %d %d %d)\n", a, b, b + n, a + n);
        owner.print("%d\n", cell);
    };
    for (const InternalEdge &e : internal) {
        side_face(e.a, e.b, e.owner);
        neighbour.print("%d\n", e.neighbour);
    }
    for (const MeshPatch &p : m.patches)
        for (const MeshEdge &e : p.edges) side_face(e.a, e.b, e.cell);
    for (std::size_t id = 0; id < m.cells(); ++id) {  // back (z = 0), normal -z
        const auto &c = m.quads[id];
        face_file.print("4(%d %d %d %d)\n", c[0], c[3], c[2], c[1]);
        owner.print("%zu\n", id);
    }
    for (std::size_t id = 0; id < m.cells(); ++id) {  // front (z = span), normal +z
        const auto &c = m.quads[id];
        face_file.print("4(%d %d %d %d)\n", c[0] + n, c[1] + n, c[2] + n, c[3] + n);
        owner.print("%zu\n", id);
    }
    face_file.print(")\n");
    owner.print(")\n");
    neighbour.print(")\n");

    OutputFile boundary(mesh + "boundary");
    header(boundary, "polyBoundaryMesh", loc, "boundary");
    boundary.print("%zu\n(\n", m.patches.size() + 1);
    std::size_t start = internal.size();
    auto entry = [&](const std::string &name, const char *type, std::size_t count) {
        boundary.print("    %s\n    {\n        type            %s;\n        inGroups        List<word> 1(%s);\n"
                       "        nFaces          %zu;\n        startFace       %zu;\n    }\n",
                       name.c_str(), type, type, count, start);
        start += count;
    };
    for (const MeshPatch &p : m.patches) entry(p.name, foam_type(p.type), p.edges.size());
    entry("frontAndBack", "empty", 2 * m.cells());
    boundary.print(")\n");

    // A set's blocks as cell zones named as the blocks (blockMesh's zones).
    std::unique_ptr<OutputFile> zones;
    if (!m.zones.empty()) {
        zones = std::make_unique<OutputFile>(mesh + "cellZones");
        header(*zones, "regIOobject", loc, "cellZones");
        zones->print("%zu\n(\n", m.zones.size());
        for (const CellZone &z : m.zones) {
            zones->print("%s\n{\n    type cellZone;\ncellLabels List<label> %zu\n(\n", z.name.c_str(), z.count);
            for (std::size_t c = z.first; c < z.first + z.count; ++c) zones->print("%zu\n", c);
            zones->print(")\n;\n}\n");
        }
        zones->print(")\n");
    }

    // The user's own system/ files stay; missing ones are written.
    std::vector<std::unique_ptr<OutputFile>> system;
    const struct { const char *name, *cls, *text; } files[] = {
        {"controlDict", "dictionary", kControlDict},
        {"fvSchemes", "dictionary", kFvSchemes},
        {"fvSolution", "dictionary", kFvSolution},
    };
    for (const auto &f : files) {
        const std::string path = dir + "/system/" + f.name;
        if (exists(path)) continue;
        system.push_back(std::make_unique<OutputFile>(path));
        header(*system.back(), f.cls, "system", f.name);
        system.back()->print("%s", f.text);
    }

    // Everything is written: now put it in place.
    for (OutputFile *f : {&points, &face_file, &owner, &neighbour, &boundary}) f->commit();
    if (zones) zones->commit();
    else std::remove((mesh + "cellZones").c_str());  // an earlier mesh's: its cells are not these
    for (auto &f : system) f->commit();
    made.keep();
}

void write_openfoam(const WriteRequest &r, const std::string &dir) {
    write_openfoam_mesh(MeshRequest{unstructured_mesh(r.grid), r.settings, ""}, dir);
}

}  // namespace eg2d
