#include "airfoil_command.hpp"

#include <eg2d.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "face_check.hpp"
#include "failure.hpp"
#include "features.hpp"
#include "front_end.hpp"
#include "grid_views.hpp"
#include "huge_pages.hpp"
#include "output_set.hpp"
#include "progress.hpp"
#include "runner.hpp"
#include "text_output.hpp"
#include "tmr_comparison.hpp"
#include "view_picture.hpp"

namespace eg2dtool {

const char *const airfoil_help =
    "usage: eg2d airfoil SOURCE --size NIxNJ (--yplus Y --reynolds RE | --first-cell H)\n"
    "                   [--topology c|o] [--farfield R] [--le-spacing S] [--te-spacing S]\n"
    "                   [--te blunt|sharpen] [--te-base T] [--growth G] [--levels N]\n"
    "                   [--method hybrid|elliptic|hyperbolic] [--format LIST] [-o DIR] [--quiet]\n"
    "\n"
    "An O- or C-grid round an airfoil (eg2d_set_airfoil), wall-resolved, written as a\n"
    "family of nested grids in the formats flow solvers read.\n"
    "  SOURCE         a NACA 4-digit code (the standard open section, its base kept blunt;\n"
    "                 with --te sharpen the section closed sharply at chord 1)\n"
    "                 or a Selig or Lednicer coordinate file\n"
    "  --size         the finest grid, NI x NJ nodes (on a C-grid NI counts both cut sides)\n"
    "  --yplus, --reynolds\n"
    "                 the first cell from y+ at the chord Reynolds number, by the turbulent\n"
    "                 flat-plate skin friction Cf = (2 log10(Re) - 0.65)^-2.3 (Schlichting 1979)\n"
    "  --first-cell   or the first cell's height in chords\n"
    "  --topology     c (default) or o\n"
    "  --farfield     chords to the far field (default 100)\n"
    "  --le-spacing, --te-spacing\n"
    "                 spacing along the section at its leading and trailing edge, chords\n"
    "                 (default: a tenth and a quarter of its mean spacing)\n"
    "  --te           an open trailing edge: kept as a blunt base, part of the wall, its\n"
    "                 cells about --te-spacing apart (default; on a C-grid the cut leaves\n"
    "                 its midpoint along its normal) or sharpened (each surface moved\n"
    "                 towards the base's midpoint); the run says which\n"
    "  --te-base      O-grid: a sharp (or sharpened) trailing edge is cut back along the\n"
    "                 chord to a straight base T chords thick, part of the wall (default\n"
    "                 5e-5): a single edge node leaves its two cells corners of about 172\n"
    "                 degrees, which OpenFOAM's checkMesh fails on skewness; 0 keeps the\n"
    "                 sharp edge; the run says which\n"
    "  --growth       the largest growth of the wall layer's cells accepted (default 1.2);\n"
    "                 a grid whose first 30 cells grow faster is reported and exits 4\n"
    "  --levels       N nested grids, each coarser one every other node of the next: NI-1\n"
    "                 and NJ-1 must be divisible by 2^(N-1) (default 1)\n"
    "  --method       hybrid (default: the hyperbolic march's wall layer held, elliptic\n"
    "                 above), elliptic (the Sorenson-type wall control) or hyperbolic (the\n"
    "                 march alone; the far field is its own)\n"
    "  --format       a comma list of the formats of case files (plot3d, plot3d-ascii, cgns,\n"
    "                 su2, openfoam: a case directory, vts, vtm: NAME.vtm and its NAME/,\n"
    "                 gmv, matlab), plot3d3d (Plot3D one cell thick, for plot3dToFoam) and\n"
    "                 the pictures svg and png (cairo): four views, the domain, the airfoil\n"
    "                 (1.5 chords), its leading and trailing edge (0.05 chords), 800x600\n"
    "                 pixels (the domain 800 on its longer side); default plot3d. A report\n"
    "                 (text and JSON) is always written\n"
    "  -o DIR         the output directory (default .; created if missing). The family is\n"
    "                 written as one set, all or nothing: formats, plugins (cgns) and paths\n"
    "                 are checked before the solve, and a failed write, a full disk or\n"
    "                 SIGINT/SIGTERM (exit 130/143) leaves DIR as it was\n"
    "Files: DIR/NAME-NIxNJ.EXT per level and format (the extensions of eg2d run: .xyz, .cgns,\n"
    "  .su2, _foam/, .vts, ...; plot3d3d -3d.xyz; the pictures -domain, -airfoil, -le and\n"
    "  -te .svg or .png), NAME the NACA code or the file's stem. A C-grid of one of the sizes of\n"
    "  NASA's Turbulence Modeling Resource NACA 0012 family (7169x2049 ... 113x33) is compared\n"
    "  with its published figures in DIR/NAME-NIxNJ.tmr.txt, printed for the finest level.\n"
    "From 2^18 nodes the command runs itself again with glibc's transparent huge pages\n"
    "  (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) and says so; EG2D_HUGE_PAGES=0 runs without,\n"
    "  EG2D_HUGE_PAGES=1 with them at any size.\n"
    "\n"
    "example:\n"
    "  eg2d airfoil 0012 --topology c --size 385x97 --yplus 1 --reynolds 6e6 --levels 3 \\\n"
    "       --format plot3d3d,cgns,su2,openfoam,vts -o out\n";

namespace {

struct CurveDeleter {
    void operator()(eg2d_curve *c) const { eg2d_curve_destroy(c); }
};

struct Args {
    std::string source, out_dir = ".", topology = "c", method = "hybrid", te, formats = "plot3d";
    int ni = 0, nj = 0, levels = 1;
    double yplus = 0, reynolds = 0, first = 0, growth = 1.2, farfield = 100, le = 0, tes = 0;
    double te_base = -1;  // O-grid: the base a sharp trailing edge is cut to; < 0: the library's default
    bool quiet = false;
};

[[noreturn]] void usage(const std::string &message) { front_end_usage("airfoil", message); }

double number(const std::string &option, const std::string &value) { return positive_number("airfoil", option, value); }

Args parse(int argc, char **argv) {
    Args a;
    bool has_first = false;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--quiet") {
            a.quiet = true;
            continue;
        }
        if (arg.size() > 1 && arg[0] == '-') {
            if (k + 1 >= argc) usage(arg + " needs a value");
            const std::string v = argv[++k];
            if (arg == "-o") a.out_dir = output_dir("airfoil", v);
            else if (arg == "--topology") a.topology = v;
            else if (arg == "--method") a.method = v;
            else if (arg == "--te") a.te = v;
            else if (arg == "--format") a.formats = v;
            else if (arg == "--yplus") a.yplus = number(arg, v);
            else if (arg == "--reynolds") a.reynolds = number(arg, v);
            else if (arg == "--first-cell") a.first = number(arg, v), has_first = true;
            else if (arg == "--growth") a.growth = number(arg, v);
            else if (arg == "--farfield") a.farfield = number(arg, v);
            else if (arg == "--le-spacing") a.le = number(arg, v);
            else if (arg == "--te-spacing") a.tes = number(arg, v);
            else if (arg == "--te-base") a.te_base = v == "0" ? 0.0 : number(arg, v);
            else if (arg == "--levels") a.levels = parse_levels("airfoil", v);
            else if (arg == "--size") parse_size("airfoil", v, a.ni, a.nj);
            else {
                usage("unknown option " + arg);
            }
        } else if (a.source.empty()) {
            a.source = arg;
        } else {
            usage("more than one SOURCE (\"" + a.source + "\", \"" + arg + "\")");
        }
    }
    if (a.source.empty()) usage("no SOURCE (a NACA 4-digit code or a coordinate file)");
    if (a.ni == 0) usage("no --size");
    if (has_first == (a.yplus > 0 || a.reynolds > 0)) usage("give --first-cell, or --yplus with --reynolds");
    if (!has_first && (a.yplus <= 0 || a.reynolds <= 0)) usage("--yplus needs --reynolds, and --reynolds --yplus");
    if (a.topology != "c" && a.topology != "o") usage("--topology expects c or o, found \"" + a.topology + "\"");
    if (a.method != "hybrid" && a.method != "elliptic" && a.method != "hyperbolic")
        usage("--method expects hybrid, elliptic or hyperbolic, found \"" + a.method + "\"");
    if (a.te.empty()) a.te = "blunt";
    if (a.te != "blunt" && a.te != "sharpen") usage("--te expects blunt or sharpen, found \"" + a.te + "\"");
    check_levels("airfoil", a.ni, a.nj, a.levels);
    return a;
}

