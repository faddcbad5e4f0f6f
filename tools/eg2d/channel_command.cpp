#include "channel_command.hpp"

#include <eg2d.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "channel_check.hpp"
#include "channel_walls.hpp"
#include "failure.hpp"
#include "formula.hpp"
#include "front_end.hpp"
#include "grid_views.hpp"
#include "huge_pages.hpp"
#include "progress.hpp"
#include "wall_summary.hpp"

namespace eg2dtool {

const char *const channel_help =
    "usage: eg2d channel (--lower WALL --upper WALL | --centreline CURVE --width W) --size NIxNJ\n"
    "                   (--first-cell H | --yplus Y --reynolds RE [--length L])\n"
    "                   [--symmetry-upper] [--spline] [--inlet-spacing A] [--outlet-spacing B]\n"
    "                   [--growth G] [--levels N] [--format LIST] [-o DIR] [--quiet]\n"
    "\n"
    "A single-block grid of an internal flow (a channel, duct or diffuser) between two\n"
    "walls, wall-resolved on both (the library's graded wall layer), with the inlet\n"
    "(IMIN) and outlet (IMAX) straight between the walls' ends, written as a family of\n"
    "nested grids in the formats flow solvers read.\n"
    "  --lower, --upper\n"
    "                 the walls, each from the inlet to the outlet, the upper on the left\n"
    "                 of the lower: a point file (x y per line) or two expressions\n"
    "                 \"x(s);y(s)\" in s from 0 to 1 (muParser: sin, cos, pi, ...)\n"
    "  --centreline, --width\n"
    "                 or a centreline (a point file or \"x(s);y(s)\") and the width across\n"
    "                 it, a number or an expression in s (its arc length from 0 to 1):\n"
    "                 each wall half the width from the centreline along its normal\n"
    "  --spline       a point file's points joined by a cubic spline (default: straight)\n"
    "  --inlet-spacing, --outlet-spacing\n"
    "                 the spacing of the nodes along the walls at the inlet, the outlet\n"
    "                 (length units; Vinokur 1983's two-sided stretching; the other end\n"
    "                 uniform when only one is given). Default: uniform in arc length\n"
    "  --size         the finest grid, NI x NJ nodes (NJ across the channel)\n"
    "  --first-cell   the first cell's height at the walls, in the walls' length unit\n"
    "  --yplus, --reynolds, --length\n"
    "                 or the first cell from y+ at the Reynolds number based on --length\n"
    "                 (default the lower wall's length; the centreline's), by the turbulent\n"
    "                 flat-plate skin friction Cf = (2 log10(Re) - 0.65)^-2.3 (Schlichting\n"
    "                 1979), as eg2d airfoil does\n"
    "  --symmetry-upper\n"
    "                 the upper side is a symmetry plane (a half channel): no wall layer\n"
    "  --growth       the largest growth of a wall layer's cells accepted (default 1.2);\n"
    "                 a layer whose first 30 cells grow faster is reported with the NJ\n"
    "                 that would do, and the command exits 4 (the files are written)\n"
    "  --levels       N nested grids, each coarser one every other node of the next: NI-1\n"
    "                 and NJ-1 must be divisible by 2^(N-1) (default 1)\n"
    "  --format       a comma list as eg2d airfoil's (plot3d, plot3d-ascii, cgns, su2,\n"
    "                 openfoam: a case directory, vts, vtm, gmv, matlab, plot3d3d, and the\n"
    "                 pictures svg and png: the domain and the lower wall's inlet corner);\n"
    "                 default plot3d. A report (text and JSON) is always written\n"
    "  -o DIR         the output directory (default .; created if missing), written as one\n"
    "                 set, all or nothing, as eg2d airfoil's\n"
    "Patches: lower_wall and upper_wall (walls; with --symmetry-upper the upper is\n"
    "  symmetry), inlet (inflow) and outlet (outflow), in every format that has\n"
    "  boundary conditions (SU2 markers, the OpenFOAM boundary file, CGNS BCs).\n"
    "Files: DIR/channel-NIxNJ.EXT per level and format (the extensions of eg2d run).\n"
    "After the files, one line per wall: its first cell and its growth over 30 cells.\n"
    "Exit codes: 0 done; 2 a bad command line; 3 a bad expression or point file; 4 walls\n"
    "  that cross or run opposite ways, a domain the library refuses, or a wall layer\n"
    "  that grows too fast (then only with the files written); 5, 6, 7 not converged,\n"
    "  diverged, folded; 8 a file that cannot be read or written. Nothing is written but\n"
    "  for exit 0 and a wall layer's exit 4.\n"
    "\n"
    "examples:\n"
    "  eg2d channel --lower \"4*s;0\" --upper \"4*s;1\" --size 257x129 --first-cell 1e-4 \\\n"
    "       --levels 2 --format su2,openfoam,cgns -o out\n"
    "  eg2d channel --lower lower.dat --upper upper.dat --size 257x129 --yplus 1 \\\n"
    "       --reynolds 1e6 --format openfoam,svg -o diffuser\n"
    "  eg2d channel --centreline \"4*s;0.5*sin(pi*s)\" --width \"1 + 0.5*s\" --size 257x129 \\\n"
    "       --first-cell 1e-4 -o bend\n";

namespace {

struct Args {
    WallOptions walls;
    std::string out_dir = ".", formats = "plot3d";
    int ni = 0, nj = 0, levels = 1;
    double yplus = 0, reynolds = 0, length = 0, first = 0, growth = 1.2;
    bool quiet = false, symmetry = false;
};

[[noreturn]] void usage(const std::string &message) { front_end_usage("channel", message); }

double number(const std::string &option, const std::string &value) { return positive_number("channel", option, value); }

Args parse(int argc, char **argv) {
    Args a;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--quiet" || arg == "--symmetry-upper" || arg == "--spline") {
            (arg == "--quiet" ? a.quiet : arg == "--spline" ? a.walls.spline : a.symmetry) = true;
            continue;
        }
        if (arg.size() < 2 || arg[0] != '-') usage("unexpected argument \"" + arg + "\" (the walls are --lower and --upper)");
        if (k + 1 >= argc) usage(arg + " needs a value");
        const std::string v = argv[++k];
        if (arg == "-o") a.out_dir = output_dir("channel", v);
        else if (arg == "--lower") a.walls.lower = v;
        else if (arg == "--upper") a.walls.upper = v;
        else if (arg == "--centreline" || arg == "--centerline") a.walls.centreline = v;
        else if (arg == "--width") a.walls.width = v;
        else if (arg == "--inlet-spacing") a.walls.inlet_spacing = number(arg, v);
        else if (arg == "--outlet-spacing") a.walls.outlet_spacing = number(arg, v);
        else if (arg == "--format") a.formats = v;
        else if (arg == "--yplus") a.yplus = number(arg, v);
        else if (arg == "--reynolds") a.reynolds = number(arg, v);
        else if (arg == "--length") a.length = number(arg, v);
        else if (arg == "--first-cell") a.first = number(arg, v);
        else if (arg == "--growth") a.growth = number(arg, v);
        else if (arg == "--levels") a.levels = parse_levels("channel", v);
        else if (arg == "--size") parse_size("channel", v, a.ni, a.nj);
        else usage("unknown option " + arg);
    }
    const WallOptions &w = a.walls;
    if (!w.centreline.empty() || !w.width.empty()) {
        if (!w.lower.empty() || !w.upper.empty()) usage("give --lower and --upper, or --centreline and --width, not both");
        if (w.centreline.empty()) usage("--width needs --centreline (a point file or \"x(s);y(s)\")");
        if (w.width.empty()) usage("--centreline needs --width (a number or an expression in s)");
    } else {
        if (w.lower.empty()) usage("no --lower (a point file or \"x(s);y(s)\")");
        if (w.upper.empty()) usage("no --upper (a point file or \"x(s);y(s)\")");
    }
    if (a.ni == 0) usage("no --size");
    const bool from_yplus = a.yplus > 0 || a.reynolds > 0 || a.length > 0;
    if ((a.first > 0) == from_yplus) usage("give --first-cell, or --yplus with --reynolds (and --length)");
    if (from_yplus && (a.yplus <= 0 || a.reynolds <= 0)) usage("--yplus needs --reynolds, and --reynolds --yplus");
    check_levels("channel", a.ni, a.nj, a.levels);
    return a;
}

