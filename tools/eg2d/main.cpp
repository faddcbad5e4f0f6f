// eg2d: generate a grid from a case file (eg2d run) or from the built-in gallery (eg2d demo).
#include <eg2d.h>
#include <unistd.h>

#include <toml++/toml.h>

#include <cfenv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include "airfoil_command.hpp"
#include "case_file.hpp"
#include "channel_command.hpp"
#include "demos.hpp"
#include "failure.hpp"
#include "features.hpp"
#include "tables.hpp"
#include "runner.hpp"

using namespace eg2dtool;

namespace {

const char *help_text =
    "usage: eg2d run CASE.toml [-o DIR] [--size NIxNJ] [--quiet]\n"
    "       eg2d airfoil SOURCE --size NIxNJ (--yplus Y --reynolds RE | --first-cell H) [...]\n"
    "       eg2d channel --lower WALL --upper WALL --size NIxNJ (--first-cell H | --yplus Y --reynolds RE) [...]\n"
    "       eg2d demo [NAME] [-o DIR] [--size NIxNJ] [--quiet]\n"
    "       eg2d demo --list\n"
    "       eg2d --help | --version      (--version lists what this build offers)\n"
    "       eg2d --tables                (every parameter, format, metric and name, as Markdown)\n"
    "\n"
    "Generates a boundary-fitted quadrilateral grid by elliptic PDEs (libeg2d).\n"
    "  run      reads the case file (TOML; see docs/case-files.md), solves, prints a\n"
    "           quality summary and writes the files listed in its [output] table:\n"
    "           the grid's formats, and the run's own: \"history\" (NAME.history.csv:\n"
    "           iteration,residual per iteration), \"history-svg\" (NAME.history.svg: the\n"
    "           residual's log against the iteration), \"controls\" (NAME.controls.csv:\n"
    "           i,j,x,y,P,Q per node, the control terms as Thompson's P, Q), \"png\"\n"
    "           (NAME.png: the grid drawn by cairo, where the build has it). A case of\n"
    "           [[blocks]] and [[joins]] is a set of blocks solved as one grid: su2 and\n"
    "           openfoam one merged mesh, svg and png one picture, the other formats\n"
    "           NAME-BLOCK files\n"
    "  airfoil  an O- or C-grid round a NACA section or a coordinate file, wall-resolved,\n"
    "           as nested levels in solver formats (eg2d airfoil --help)\n"
    "  channel  a channel, duct or diffuser grid between two walls (or round a centreline),\n"
    "           wall-resolved, with inlet, outlet, wall and symmetry patches, as nested\n"
    "           levels in solver formats (eg2d channel --help)\n"
    "  demo     runs a built-in case of the gallery (the case files of examples/;\n"
    "           default: swan, the elliptic-grid course notes' swan domain) with no file at all\n"
    "\n"
    "options:\n"
    "  -o DIR          write the output files into DIR (created if missing; default .)\n"
    "  --size NIxNJ    override the case's size, e.g. --size 33x33 (not for [[blocks]])\n"
    "  --quiet         no progress lines\n"
    "  --list          (demo) list the gallery\n"
    "\n"
    "While it runs, a progress line shows the iteration, the residual (docs/NUMERICS.md)\n"
    "and the rate (mean residual factor per iteration). Ctrl-C stops the run cleanly\n"
    "and writes nothing.\n"
    "\n"
    "exit codes:\n"
    "  0    success: converged, unfolded, files written\n"
    "  1    internal error\n"
    "  2    bad command line\n"
    "  3    bad case file (syntax, unknown key, wrong type, missing side, bad formula)\n"
    "  4    the library rejected the domain or a setting (e.g. corners that disagree), or a wall\n"
    "       layer grows by more than 1.2 within its first 30 cells (the files are written)\n"
    "  5    not converged within max_iterations\n"
    "  6    diverged\n"
    "  7    the converged grid has folded cells\n"
    "  8    a file could not be read or written\n"
    "  9    the case asks for a feature not available in this build\n"
    "  10   out of memory: the grid is too large for this machine\n"
    "  130  interrupted by Ctrl-C (SIGINT), 143 by SIGTERM: nothing written\n"
    "\n"
    "example:\n"
    "  eg2d demo -o demo-out                 # swan.svg (and the grid) in demo-out/\n"
    "  eg2d run examples/valley.toml -o out --size 33x33\n";

struct Args {
    std::string command, target, out_dir = ".";
    int ni = 0, nj = 0;
    bool quiet = false, list = false;
};

[[noreturn]] void usage_error(const std::string &message) {
    throw Failure(EXIT_USAGE, message + " (eg2d --help shows the usage)");
}

Args parse_args(int argc, char **argv) {
    Args a;
    std::vector<std::string> positional;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "-o" || arg == "--size") {
            if (k + 1 >= argc) usage_error(arg + " needs a value");
            const std::string value = argv[++k];
            if (arg == "-o") {
                if (value.empty()) usage_error("-o needs a directory");
                a.out_dir = value;
            } else {
                char *end = nullptr;
                const long ni = std::strtol(value.c_str(), &end, 10);
                long nj = -1;
                if (end && *end == 'x') nj = std::strtol(end + 1, &end, 10);
                if (!end || *end || ni < 3 || nj < 3 || ni > 100000 || nj > 100000)
                    usage_error("--size expects NIxNJ with 3 <= NI, NJ <= 100000, found \"" + value + "\"");
                a.ni = static_cast<int>(ni);
                a.nj = static_cast<int>(nj);
            }
        } else if (arg == "--quiet") {
            a.quiet = true;
        } else if (arg == "--list") {
            a.list = true;
        } else if (arg.size() > 1 && arg[0] == '-') {
            usage_error("unknown option " + arg);
        } else {
            positional.push_back(arg);
        }
    }
    if (positional.empty()) usage_error("no command");
    a.command = positional[0];
    if (positional.size() > 2) usage_error("too many arguments");
    if (positional.size() == 2) a.target = positional[1];
    if (a.command == "run" && a.target.empty()) usage_error("run needs a case file");
    if (a.command != "run" && a.command != "demo") usage_error("unknown command \"" + a.command + "\"");
    if (a.list && a.command != "demo") usage_error("--list belongs to demo");
    return a;
}