bool is_naca4(const std::string &s) {
    return s.size() == 4 && std::isdigit(static_cast<unsigned char>(s[0])) && std::isdigit(static_cast<unsigned char>(s[1])) &&
           std::isdigit(static_cast<unsigned char>(s[2])) && std::isdigit(static_cast<unsigned char>(s[3]));
}

std::string stem(const std::string &path) {
    std::string s = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
    const std::size_t dot = s.find_last_of('.');
    return dot == std::string::npos || dot == 0 ? s : s.substr(0, dot);
}

// The largest ratio of consecutive cell heights over the first 30 cells of
// the body's grid lines (JMIN nodes first..last).
double wall_growth(eg2d_grid *g, int ni, int nj, int first, int last) {
    std::vector<double> x(static_cast<std::size_t>(ni) * nj), y(x.size());
    eg2d_get_coordinates(g, x.data(), y.data());
    auto h = [&](int i, int j) {
        const std::size_t a = static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j, b = a + ni;
        return std::hypot(x[b] - x[a], y[b] - y[a]);
    };
    double worst = 0;
    for (int i = first; i <= last; ++i)
        for (int j = 1; j < 30 && j < nj - 1; ++j) worst = std::max(worst, h(i, j) / h(i, j - 1));
    return worst;
}

// The section's ends' midpoint (the trailing edge), its leading edge (the
// farthest of 2000 points of the section from it, as eg2d_set_airfoil finds
// it), the chord between, and the gap between the ends in chords (open above
// 1e-7, as eg2d_set_airfoil tests it).
struct SectionShape {
    double te_x, te_y, le_x = 0, le_y = 0, chord = 0, gap = 0;
};
SectionShape section_shape(const eg2d_curve *c) {
    double x0, y0, x1, y1;
    eg2d_curve_evaluate(c, 0.0, &x0, &y0);
    eg2d_curve_evaluate(c, 1.0, &x1, &y1);
    SectionShape s{0.5 * (x0 + x1), 0.5 * (y0 + y1)};
    for (int k = 1; k < 2000; ++k) {
        double x, y;
        eg2d_curve_evaluate(c, k / 2000.0, &x, &y);
        if (std::hypot(x - s.te_x, y - s.te_y) > s.chord)
            s.chord = std::hypot(x - s.te_x, y - s.te_y), s.le_x = x, s.le_y = y;
    }
    s.gap = s.chord > 0 ? std::hypot(x1 - x0, y1 - y0) / s.chord : 0;
    return s;
}

