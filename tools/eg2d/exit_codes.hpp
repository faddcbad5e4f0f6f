// The eg2d command's exit codes, one per kind of failure (documented in --help).
#pragma once

namespace eg2dtool {

enum ExitCode {
    EXIT_OK = 0,
    EXIT_INTERNAL = 1,       // an unexpected failure (out of memory, a bug)
    EXIT_USAGE = 2,          // a bad command line
    EXIT_CASE = 3,           // the case file: syntax, unknown key, wrong type, bad formula, point file
    EXIT_GEOMETRY = 4,       // the library rejected the domain or a setting (corners disagree, ...)
    EXIT_NOT_CONVERGED = 5,  // the iteration limit was reached
    EXIT_DIVERGED = 6,       // the run diverged
    EXIT_FOLDED = 7,         // the converged grid has folded cells
    EXIT_IO = 8,             // an output file could not be written
    EXIT_UNSUPPORTED = 9,    // the case asks for a feature not available in this build
    EXIT_MEMORY = 10,        // out of memory: the grid is too large for this machine
    EXIT_INTERRUPTED = 130,  // Ctrl-C (SIGINT): stopped cleanly, nothing written (SIGTERM: 143, Progress)
};

// The exit code for a library status (EG2D_ERR_*).
int exit_code_for_status(int status);

}  // namespace eg2dtool
