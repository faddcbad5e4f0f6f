// EG2D_FORMAT_REPORT (text) and EG2D_FORMAT_REPORT_JSON: the numbers a flow
// solver's user checks before a run, one file per grid, after Construct2D's
// stats file (Prosser's Construct2D): sizes, the wall's first cells (height, growth
// away from it, the angle the grid lines leave it at), the worst cells, and
// what the run took.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "base/folds.hpp"
#include "base/parameters.hpp"
#include "base/polyline.hpp"
#include "eg2d.h"
#include "io/formats.hpp"
#include "io/unstructured.hpp"
#include "quality/quality.hpp"
#include "quality/wall_layer_stats.hpp"

namespace eg2d {

namespace {

struct Range {
    double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity(), sum = 0;
    int n = 0;
    void add(double v) {
        min = std::min(min, v);
        max = std::max(max, v);
        sum += v;
        ++n;
    }
    double mean() const { return n ? sum / n : 0.0; }
};

struct WallStats {
    int nodes = 0;  // wall nodes measured (stretch ends and corners excluded)
    int rows = 0;   // rows of the wall layer the growth is taken over
    Range height, growth, angle;
    std::vector<std::string> stretches;  // "name: SIDE first..last"
};

struct Report {
    int ni, nj, cells, points;
    const char *topology;
    WallStats wall;
    double skewness, aspect_ratio, min_area;
    long folded;
    const RunSummary *run;
};

double metric(const Grid &g, int id) { return find_quality_metric(id)->summary(g); }

// The wall stretches (patches of type wall): at each node but a stretch's
// two ends and its corners with the nodes beside them (a trailing edge, a
// blunt base's corners, where the tangent is not defined), the first-cell
// height normal to the wall, the growth of the spacing along the line
// leaving it, and that line's deviation from the wall normal.
WallStats wall_stats(const Grid &g) {
    WallStats w;
    // The wall layer: the rows held by a marched layer, else the first third.
    w.rows = g.held_rows() > 0 ? g.held_rows() + 1 : std::max(2, (g.nj() - 1) / 3);
    w.rows = std::min(w.rows, g.nj() - 1);
    for (const Patch &p : resolve_patches(g)) {
        if (p.type != PatchType::Wall) continue;
        w.stretches.push_back(format("%s: %s %d..%d", p.name.c_str(), side_name(p.side), p.first, p.last));
        for (const WallNodeStats &n : wall_stretch_stats(g, p.side, p.first, p.last, w.rows)) {
            ++w.nodes;
            w.height.add(n.height);
            w.angle.add(n.angle);
            if (w.rows >= 2) w.growth.add(n.growth);
        }
    }
    return w;
}

Report make_report(const WriteRequest &r) {
    const Grid &g = r.grid;
    const UnstructuredMesh m = unstructured_mesh(g);
    // One fold summary for the smallest area and the folded cells (the
    // metrics' each make their own).
    const FoldSummary folds = fold_summary(g);
    Report rep{g.ni(), g.nj(), static_cast<int>(m.cells()), static_cast<int>(m.points()),
               topology_name(g.topology()), wall_stats(g), metric(g, EG2D_QUALITY_SKEWNESS),
               metric(g, EG2D_QUALITY_ASPECT_RATIO), folds.min_area, folds.folded, r.run};
    return rep;
}

// JSON has no infinity or NaN: a value that is not finite is null.
std::string json_number(double v) { return std::isfinite(v) ? format("%.17g", v) : "null"; }

std::string json_string(const std::string &s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}
}  // namespace

void write_report(const WriteRequest &r, OutputFile &out) {
    const Report rep = make_report(r);
    out.print("eg2d grid report\n");
    out.print("grid            %d x %d nodes, %s: %d cells, %d points (a cut's duplicates merged)\n", rep.ni, rep.nj,
              rep.topology, rep.cells, rep.points);
    if (rep.run)
        out.print("run             %s, %d iterations (one multigrid cycle each), residual %.3e, %.3f s\n",
                  rep.run->solver, rep.run->iterations, rep.run->residual, rep.run->seconds);
    const WallStats &w = rep.wall;
    if (w.nodes == 0) {
        out.print("wall            none (no patch of type wall with inner nodes)\n");
    } else {
        for (const std::string &s : w.stretches) out.print("wall            %s\n", s.c_str());
        out.print("first cell      height normal to the wall min %.4e, max %.4e, mean %.4e (%d nodes, stretch "
                  "ends and corners excluded)\n",
                  w.height.min, w.height.max, w.height.mean(), w.nodes);
        if (w.growth.n)
            out.print("wall growth     largest ratio of consecutive spacings off the wall %.4f (rows 1..%d)\n",
                      w.growth.max, w.rows);
        out.print("wall angle      deviation of the first line from the wall normal max %.3f, mean %.3f deg\n",
                  w.angle.max, w.angle.mean());
    }
    const Settings defaults;
    std::string changed;  // the parameters set away from their defaults, by the names of the table
    for (const ParameterInfo &q : parameter_table())
        if (r.settings.*(q.field) != defaults.*(q.field))
            changed += format("%s%s = %.17g", changed.empty() ? "" : ", ", q.name, r.settings.*(q.field));
    out.print("parameters      %s\n", changed.empty() ? "all at their defaults" : changed.c_str());
    out.print("skewness        largest %.3f deg (corner angle from 90)\n", rep.skewness);
    out.print("aspect ratio    largest %.4g\n", rep.aspect_ratio);
    out.print("cell area       smallest %.4e\n", rep.min_area);
    out.print("folded cells    %ld\n", rep.folded);
}

void write_report_json(const WriteRequest &r, OutputFile &out) {
    const Report rep = make_report(r);
    out.print("{\n  \"ni\": %d,\n  \"nj\": %d,\n  \"topology\": \"%s\",\n  \"cells\": %d,\n  \"points\": %d,\n",
              rep.ni, rep.nj, rep.topology, rep.cells, rep.points);
    if (rep.run)
        out.print("  \"run\": {\"solver\": \"%s\", \"iterations\": %d, \"residual\": %s, \"seconds\": %s},\n",
                  rep.run->solver, rep.run->iterations, json_number(rep.run->residual).c_str(),
                  json_number(rep.run->seconds).c_str());
    else
        out.print("  \"run\": null,\n");
    const WallStats &w = rep.wall;
    if (w.nodes == 0) {
        out.print("  \"wall\": null,\n");
    } else {
        out.print("  \"wall\": {\n    \"stretches\": [");
        for (std::size_t k = 0; k < w.stretches.size(); ++k)
            out.print("%s%s", k ? ", " : "", json_string(w.stretches[k]).c_str());
        out.print("],\n    \"nodes\": %d,\n", w.nodes);
        out.print("    \"first_cell_height\": {\"min\": %s, \"max\": %s, \"mean\": %s},\n",
                  json_number(w.height.min).c_str(), json_number(w.height.max).c_str(),
                  json_number(w.height.mean()).c_str());
        out.print("    \"growth_rows\": %d,\n    \"growth_max\": %s,\n", w.rows,
                  w.growth.n ? json_number(w.growth.max).c_str() : "null");
        out.print("    \"angle_deviation_deg\": {\"max\": %s, \"mean\": %s}\n  },\n", json_number(w.angle.max).c_str(),
                  json_number(w.angle.mean()).c_str());
    }
    out.print("  \"parameters\": {");  // every one, by the names of the table
    bool first = true;
    for (const ParameterInfo &q : parameter_table()) {
        out.print("%s\n    \"%s\": %s", first ? "" : ",", q.name, json_number(r.settings.*(q.field)).c_str());
        first = false;
    }
    out.print("\n  },\n");
    out.print("  \"skewness_max_deg\": %s,\n  \"aspect_ratio_max\": %s,\n  \"area_min\": %s,\n  \"folded_cells\": %ld\n}\n",
              json_number(rep.skewness).c_str(), json_number(rep.aspect_ratio).c_str(),
              json_number(rep.min_area).c_str(), rep.folded);
}

}  // namespace eg2d
