// A case file: everything that defines one grid, read from TOML (schema in docs/case-files.md).
#pragma once

#include <string>
#include <vector>

#include "eg2d.h"
#include "formula.hpp"
#include "location.hpp"
#include "side_spec.hpp"

namespace eg2dtool {

struct ParameterSetting {  // a generic EG2D_PARAM_* setting
    int id;
    double value;
    Location where;
};

struct LineSource {  // eg2d_add_line_source
    int direction;   // EG2D_XI / EG2D_ETA
    double line, amplitude, decay;
    Location where;
};

struct PointSource {  // eg2d_add_point_source
    double xi, eta, amplitude, decay;
    Location where;
};

struct WallSpacing {  // eg2d_set_wall_spacing, or _nodes when `nodes` holds the side's heights
    int side;
    double height;  // the least of `nodes`, if any
    Location where;
    std::vector<double> nodes;
};

struct PatchSetting {  // eg2d_set_patch
    int side, first, last, type;
    std::string name;
    Location where;
};

struct InteriorLineSetting {  // eg2d_set_interior_line: the line's curve, placed like a side's
    int direction;             // EG2D_XI (a column) / EG2D_ETA (a row)
    int index;
    SideSpec curve;
    Location where;
};

struct Clustering {  // Khattri's (2006) clustering map in one direction (eg2d_clustering_map)
    int kind = -1;      // EG2D_CLUSTER_*; -1: uniform
    double a = 0.5, b = 0, strength = 0;
    Location where;
};

struct OutputFile {
    int format;         // EG2D_FORMAT_* (-1 for the command's own files: tool)
    std::string name;   // file name, e.g. "swan.svg"
    Location where;
    bool directory = false;  // a directory format (Feature::directory): NAME_foam
    int tool = 0;            // a ToolFile (features.hpp) the command writes itself; 0: eg2d_write
};

// A set of blocks (docs/case-files.md, "Sets of blocks"): [[blocks]], [[joins]].
struct BlockSpec {  // one block: a single-block grid of its own
    std::string name;
    int ni = 0, nj = 0;
    Location where, size_at, name_at;
    Constants constants;  // the case's, with this block's ni, nj
    std::vector<SideSpec> sides;
    std::vector<PatchSetting> patches;
    std::vector<WallSpacing> wall_spacings;  // wall_spacing: this block's walls
};

struct JoinEnd {  // one side of a join: nodes first..last of a block's side
    int block = 0, side = 0, first = 0, last = 0;
    Location where;
};

struct JoinSpec {  // eg2d_blocks_join (and _hold_join when held)
    JoinEnd a, b;
    Location where;
    bool held = false;
};

struct Case {
    std::string file;  // as given
    std::string dir;   // directory of the case file: relative point files are read from here
    std::string title;
    int ni = 0, nj = 0;
    Location size_at;
    int topology = 0, system = 1, initial = 0;
    Location topology_at, system_at, initial_at;
    bool solve = true;  // false: the start grid is the result (to show an initializer alone)
    int solver = EG2D_SOLVER_MULTIGRID;  // the library's default
    Location solver_at;
    std::vector<ParameterSetting> parameters;
    Constants constants;
    std::vector<SideSpec> sides;
    // controls
    int orthogonality = -1;  // -1: not set
    Location orthogonality_at;
    std::vector<WallSpacing> wall_spacings;
    double wall_growth_limit = 1.2;  // a larger wall-layer growth exits EXIT_GEOMETRY (wall_summary.hpp)
    std::vector<LineSource> line_sources;
    std::vector<PointSource> point_sources;
    std::string source_p, source_q;  // formulas in i, j, ni, nj ("" = none)
    Location source_p_at, source_q_at;
    std::string weight;  // formula in i, j ("" = none): eg2d_set_weight
    Location weight_at;
    bool parameter_grid = false;  // Khattri (2006): eg2d_set_parameter_grid from two clustering maps
    Clustering cluster_i, cluster_j;
    std::vector<PatchSetting> patches;  // [[patches]]: boundary conditions of the solver formats
    std::vector<InteriorLineSetting> interior_lines;  // [[interior_lines]]
    std::vector<OutputFile> outputs;
    int svg_quality = -1;  // EG2D_QUALITY_* the picture is coloured by; -1: none
    Location svg_quality_at;
    // A set of blocks: every block's sides and patches are its own; size,
    // sides, patches and the other one-grid keys are not at the top level.
    std::vector<BlockSpec> blocks;  // empty: one grid
    std::vector<JoinSpec> joins;
    Location blocks_at;
};

// Reads a case from TOML text; `file` names it in messages, `dir` resolves relative
// point files; ni, nj > 0 override the file's size (--size). Throws Failure(EXIT_CASE
// or EXIT_UNSUPPORTED) with "FILE:LINE:COL: key 'K': ...".
Case read_case(const std::string &text, const std::string &file, const std::string &dir, int ni = 0, int nj = 0);

// Reads the file at `path` (EXIT_IO if it cannot be read), then read_case.
Case read_case_file(const std::string &path, int ni = 0, int nj = 0);

}  // namespace eg2dtool
