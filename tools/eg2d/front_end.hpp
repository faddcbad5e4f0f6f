// What the front ends (eg2d airfoil, eg2d channel) share: their command
// line's numbers, sizes and levels, the formats list (--format), the library
// calls' failures, and the family of nested levels they write.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "eg2d.h"
#include "output_set.hpp"
#include "view_lines.hpp"

namespace eg2dtool {

struct GridDeleter {
    void operator()(eg2d_grid *g) const { eg2d_destroy(g); }
};
using GridPtr = std::unique_ptr<eg2d_grid, GridDeleter>;

// An output: a format of the command's table (features.cpp, the names and
// extensions case files use), with flags; plot3d3d is Plot3D one cell thick;
// svg and png are the command's own pictures (views).
struct Output {
    std::string name, extension;
    int id;
    bool views = false;
    bool directory = false;  // a case directory (openfoam)
};

// Whether --help or -h is among the arguments; then prints `help` on stdout.
bool help_asked(int argc, char **argv, const char *help);

// -o DIR's value; an empty one is refused (it would be taken as the filesystem root).
std::string output_dir(const std::string &command, const std::string &value);

// Failure(EXIT_USAGE) "COMMAND: MESSAGE (eg2d COMMAND --help shows the usage)".
[[noreturn]] void front_end_usage(const std::string &command, const std::string &message);

// A positive finite number of an option, or a usage failure naming it.
double positive_number(const std::string &command, const std::string &option, const std::string &value);

// The first cell's height: `first` when given (> 0), else the height for
// y+ at the Reynolds number based on `length`, by the library's turbulent
// flat-plate estimate (eg2d_first_cell_height: Schlichting 1979).
// Failure(EXIT_USAGE) naming --yplus and --reynolds when the library refuses them.
double first_cell(const std::string &command, double first, double yplus, double reynolds, double length);

// --size NIxNJ (9 <= NI, 5 <= NJ, both <= 100000).
void parse_size(const std::string &command, const std::string &value, int &ni, int &nj);

// --levels N (1 to 12).
int parse_levels(const std::string &command, const std::string &value);

// Refuses levels the size cannot nest (NI-1, NJ-1 divisible by 2^(N-1), the
// coarsest at least 9x5), naming the most it allows.
void check_levels(const std::string &command, int ni, int nj, int levels);

// The outputs of a comma list of format names (usage or EXIT_UNSUPPORTED failures).
std::vector<Output> outputs_of(const std::string &command, const std::string &list);

// A failed library call: Failure with the status's exit code, "WHAT: the library's message".
void check(eg2d_grid *g, int status, const std::string &what);

// The run's events (eg2d_get_run_event), "note (iteration N): TEXT" each.
void print_run_notes(eg2d_grid *g);

// A level's files are named BASE.EXT, BASE = NAME-CIxCJ (level 0 the finest).
std::string level_base(const std::string &name, int ni, int nj, int level);

// The paths of the nested family, for check_before_solving: each level's
// formats, its reports and, with svg or png among the outputs, its views
// (BASE-VIEW.EXT for each of view_names).
std::vector<PlannedPath> level_paths(const std::string &command, int ni, int nj, int levels, const std::string &name,
                                     const std::vector<Output> &outputs, const std::vector<std::string> &view_names);

// Lines a level's reports get besides the library's: text appended to
// BASE.report.txt, and JSON members ("  \"key\": value", comma-separated)
// added to the object of BASE.report.json.
struct ReportLines {
    std::string text, json;
};

// setup: called on each coarser level's grid before anything of it is
// written (its patches). each_level: adds what else a level has to the set
// (its views, ...) and returns its reports' lines.
using LevelSetup = std::function<void(int level, eg2d_grid *level_grid, int ci, int cj)>;
using LevelHook = std::function<ReportLines(int level, eg2d_grid *level_grid, const std::string &base, int ci, int cj)>;

// The nested family into `set` (committed by the caller): level k every
// 2^k-th node of g (topology as g's), its formats (not the views) and the
// text and JSON reports; setup may be empty. Returns each level's text report.
std::vector<std::string> write_levels(OutputSet &set, eg2d_grid *g, int topology, int ni, int nj, int levels,
                                      const std::string &name, const std::vector<Output> &outputs,
                                      const LevelSetup &setup, const LevelHook &each_level);

// The pictures (svg, png among outputs) of one level into `set`: BASE-VIEW.svg/.png for
// each of views(the grid's lines), titled "eg2d TITLE: VIEW".
void write_views(OutputSet &set, const eg2d_grid *g, const std::vector<Output> &outputs, const std::string &base,
                 const std::string &title, const std::function<std::vector<View>(const GridLines &)> &views);

}  // namespace eg2dtool
