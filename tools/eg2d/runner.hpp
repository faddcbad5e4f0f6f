// Runs one case through the library's C API: grid, sides, controls, solve with
// progress, quality summary, output files.
#pragma once

#include <string>

#include "case_file.hpp"

namespace eg2dtool {

struct RunOptions {
    std::string out_dir = ".";
    bool quiet = false;   // no progress lines
    bool live = false;    // progress rewrites one terminal line
};

// Returns the exit code; prints the summary on stdout. Throws Failure with the
// message for stderr. Writes output files only after a successful run.
int run_case(const Case &c, const RunOptions &options);

}  // namespace eg2dtool
