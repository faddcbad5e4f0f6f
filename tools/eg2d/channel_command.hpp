// eg2d channel: a channel, duct or diffuser grid between two walls (point
// files or expressions), wall-resolved on both (the library's graded layer),
// with inlet, outlet, wall and symmetry patches, as a family of nested
// levels written in the formats flow solvers read.
#pragma once

namespace eg2dtool {

extern const char *const channel_help;

// argv[0] is "channel"; whole_argv is main's (a large grid runs the command
// again with huge pages, as eg2d airfoil does). Returns the exit code; throws Failure.
int run_channel(int argc, char **argv, char **whole_argv);

}  // namespace eg2dtool