// printf into a string.
template <class... Args>
std::string format_text(const char *f, Args... args) {
    const int n = std::snprintf(nullptr, 0, f, args...);
    std::string out(static_cast<std::size_t>(std::max(n, 0)), '\0');
    std::snprintf(out.data(), out.size() + 1, f, args...);
    return out;
}

// Says what becomes of an open trailing edge.
void trailing_edge_note(double gap, bool sharpen) {
    if (gap <= 1e-7) return;
    if (sharpen)
        std::printf("note: the open trailing edge (%.3g chords thick) sharpened: each surface moved towards the base's "
                    "midpoint in proportion to its distance along the chord (--te sharpen)\n", gap);
    else
        std::printf("note: the open trailing edge (%.3g chords thick) kept as a blunt base, part of the wall "
                    "(--te sharpen closes it)\n", gap);
}

// Every path of the family, TMR comparisons included, for check_before_solving.
std::vector<PlannedPath> planned_paths(const Args &a, const std::vector<Output> &outputs, const std::string &name) {
    std::vector<PlannedPath> paths =
        level_paths("airfoil", a.ni, a.nj, a.levels, name, outputs, {"domain", "airfoil", "le", "te"});
    for (int level = 0; level < a.levels && a.topology == "c"; ++level) {
        const int s = 1 << level;
        if (tmr_level((a.ni - 1) / s + 1, (a.nj - 1) / s + 1) >= 0)
            paths.push_back({level_base(name, a.ni, a.nj, level) + ".tmr.txt", -1, false, "airfoil"});
    }
    return paths;
}