// The patches of a level of ni x nj nodes: both walls (the upper a symmetry
// plane for a half channel), the inlet and the outlet.
void set_patches(eg2d_grid *g, int ni, int nj, bool symmetry) {
    check(g, eg2d_set_patch(g, EG2D_SIDE_JMIN, 0, ni - 1, EG2D_PATCH_WALL, "lower_wall"), "the lower wall's patch");
    check(g, eg2d_set_patch(g, EG2D_SIDE_JMAX, 0, ni - 1, symmetry ? EG2D_PATCH_SYMMETRY : EG2D_PATCH_WALL,
                            symmetry ? "symmetry" : "upper_wall"), "the upper side's patch");
    check(g, eg2d_set_patch(g, EG2D_SIDE_IMIN, 0, nj - 1, EG2D_PATCH_INFLOW, "inlet"), "the inlet's patch");
    check(g, eg2d_set_patch(g, EG2D_SIDE_IMAX, 0, nj - 1, EG2D_PATCH_OUTFLOW, "outlet"), "the outlet's patch");
}

// The domain, and the lower wall's inlet corner (a tenth of the inlet's width).
std::vector<View> channel_views(const GridLines &lines) {
    const double x0 = lines.x[0], y0 = lines.y[0];
    const std::size_t top = static_cast<std::size_t>(lines.ni) * (lines.nj - 1);
    const double w = 0.1 * std::hypot(lines.x[top] - x0, lines.y[top] - y0);
    return {domain_view(lines), fitted_view("inlet-corner", x0 - 0.2 * w, y0 - 0.2 * w, x0 + w, y0 + 0.8 * w,
                                            kViewWidth, kViewHeight)};
}

}  // namespace