const Demo *find_demo(const std::string &name) {
    for (const auto &d : demos())
        if (name == d.name) return &d;
    return nullptr;
}

int list_demos() {
    for (const auto &d : demos()) {
        std::string title;
        try {
            title = toml::parse(d.text)["title"].value_or(std::string());
        } catch (const toml::parse_error &) {
        }
        std::string note;
        try {
            read_case(d.text, std::string("demo:") + d.name, ".");
        } catch (const Failure &f) {
            note = f.exit_code() == EXIT_UNSUPPORTED ? "  [not available in this build]" : "  [broken]";
        }
        std::printf("%-16s %s%s%s\n", d.name, title.c_str(), std::strcmp(d.name, default_demo()) ? "" : " (default)",
                    note.c_str());
    }
    return EXIT_OK;
}

// What this build offers, by the names case files use (tests read this too).
void print_features() {
    auto line = [](const char *what, const std::vector<Feature> &table) {
        std::string have, lack;
        for (const auto &f : table) (f.available ? have : lack) += std::string(" ") + f.name;
        std::printf("%-14s%s%s%s\n", what, have.c_str(), lack.empty() ? "" : "   not in this build:", lack.c_str());
    };
    line("topologies:", topologies());
    line("solvers:", solvers());
    line("orthogonality:", orthogonality());
    line("controls:", controls());
    line("geometry:", geometry());
    line("formats:", formats());
}

int run(const Args &a) {
    RunOptions o;
    o.out_dir = a.out_dir;
    o.quiet = a.quiet;
    o.live = isatty(STDOUT_FILENO) != 0;
    if (a.command == "run") return run_case(read_case_file(a.target, a.ni, a.nj), o);
    if (a.list) return list_demos();
    const std::string name = a.target.empty() ? default_demo() : a.target;
    const Demo *d = find_demo(name);
    if (!d) {
        std::string known;
        for (const auto &x : demos()) known += std::string(known.empty() ? "" : ", ") + x.name;
        usage_error("no demo named \"" + name + "\" (the gallery: " + known + ")");
    }
    return run_case(read_case(d->text, std::string("demo:") + d->name, ".", a.ni, a.nj), o);
}

}  // namespace

// The command's body with every failure turned into its message and exit code.
template <class Body>
int guarded(Body body) {
    try {
        return body();
    } catch (const Failure &f) {
        std::fflush(stdout);
        std::fprintf(stderr, "eg2d: %s\n", f.what());
        return f.exit_code();
    } catch (const std::bad_alloc &) {  // the library reports its own; this is the command's (the case file)
        std::fflush(stdout);
        std::fprintf(stderr, "eg2d: out of memory\n");
        return EXIT_MEMORY;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "eg2d: internal error: %s\n", e.what());
        return EXIT_INTERNAL;
    }
}

// EG2D_FP_TRAPS=1: trap invalid, divide-by-zero and overflow as a host
// solver built with -ffpe-trap does; the command's tests run so, to hold the
// library (and the command) to raising none of them on valid input.
void trap_floating_point_if_asked() {
    const char *v = std::getenv("EG2D_FP_TRAPS");
    if (v && !std::strcmp(v, "1")) feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
}

int main(int argc, char **argv) {
    trap_floating_point_if_asked();
    if (argc > 1 && !std::strcmp(argv[1], "airfoil")) return guarded([&] { return run_airfoil(argc - 1, argv + 1, argv); });
    if (argc > 1 && !std::strcmp(argv[1], "channel")) return guarded([&] { return run_channel(argc - 1, argv + 1, argv); });
    for (int k = 1; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--help") || !std::strcmp(argv[k], "-h")) {
            std::fputs(help_text, stdout);
            return EXIT_OK;
        }
        if (!std::strcmp(argv[k], "--tables")) {
            std::fputs(tables_markdown().c_str(), stdout);
            return EXIT_OK;
        }
        if (!std::strcmp(argv[k], "--version")) {
            int major, minor, patch;
            eg2d_version(&major, &minor, &patch);
            std::printf("eg2d %d.%d.%d\n", major, minor, patch);
            print_features();
            return EXIT_OK;
        }
    }
    return guarded([&] { return run(parse_args(argc, argv)); });
}
