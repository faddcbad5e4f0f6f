// The files of a run that the command makes itself, beside the grid's: the
// iteration history (residual per iteration, from the monitor) as CSV and as
// an SVG plot, and the control functions per node as CSV
// (docs/case-files.md, [output] formats "history", "history-svg", "controls").
#pragma once

#include <string>
#include <vector>

typedef struct eg2d_grid eg2d_grid;

namespace eg2dtool {

struct HistoryRow {
    int iteration;
    double residual;
};

// "iteration,residual" and one line per iteration (17 significant digits).
std::string history_csv(const std::vector<HistoryRow> &rows);

// log10(residual) against the iteration, with the tolerance as a dashed line.
std::string history_svg(const std::vector<HistoryRow> &rows, double tolerance, const std::string &title);

// "i,j,x,y,P,Q" and one line per node in the library's order (i fastest):
// the coordinates and eg2d_get_controls' P, Q. Throws Failure on a library error.
std::string controls_csv(const eg2d_grid *grid);

}  // namespace eg2dtool
