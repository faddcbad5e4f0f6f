// What the case file can ask for, by name, and whether this build of the library has it.
// A name that exists but whose library part is not in this build gives a precise
// "not available in this build" error (EXIT_UNSUPPORTED) instead of "unknown".
#pragma once

#include <string>
#include <vector>

namespace eg2dtool {

struct Feature {
    const char *name;  // as written in a case file (the library's list name)
    int id;            // the library's constant
    bool available;    // compiled into this build of the tool's library
    const char *extension = "";  // output formats: file name extension
    const char *section = "solver";  // parameters: the table of the case file that holds them
    bool flag = false;               // parameters: on/off, written true/false (1/0 accepted)
    bool directory = false;          // output formats: a directory (an OpenFOAM case), not a file
    int tool = 0;                    // output formats: a ToolFile the command writes itself (0: eg2d_write)
};

// Output files the command writes itself, from the run rather than the grid
// (run_files.hpp), or the grid's PNG picture (view_picture.hpp; available
// only with cairo): Feature::tool, OutputFile::tool.
enum ToolFile { kLibraryFile = 0, kHistoryCsv = 1, kHistorySvg = 2, kControlsCsv = 3, kGridPng = 4 };

const std::vector<Feature> &solvers();        // [solver] method
const std::vector<Feature> &parameters();     // keys that are EG2D_PARAM_* settings, by section
const std::vector<Feature> &orthogonality();  // [controls] orthogonality
const std::vector<Feature> &controls();       // the other [controls] keys
const std::vector<Feature> &formats();        // [output] formats
const std::vector<Feature> &cell_metrics();   // [output] svg_quality
const std::vector<Feature> &geometry();       // curves and distributions on sides
const std::vector<Feature> &distributions();  // a side's distribution kind
const std::vector<Feature> &set_formats();    // the formats that hold a set of blocks (eg2d_blocks_write)
const std::vector<Feature> &systems();
const std::vector<Feature> &topologies();
const std::vector<Feature> &initializers();

// The names of a table (for messages: "expected one of: ...").
std::vector<std::string> names(const std::vector<Feature> &table);

}  // namespace eg2dtool