// JSON has no infinity or NaN: a value that is not finite is null.
std::string json_number(double v) { return std::isfinite(v) ? format_text("%.17g", v) : "null"; }

// The face check as the reports' lines: the text report's line (also
// printed) and the JSON report's member "solver_check".
ReportLines face_check_lines(const FaceCheck &fv, double nonorth_limit, double skew_limit) {
    ReportLines r;
    r.text = format_text(
        "solver check    faces as OpenFOAM's checkMesh measures them: non-orthogonality max %.3g (limit %g), "
        "skewness max %.3g (limit %g)%s\n", fv.nonorth_max, nonorth_limit, fv.skew_max, skew_limit,
        fv.past == 0 ? "" : format_text(": %d face(s) past, the worst of cell (%d, %d): non-orthogonality %.3g, "
                                        "skewness %.3g", fv.past, fv.worst_i, fv.worst_j, fv.worst_nonorth,
                                        fv.worst_skew).c_str());
    r.json = "  \"solver_check\": {\"nonorthogonality_max_deg\": " + json_number(fv.nonorth_max) +
             ", \"nonorthogonality_limit_deg\": " + json_number(nonorth_limit) +
             ", \"skewness_max\": " + json_number(fv.skew_max) + ", \"skewness_limit\": " + json_number(skew_limit) +
             ", \"faces_past\": " + std::to_string(fv.past) + ", \"worst\": " +
             (fv.past == 0 ? std::string("null")
                           : format_text("{\"cell\": [%d, %d], \"nonorthogonality_deg\": %s, \"skewness\": %s}",
                                         fv.worst_i, fv.worst_j, json_number(fv.worst_nonorth).c_str(),
                                         json_number(fv.worst_skew).c_str())) + "}";
    return r;
}

}  // namespace

