// eg2d airfoil: an airfoil grid from a NACA code or a coordinate file and a
// handful of numbers (eg2d_set_airfoil, the hybrid wall layer), as a family
// of nested levels written in the formats flow solvers read.
#pragma once

namespace eg2dtool {

extern const char *const airfoil_help;

// argv[0] is "airfoil"; whole_argv is main's (the command runs itself
// again with it for huge pages, huge_pages.hpp). Returns the exit code;
// throws Failure.
int run_airfoil(int argc, char **argv, char **whole_argv);

}  // namespace eg2dtool
