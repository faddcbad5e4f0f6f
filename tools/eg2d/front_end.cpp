#include "front_end.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "failure.hpp"
#include "features.hpp"
#include "formula.hpp"
#include "grid_lines.hpp"
#include "runner.hpp"
#include "text_output.hpp"
#include "view_picture.hpp"

namespace eg2dtool {

bool help_asked(int argc, char **argv, const char *help) {
    for (int k = 1; k < argc; ++k)
        if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h") {
            std::fputs(help, stdout);
            return true;
        }
    return false;
}

std::string output_dir(const std::string &command, const std::string &value) {
    if (value.empty())
        front_end_usage(command, "-o \"\": an empty output directory name (it would be the filesystem root; -o . is "
                                 "the current directory)");
    return value;
}

void front_end_usage(const std::string &command, const std::string &message) {
    throw Failure(EXIT_USAGE, command + ": " + message + " (eg2d " + command + " --help shows the usage)");
}

double positive_number(const std::string &command, const std::string &option, const std::string &value) {
    char *end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || !end || *end || !std::isfinite(v) || v <= 0)
        front_end_usage(command, option + " expects a positive number, found \"" + value + "\"");
    return v;
}

double first_cell(const std::string &command, double first, double yplus, double reynolds, double length) {
    double h = first;
    if (h > 0) return h;
    if (eg2d_first_cell_height(yplus, reynolds, length, &h) != EG2D_OK)
        throw Failure(EXIT_USAGE, command + ": --yplus " + fmt(yplus) + ", --reynolds " + fmt(reynolds) + ": " +
                                      eg2d_last_error(nullptr));
    return h;
}

void parse_size(const std::string &command, const std::string &v, int &ni, int &nj) {
    char *end = nullptr;
    const long i = std::strtol(v.c_str(), &end, 10);
    long j = -1;
    if (end && *end == 'x') j = std::strtol(end + 1, &end, 10);
    if (!end || *end || i < 9 || j < 5 || i > 100000 || j > 100000)
        front_end_usage(command, "--size expects NIxNJ with 9 <= NI <= 100000 and 5 <= NJ <= 100000, found \"" + v + "\"");
    ni = static_cast<int>(i);
    nj = static_cast<int>(j);
}

int parse_levels(const std::string &command, const std::string &v) {
    const double n = positive_number(command, "--levels", v);
    if (n != std::floor(n) || n > 12) front_end_usage(command, "--levels expects a whole number from 1 to 12, found \"" + v + "\"");
    return static_cast<int>(n);
}

void check_levels(const std::string &command, int ni, int nj, int levels) {
    auto nests = [&](int k) {
        const int step = 1 << k;
        return (ni - 1) % step == 0 && (nj - 1) % step == 0 && (ni - 1) / step + 1 >= 9 && (nj - 1) / step + 1 >= 5;
    };
    if (nests(levels - 1)) return;
    int most = 1;
    while (nests(most)) ++most;
    front_end_usage(command, "--levels " + std::to_string(levels) + " needs NI-1 and NJ-1 divisible by " +
                                 std::to_string(1 << (levels - 1)) + " and a coarsest grid of at least 9x5; " +
                                 std::to_string(ni) + "x" + std::to_string(nj) + " allows at most " +
                                 std::to_string(most) + " (e.g. 385x97 allows 6, 257x129 allows 6, 1793x513 allows 9)");
}

std::vector<Output> outputs_of(const std::string &command, const std::string &list) {
    std::vector<Output> out;
    // the library's formats but its reports (written with every level) and the pictures (views)
    auto listed = [](const Feature &k) {
        return k.tool == 0 && k.id != EG2D_FORMAT_REPORT && k.id != EG2D_FORMAT_REPORT_JSON && k.id != EG2D_FORMAT_SVG;
    };
    std::string known = "plot3d3d, svg, png";
    for (const Feature &k : formats())
        if (listed(k)) known += std::string(", ") + k.name;
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        if (name == "png" && !png_available())
            throw Failure(EXIT_UNSUPPORTED, command + ": --format png is not in this build: it needs cairo (Debian's "
                                                      "libcairo2-dev) when eg2d is configured; svg draws the same views");
        if (name == "svg" || name == "png") {
            out.push_back({name, "." + name, -1, true});
            continue;
        }
        if (name == "plot3d3d") {
            out.push_back({name, "-3d.xyz", EG2D_FORMAT_PLOT3D | EG2D_PLOT3D_EXTRUDED});
            continue;
        }
        const Feature *f = nullptr;
        for (const Feature &k : formats())
            if (listed(k) && name == k.name) f = &k;
        if (!f) front_end_usage(command, "--format: unknown format \"" + name + "\" (" + known + ")");
        if (!f->available) throw Failure(EXIT_UNSUPPORTED, command + ": --format " + name + " is not in this build");
        out.push_back({name, f->extension, f->id, false, f->directory});
    }
    if (out.empty()) front_end_usage(command, "--format needs at least one format");
    return out;
}

void check(eg2d_grid *g, int status, const std::string &what) {
    if (status != EG2D_OK) throw Failure(exit_code_for_status(status), what + ": " + eg2d_last_error(g));
}

void print_run_notes(eg2d_grid *g) {
    int events = 0;
    eg2d_get_run_info(g, EG2D_RUN_EVENTS, &events);
    for (int k = 0; k < events; ++k) {
        char text[1024];
        int at = 0;
        eg2d_get_run_event(g, k, &at, text, sizeof text);
        std::printf("note (iteration %d): %s\n", at, text);
    }
}