int run_channel(int argc, char **argv, char **whole_argv) {
    if (help_asked(argc, argv, channel_help)) return EXIT_OK;
    const Args a = parse(argc, argv);
    rerun_with_huge_pages(whole_argv, static_cast<double>(a.ni) * a.nj, a.quiet);
    const std::vector<Output> outputs = outputs_of("channel", a.formats);
    const Walls walls = channel_walls(a.walls, a.ni);
    check_channel_walls(walls);
    const std::vector<double> &lx = walls.lx, &ly = walls.ly, &ux = walls.ux, &uy = walls.uy;
    const double length = a.length > 0 ? a.length : a.walls.centreline.empty() ? polyline_length(lx, ly)
                                                                              : centreline_length(walls);
    const double h = first_cell("channel", a.first, a.yplus, a.reynolds, length);
    check_before_solving(a.out_dir, level_paths("channel", a.ni, a.nj, a.levels, "channel", outputs, {"domain", "inlet-corner"}));

    eg2d_grid *raw = nullptr;
    if (eg2d_create(a.ni, a.nj, &raw) != EG2D_OK)
        throw Failure(EXIT_MEMORY, std::string("channel: ") + eg2d_last_error(nullptr));
    GridPtr grid(raw);
    eg2d_grid *g = grid.get();
    // The inlet and outlet: uniform points on the straight lines between the
    // walls' ends, which the graded layer moves along them to its spacing.
    auto across = [&](std::size_t k, std::vector<double> &x, std::vector<double> &y) {
        x.resize(static_cast<std::size_t>(a.nj));
        y.resize(x.size());
        for (int j = 0; j < a.nj; ++j) {
            const double t = static_cast<double>(j) / (a.nj - 1);
            x[static_cast<std::size_t>(j)] = lx[k] + t * (ux[k] - lx[k]);
            y[static_cast<std::size_t>(j)] = ly[k] + t * (uy[k] - ly[k]);
        }
    };
    std::vector<double> ix, iy, ox, oy;
    across(0, ix, iy);
    across(lx.size() - 1, ox, oy);
    check(g, eg2d_set_side(g, EG2D_SIDE_JMIN, lx.data(), ly.data()), "channel: --lower");
    check(g, eg2d_set_side(g, EG2D_SIDE_JMAX, ux.data(), uy.data()), "channel: --upper");
    check(g, eg2d_set_side(g, EG2D_SIDE_IMIN, ix.data(), iy.data()), "channel: the inlet");
    check(g, eg2d_set_side(g, EG2D_SIDE_IMAX, ox.data(), oy.data()), "channel: the outlet");
    set_patches(g, a.ni, a.nj, a.symmetry);
    check(g, eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), "channel: the first cell");
    if (!a.symmetry) check(g, eg2d_set_wall_spacing(g, EG2D_SIDE_JMAX, h), "channel: the first cell");
    check(g, eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), "channel: the wall control");
    if (!a.quiet)
        std::printf("channel %dx%d, first cell %.4g (%s), lower wall %.6g long, upper %.6g, %s\n", a.ni, a.nj, h,
                    a.first > 0 ? "--first-cell" : ("from y+ at Re " + fmt(a.reynolds) + " on length " + fmt(length)).c_str(),
                    polyline_length(lx, ly), polyline_length(ux, uy),
                    a.symmetry ? "the upper side a symmetry plane" : "two walls");
    Progress progress(isatty(STDOUT_FILENO) != 0, a.quiet);
    check(g, eg2d_set_monitor(g, Progress::monitor, &progress), "monitor");
    // in the march too: Ctrl-C and SIGTERM stop it at its next layer
    check(g, eg2d_set_parameter(g, EG2D_PARAM_MONITOR_SET_UP, 1), "monitor");
    const int status = eg2d_solve(g);
    progress.finish();
    if (!a.quiet) print_run_notes(g);
    if (Progress::interrupted())
        throw Failure(Progress::interrupt_exit_code(),
                      std::string("channel: interrupted by ") + Progress::interrupt_name() + ": no files written");
    check(g, status, "channel: the solve");

    OutputSet set(a.out_dir);
    std::string written;  // printed once the set is in place
    write_levels(set, g, EG2D_TOPO_SINGLE, a.ni, a.nj, a.levels, "channel", outputs,
                 [&](int, eg2d_grid *lg, int ci, int cj) { set_patches(lg, ci, cj, a.symmetry); },
                 [&](int level, eg2d_grid *lg, const std::string &base, int ci, int cj) {
        write_views(set, lg, outputs, base, "channel " + std::to_string(ci) + "x" + std::to_string(cj), channel_views);
        written += "level " + std::to_string(level) + ": " + std::to_string(ci) + "x" + std::to_string(cj) + " -> " +
                   a.out_dir + "/" + base + ".*\n";
        return ReportLines();
    });
    set.commit();
    if (!a.quiet) std::printf("%s", written.c_str());
    // The layers' figures are printed whatever --quiet says: they are the result.
    bool short_layer = print_wall_layer(g, EG2D_SIDE_JMIN, "lower_wall", h, a.growth);
    if (!a.symmetry) short_layer = print_wall_layer(g, EG2D_SIDE_JMAX, "upper_wall", h, a.growth) || short_layer;
    return short_layer ? EXIT_GEOMETRY : EXIT_OK;
}

}  // namespace eg2dtool
