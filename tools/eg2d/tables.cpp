#include "tables.hpp"

#include <eg2d.h>

#include <cstdio>

#include "features.hpp"

namespace eg2dtool {

namespace {
std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

std::string kind_text(int kind) {
    std::string s = kind & EG2D_VALUE_FLAG ? "on/off" : kind & EG2D_VALUE_INTEGER ? "integer" : "real";
    return kind & EG2D_VALUE_AUTOMATIC ? s + ", 0 automatic" : s;
}

// A list of names with their ids: "| name | EG2D id |".
std::string names_table(const char *title, const char *what, const std::vector<Feature> &rows) {
    std::string s = std::string("## ") + title + "\n\n| name | id |\n|---|---|\n";
    for (const Feature &f : rows) s += std::string("| `") + f.name + "` | " + std::to_string(f.id) + " |\n";
    return s + "\n" + what + "\n\n";
}
}  // namespace

std::string tables_markdown() {
    std::string s;
    s += "## Parameters\n\n"
         "Set with `eg2d_set_parameter` (id) or in a case file (key, in its table: `top` is the file's top level).\n\n"
         "| key | id | table | range | default | kind | unit | what |\n|---|---|---|---|---|---|---|---|\n";
    for (const Feature &p : parameters()) {
        double lo = 0, hi = 0, def = 0;
        int kind = 0;
        const char *unit = "", *summary = "";
        eg2d_parameter_bounds(p.id, &lo, &hi, &def);
        eg2d_parameter_info(p.id, &kind, &unit, &summary);
        s += std::string("| `") + p.name + "` | " + std::to_string(p.id) + " | " + p.section + " | " +
             (kind & EG2D_VALUE_OPEN_LOWER ? "(" : "[") + number(lo) + ", " + number(hi) +
             (kind & EG2D_VALUE_OPEN_UPPER ? ")" : "]") + " | " + number(def) + " | " + kind_text(kind) + " | " + unit + " | " + summary +
             " |\n";
    }
    s += "\n## Formats\n\n`[output] formats` in a case file; `eg2d_write` with the id.\n\n"
         "| name | id | file |\n|---|---|---|\n";
    for (const Feature &f : formats())
        s += std::string("| `") + f.name + "` | " + (f.id >= 0 ? std::to_string(f.id) : "the command's") + " | `NAME" +
             f.extension + "`" + (f.directory ? " (a directory)" : "") + " |\n";
    s += "\n## Quality metrics\n\n`eg2d_get_quality` with the id; the per-cell field is in .vts and .gmv files, in "
         "`eg2d_get_cell_quality` and in a case file's `[output] svg_quality`.\n\n"
         "| name | id | per-cell field |\n|---|---|---|\n";
    int n = 0;
    eg2d_list_count(EG2D_LIST_QUALITY, &n);
    for (int k = 0; k < n; ++k) {
        int id = 0;
        const char *name = "";
        eg2d_list_entry(EG2D_LIST_QUALITY, k, &id, &name);
        const char *field = eg2d_quality_cell_field(id);
        s += std::string("| `") + name + "` | " + std::to_string(id) + " | " + (field ? field : "(a summary)") + " |\n";
    }
    s += "\n";
    s += names_table("Solvers", "`[solver] method`; `eg2d_set_solver`.", solvers());
    s += names_table("Systems", "`system`; `eg2d_set_system`.", systems());
    s += names_table("Initial grids", "`initial`; `eg2d_initialize`.", initializers());
    s += names_table("Orthogonality", "`[controls] orthogonality`; `eg2d_set_orthogonality`.", orthogonality());
    s += names_table("Topologies", "`topology`; `eg2d_set_topology`.", topologies());
    s += names_table("Distributions", "a side's `distribution = {kind = ...}`; `eg2d_distribution`.", distributions());
    return s;
}

}  // namespace eg2dtool