int run_airfoil(int argc, char **argv, char **whole_argv) {
    if (help_asked(argc, argv, airfoil_help)) return EXIT_OK;
    const Args a = parse(argc, argv);
    rerun_with_huge_pages(whole_argv, static_cast<double>(a.ni) * a.nj, a.quiet);
    const std::vector<Output> outputs = outputs_of("airfoil", a.formats);
    const double h = first_cell("airfoil", a.first, a.yplus, a.reynolds, 1.0);
    eg2d_curve *raw = nullptr;
    const bool naca = is_naca4(a.source);
    // A NACA code is the standard open section with its base kept blunt, or
    // with --te sharpen the section closed sharply (NASA's TMR grids): round
    // a sharp edge an O-grid's cells beside the edge's line turn 90 degrees
    // across one cell, which OpenFOAM's checkMesh fails (skewness 17 on NACA
    // 0012 257x129), while at a blunt base it is 2.2.
    const int st = naca ? eg2d_curve_naca4(a.source.c_str(), a.te == "sharpen" ? EG2D_NACA_CLOSED_TE : 0, &raw)
                        : eg2d_curve_read_airfoil(a.source.c_str(), &raw);
    if (st != EG2D_OK) throw Failure(st == EG2D_ERR_IO ? EXIT_IO : EXIT_GEOMETRY, std::string("airfoil: ") + eg2d_last_error(nullptr));
    std::unique_ptr<eg2d_curve, CurveDeleter> section(raw);
    const std::string name = naca ? "naca" + a.source : stem(a.source);
    const bool cgrid = a.topology == "c";
    const int step = 1 << (a.levels - 1);
    check_before_solving(a.out_dir, planned_paths(a, outputs, name));

    eg2d_grid *raw_grid = nullptr;
    if (eg2d_create(a.ni, a.nj, &raw_grid) != EG2D_OK)
        throw Failure(EXIT_MEMORY, std::string("airfoil: ") + eg2d_last_error(nullptr));
    GridPtr grid(raw_grid);
    eg2d_grid *g = grid.get();
    check(g, eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_FARFIELD, a.farfield), "--farfield");
    if (a.le > 0) check(g, eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_LE_SPACING, a.le), "--le-spacing");
    if (a.tes > 0) check(g, eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_TE_SPACING, a.tes), "--te-spacing");
    check(g, eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_TRAILING_EDGE,
                                a.te == "blunt" ? EG2D_AIRFOIL_TE_BLUNT : EG2D_AIRFOIL_TE_SHARPEN), "--te");
    if (a.te_base >= 0) check(g, eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_O_TE_BASE, a.te_base), "--te-base");
    double te_base = 0;
    eg2d_get_parameter(g, EG2D_PARAM_AIRFOIL_O_TE_BASE, &te_base);
    check(g, eg2d_set_airfoil(g, section.get(), cgrid ? EG2D_TOPO_C : EG2D_TOPO_O), "airfoil " + a.source);
    // The library's cut (EG2D_PARAM_AIRFOIL_WAKE_NODES automatic: what a
    // program embedding it gets), unless a level of the family would not
    // have the trailing edge on a node: then the nearest count that does.
    int wake = 0;
    check(g, eg2d_get_cut(g, &wake), "the cut");
    if (cgrid && wake % step != 0) {
        wake = step * std::max(1, static_cast<int>(std::lround(static_cast<double>(wake) / step)));
        check(g, eg2d_set_parameter(g, EG2D_PARAM_AIRFOIL_WAKE_NODES, wake), "the cut's nodes");
        check(g, eg2d_set_airfoil(g, section.get(), EG2D_TOPO_C), "airfoil " + a.source);
    }
    const SectionShape shape = section_shape(section.get());
    const double gap = shape.gap;  // 0 for a NACA code closed by --te sharpen
    if (!a.quiet) {
        // What the file gave, so that a misread shows at once.
        const auto tidy = [&](double v) { return std::fabs(v) < 1e-9 * shape.chord ? 0.0 : v; };  // not -1e-20
        if (!naca)
            std::printf("%s: chord %.6g from the leading edge (%.6g, %.6g) to the trailing edge (%.6g, %.6g)\n",
                        a.source.c_str(), shape.chord, tidy(shape.le_x), tidy(shape.le_y), tidy(shape.te_x),
                        tidy(shape.te_y));
        std::printf("%s %s-grid %dx%d, first cell %.4g chords, far field %g chords, %s trailing edge, method %s\n",
                    name.c_str(), cgrid ? "C" : "O", a.ni, a.nj, h, a.farfield,
                    gap <= 1e-7 ? "sharp" : (a.te == "blunt" ? "blunt" : "sharpened"), a.method.c_str());
        if (naca && a.te == "sharpen") std::printf("note: the NACA section closed sharply at chord 1 (--te sharpen)\n");
        trailing_edge_note(gap, a.te == "sharpen");
        if (!cgrid && (gap <= 1e-7 || a.te == "sharpen"))
            std::printf(te_base > 0 ? "note: the O-grid's sharp trailing edge cut back to a base %.3g chords thick, part "
                                      "of the wall (--te-base 0 keeps it sharp)\n"
                                    : "note: the O-grid's trailing edge kept sharp (--te-base 0): its two cells have "
                                      "corners of about 180 degrees less half its angle\n", te_base);
    }
    Progress progress(isatty(STDOUT_FILENO) != 0, a.quiet);
    check(g, eg2d_set_monitor(g, Progress::monitor, &progress), "monitor");
    // in the march too: Ctrl-C and SIGTERM stop it at its next layer
    check(g, eg2d_set_parameter(g, EG2D_PARAM_MONITOR_SET_UP, 1), "monitor");
    int status;
    if (a.method == "hyperbolic") {
        check(g, eg2d_set_parameter(g, EG2D_PARAM_MARCH_DISTANCE, a.farfield), "--farfield");
        check(g, eg2d_set_parameter(g, EG2D_PARAM_MARCH_FIRST_HEIGHT, h), "the first cell");
        check(g, eg2d_set_parameter(g, EG2D_PARAM_MARCH_GROWTH, 3.0), "the march");
        status = eg2d_initialize(g, EG2D_INIT_HYPERBOLIC);
    } else {
        check(g, eg2d_set_wall_spacing(g, EG2D_SIDE_JMIN, h), "the first cell");
        check(g, eg2d_set_orthogonality(g, EG2D_ORTHO_WALL), "the wall control");
        check(g, eg2d_set_parameter(g, EG2D_PARAM_WALL_LAYER, a.method == "hybrid" ? 2 : 0), "--method");
        // The tolerance and the cycle are eg2d_set_airfoil's run defaults.
        status = eg2d_solve(g);
    }
    progress.finish();
    if (!a.quiet) print_run_notes(g);
    if (Progress::interrupted())  // the march does not call the monitor: stopped here
        throw Failure(Progress::interrupt_exit_code(),
                      std::string("airfoil: interrupted by ") + Progress::interrupt_name() + ": no files written");
    check(g, status, a.method == "hyperbolic" ? "the march" : "the solve");
    const int body0 = cgrid ? wake : 0, body1 = cgrid ? a.ni - 1 - wake : a.ni - 1;
    const double growth = wall_growth(g, a.ni, a.nj, body0, body1);

    // OpenFOAM's checkMesh limits (aspect ratio aside): what each level's
    // faces are checked against, as a solver would (face_check.hpp).
    constexpr double kNonorthLimit = 70.0, kSkewLimit = 4.0;
    std::string past_limits;
    std::vector<std::string> heads, tails;  // each level's lines, printed once the set is in place (its report between)
    OutputSet set(a.out_dir);
    const std::vector<std::string> reports = write_levels(
        set, g, cgrid ? EG2D_TOPO_C : EG2D_TOPO_O, a.ni, a.nj, a.levels, name, outputs, {},
        [&](int level, eg2d_grid *lg, const std::string &base, int ci, int cj) {
        write_views(set, lg, outputs, base, name + " " + std::to_string(ci) + "x" + std::to_string(cj), airfoil_views);
        std::vector<double> lx(static_cast<std::size_t>(ci) * cj), ly(lx.size());
        eg2d_get_coordinates(lg, lx.data(), ly.data());
        const FaceCheck fv = check_faces(ci, cj, lx, ly, !cgrid, wake / (1 << level), kNonorthLimit, kSkewLimit);
        const ReportLines lines = face_check_lines(fv, kNonorthLimit, kSkewLimit);
        if (fv.past > 0 && past_limits.empty())
            past_limits = format_text("%dx%d has %d face(s) past checkMesh's limits (non-orthogonality %g, skewness %g), "
                                      "the worst of cell (%d, %d): non-orthogonality %.3g, skewness %.3g",
                                      ci, cj, fv.past, kNonorthLimit, kSkewLimit, fv.worst_i, fv.worst_j,
                                      fv.worst_nonorth, fv.worst_skew);
        // A C-grid of one of the TMR family's sizes is compared with it.
        const int s = 1 << level;
        const std::string tmr = cgrid ? tmr_comparison(lg, ci, cj, wake / s, a.farfield, a.levels - 1 - level) : std::string();
        if (!tmr.empty()) set.add_text(base + ".tmr.txt", tmr);
        heads.push_back(format_text("level %d: %dx%d -> %s/%s.*\n", level, ci, cj, a.out_dir.c_str(), base.c_str()));
        tails.push_back(level == 0 ? tmr : fv.past > 0 ? lines.text : std::string());
        return lines;
    });
    set.commit();
    if (!a.quiet)  // the finest level's report in full, with its face check
        for (std::size_t k = 0; k < heads.size(); ++k)
            std::printf("%s%s%s", heads[k].c_str(), k == 0 ? reports[0].c_str() : "", tails[k].c_str());
    if (growth > a.growth) {
        std::fprintf(stderr,
                     "eg2d: airfoil: the wall layer grows by up to %.3f over its first 30 cells, more than --growth %g: "
                     "raise NJ or lower --farfield (the files are written)\n", growth, a.growth);
    }
    if (!past_limits.empty())
        std::fprintf(stderr, "eg2d: airfoil: %s (the files are written)\n", past_limits.c_str());
    return growth > a.growth || !past_limits.empty() ? EXIT_GEOMETRY : EXIT_OK;
}

}  // namespace eg2dtool
