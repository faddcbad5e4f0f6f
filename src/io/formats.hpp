// Grid files. Each format is a writer function in its own file, declared and
// listed in formats.cpp's table (format id -> writer); a format that accepts
// variant flags (EG2D_PLOT3D_*, OR-ed into the id) lists them.
#pragma once
#include <string>
#include <vector>

#include "base/settings.hpp"
#include "base/grid.hpp"
#include "base/table.hpp"
#include "io/output_file.hpp"

namespace eg2d {

// What the last run did, for the report formats.
struct RunSummary {
    const char *solver;
    int iterations;
    double residual, seconds;
};

struct WriteRequest {
    const Grid &grid;
    const Settings &settings;
    int flags;               // the EG2D_PLOT3D_* bits of the format argument
    const RunSummary *run;   // nullptr: not known
};

struct UnstructuredMesh;
// A mesh to write: a grid or a set of blocks merged (io/unstructured.hpp),
// and the line that says what it is ("257 x 129 nodes, C-grid").
struct MeshRequest {
    const UnstructuredMesh &mesh;
    const Settings &settings;
    const std::string &title;
};

// Nodes first_a..last_a of side side_a of grid a are nodes first_b..last_b
// of side side_b of grid b (a set of blocks' join, for the formats that
// record connections).
struct ZoneJoin {
    int a;
    Side side_a;
    int first_a, last_a;
    int b;
    Side side_b;
    int first_b, last_b;
};

// Grids to write into one file, one zone each (a set of blocks).
struct BlocksRequest {
    std::vector<const Grid *> grids;
    const Settings &settings;
    int flags;
    std::vector<ZoneJoin> joins = {};
    std::vector<std::string> names = {};  // a zone a block's names; empty: block0, block1, ...
    std::string name(std::size_t b) const { return b < names.size() ? names[b] : "block" + std::to_string(b); }
};

struct FileFormat {
    int id;                 // EG2D_FORMAT_*
    const char *name;       // list name: "plot3d-ascii"
    const char *suffix;     // of the file or directory a user would name: ".p3d", "_foam"
    int allowed_flags;      // the flags this writer understands
    void (*write)(const WriteRequest &request, OutputFile &out);
    // A format that is a directory of files (an OpenFOAM case): the writer
    // makes the directory and writes each file through an OutputFile.
    void (*write_directory)(const WriteRequest &request, const std::string &directory) = nullptr;
    // A format written from the grid as an unstructured mesh
    // (io/unstructured.hpp) writes a set of blocks merged too: these take
    // the mesh (a file, or a directory of files).
    void (*write_mesh)(const MeshRequest &request, OutputFile &out) = nullptr;
    void (*write_mesh_directory)(const MeshRequest &request, const std::string &directory) = nullptr;
    // A format with several zones in one file writes a set of blocks one zone a block.
    void (*write_blocks)(const BlocksRequest &request, OutputFile &out) = nullptr;
    // A format of a file a block and a file that names them (a VTK
    // multiblock .vtm): the writer is given the path and writes each file
    // through an OutputFile, committing them together (the file at the path
    // last); a grid is written as a set of one block.
    void (*write_blocks_files)(const BlocksRequest &request, const std::string &path) = nullptr;
};

Table<FileFormat> format_table();  // in increasing id order
// nullptr if there is no format with that id.
const FileFormat *find_format(int id);

// A set of blocks: whether the format writes them as one merged mesh
// (write_mesh) or a zone a block (write_blocks, write_blocks_files); Failure::Argument for no
// such format, Unsupported naming the formats that hold a set for one that
// does neither.
enum class SetWriting { Mesh, Zones };
SetWriting set_writing(int id);
// The formats that hold a set (a mesh, zone or block-files writer), in id order.
std::vector<FileFormat> set_formats();
// Writes a merged mesh (a set of blocks) to path in the format id.
void write_mesh(const UnstructuredMesh &mesh, const Settings &settings, const std::string &title, const char *path, int id);
// Writes the blocks a zone (or a file) each to path in the format (id | flags).
// names: the blocks' (BlocksRequest::names).
void write_blocks(const std::vector<const Grid *> &grids, const std::vector<ZoneJoin> &joins,
                  const std::vector<std::string> &names, const Settings &settings, const char *path, int id);

// Writes the grid to path in the format (id | flags); all-or-nothing.
void write_grid(const Grid &grid, const Settings &settings, const char *path, int id,
                const RunSummary *run = nullptr);

}  // namespace eg2d