std::string level_base(const std::string &name, int ni, int nj, int level) {
    const int s = 1 << level;
    return name + "-" + std::to_string((ni - 1) / s + 1) + "x" + std::to_string((nj - 1) / s + 1);
}

namespace {

// The library's report formats, written with every level.
std::vector<const Feature *> report_formats() {
    std::vector<const Feature *> reports;
    for (const Feature &f : formats())
        if (f.id == EG2D_FORMAT_REPORT || f.id == EG2D_FORMAT_REPORT_JSON) reports.push_back(&f);
    return reports;
}

// The library's report of g with `lines` added, made in the stage at `scratch`.
std::string report_text(const eg2d_grid *g, int format, const std::string &scratch, const ReportLines &lines) {
    check(const_cast<eg2d_grid *>(g), eg2d_write(g, scratch.c_str(), format), scratch);
    std::ifstream in(scratch, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::remove(scratch.c_str());
    if (format == EG2D_FORMAT_REPORT) return text + lines.text;
    const std::size_t close = text.find_last_of('}');  // the object's end: the members go before it
    if (lines.json.empty() || close == std::string::npos || close == 0) return text;
    const std::size_t end = text.find_last_not_of(" \n", close - 1) + 1;  // after the last member
    return text.substr(0, end) + ",\n" + lines.json + text.substr(end);
}

}  // namespace

std::vector<PlannedPath> level_paths(const std::string &command, int ni, int nj, int levels, const std::string &name,
                                     const std::vector<Output> &outputs, const std::vector<std::string> &view_names) {
    std::vector<PlannedPath> paths;
    for (int level = 0; level < levels; ++level) {
        const std::string base = level_base(name, ni, nj, level);
        for (const Output &o : outputs) {
            if (!o.views) paths.push_back({base + o.extension, o.id, o.directory, command + ": --format " + o.name});
            else
                for (const std::string &v : view_names) paths.push_back({base + "-" + v + o.extension, -1, false, command});
        }
        for (const Feature *f : report_formats()) paths.push_back({base + f->extension, f->id, false, command + ": the report"});
    }
    return paths;
}

std::vector<std::string> write_levels(OutputSet &set, eg2d_grid *g, int topology, int ni, int nj, int levels,
                                      const std::string &name, const std::vector<Output> &outputs,
                                      const LevelSetup &setup, const LevelHook &each_level) {
    double span = 1.0;
    eg2d_get_parameter(g, EG2D_PARAM_SPAN, &span);
    std::vector<std::string> reports;
    for (int level = 0; level < levels; ++level) {
        const int s = 1 << level, ci = (ni - 1) / s + 1, cj = (nj - 1) / s + 1;
        const std::string base = level_base(name, ni, nj, level);
        // A path written in place is written again at the commit: its grid lives until then.
        std::shared_ptr<eg2d_grid> lg(g, [](eg2d_grid *) {});
        if (level > 0) {  // every s-th node of the finest
            std::vector<double> x(static_cast<std::size_t>(ni) * nj), y(x.size()), cx, cy;
            eg2d_get_coordinates(g, x.data(), y.data());
            for (int j = 0; j < nj; j += s)
                for (int i = 0; i < ni; i += s) {
                    cx.push_back(x[static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j]);
                    cy.push_back(y[static_cast<std::size_t>(i) + static_cast<std::size_t>(ni) * j]);
                }
            eg2d_grid *raw_coarse = nullptr;
            if (eg2d_create(ci, cj, &raw_coarse) != EG2D_OK)
                throw Failure(EXIT_MEMORY, "cannot make level " + std::to_string(level) + ": " + eg2d_last_error(nullptr));
            lg.reset(raw_coarse, GridDeleter());
            check(lg.get(), eg2d_set_topology(lg.get(), topology), "level topology");
            check(lg.get(), eg2d_set_coordinates(lg.get(), cx.data(), cy.data()), "level " + std::to_string(level));
            check(lg.get(), eg2d_set_parameter(lg.get(), EG2D_PARAM_SPAN, span), "span");
            if (setup) setup(level, lg.get(), ci, cj);
        }
        for (const Output &o : outputs)
            if (!o.views)
                set.add(base + o.extension, o.directory, [lg, o, base](const std::string &path, bool) {
                    check(lg.get(), eg2d_write(lg.get(), path.c_str(), o.id), base + o.extension);
                });
        const ReportLines lines = each_level ? each_level(level, lg.get(), base, ci, cj) : ReportLines();
        for (const Feature *f : report_formats()) {  // the reports, always
            const std::string text = report_text(lg.get(), f->id, set.staged(base + f->extension), lines);
            set.add_text(base + f->extension, text);
            if (f->id == EG2D_FORMAT_REPORT) reports.push_back(text);
        }
    }
    return reports;
}

void write_views(OutputSet &set, const eg2d_grid *g, const std::vector<Output> &outputs, const std::string &base,
                 const std::string &title, const std::function<std::vector<View>(const GridLines &)> &views) {
    bool any = false;
    for (const Output &o : outputs) any = any || o.views;
    if (!any) return;
    const GridLines lines = grid_lines(g);
    for (const View &v : views(lines)) {
        const std::vector<Polyline> shown = view_lines(lines, v);
        for (const Output &o : outputs) {
            if (!o.views) continue;
            set.add_text(base + "-" + v.name + o.extension,
                         o.name == "png" ? view_png(v, shown) : view_svg(v, shown, "eg2d " + title + ": " + v.name));
        }
    }
}

}  // namespace eg2dtool
