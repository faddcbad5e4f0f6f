#include "features.hpp"

#include <eg2d.h>

#include "view_picture.hpp"

namespace eg2dtool {

namespace {
// A list of the library's (eg2d_list_*), by its names: the command keeps no
// copy. `describe` adds what the command needs of each entry.
std::vector<Feature> library_list(int list, void (*describe)(Feature &) = nullptr) {
    std::vector<Feature> v;
    int n = 0;
    eg2d_list_count(list, &n);
    for (int k = 0; k < n; ++k) {
        Feature f{"", 0, true};
        if (eg2d_list_entry(list, k, &f.id, &f.name) != EG2D_OK) continue;
        if (describe) describe(f);
        v.push_back(f);
    }
    return v;
}

// A list read once, on first use.
template <int List>
const std::vector<Feature> &listed() {
    static const std::vector<Feature> t = library_list(List);
    return t;
}

const char *section_of(int id) {
    if (id < 10 || (id >= 100 && id < 200)) return "solver";
    if (id >= 200 && id < 300) return "controls";
    if (id >= 300 && id < 400) return "output";
    return "top";
}
}  // namespace

const std::vector<Feature> &solvers() { return listed<EG2D_LIST_SOLVERS>(); }

const std::vector<Feature> &parameters() {
    static const std::vector<Feature> t = library_list(EG2D_LIST_PARAMETERS, [](Feature &f) {
        int kind = 0;
        eg2d_parameter_info(f.id, &kind, nullptr, nullptr);
        f.section = section_of(f.id);
        f.flag = (kind & EG2D_VALUE_FLAG) != 0;
    });
    return t;
}

const std::vector<Feature> &orthogonality() { return listed<EG2D_LIST_ORTHOGONALITY>(); }

const std::vector<Feature> &controls() {
    // The command's own [controls] keys (case_file.cpp reads each).
    static const std::vector<Feature> t = {{"line_source", 0, true},    {"point_source", 0, true},
                                           {"source_arrays", 0, true},  {"parameter_grid", 0, true},
                                           {"weight", 0, true},         {"wall_spacing", 0, true}};
    return t;
}

const std::vector<Feature> &geometry() {
    static const std::vector<Feature> t = {{"curves", 0, true}};
    return t;
}

const std::vector<Feature> &distributions() { return listed<EG2D_LIST_DISTRIBUTIONS>(); }

const std::vector<Feature> &set_formats() { return listed<EG2D_LIST_SET_FORMATS>(); }

const std::vector<Feature> &formats() {
    static const std::vector<Feature> t = [] {
        std::vector<Feature> v = library_list(EG2D_LIST_FORMATS, [](Feature &f) {
            int kind = 0;
            eg2d_format_info(f.id, &kind, &f.extension);
            f.directory = kind == EG2D_WRITES_DIRECTORY;
        });
        // written by the command (run_files.hpp): the run's history and the control functions
        v.push_back({"history", -1, true, ".history.csv", "", false, false, kHistoryCsv});
        v.push_back({"history-svg", -1, true, ".history.svg", "", false, false, kHistorySvg});
        v.push_back({"controls", -1, true, ".controls.csv", "", false, false, kControlsCsv});
        // the whole grid as a PNG picture, drawn by the command with cairo where the build has it
        v.push_back({"png", -1, png_available(), ".png", "", false, false, kGridPng});
        return v;
    }();
    return t;
}

const std::vector<Feature> &cell_metrics() {
    // The library's quality metrics that have per-cell values, by their
    // field names (as in .vts and .gmv files), each once.
    static const std::vector<Feature> t = [] {
        std::vector<Feature> v;
        for (const Feature &m : library_list(EG2D_LIST_QUALITY)) {
            const char *field = eg2d_quality_cell_field(m.id);
            bool seen = false;
            for (const Feature &f : v) seen = seen || (field && std::string(field) == f.name);
            if (field && !seen) v.push_back({field, m.id, true});
        }
        return v;
    }();
    return t;
}

const std::vector<Feature> &systems() { return listed<EG2D_LIST_SYSTEMS>(); }

const std::vector<Feature> &topologies() {
    // Asked of the library: a topology it reserves but lacks is EG2D_ERR_UNSUPPORTED.
    static const std::vector<Feature> t = [] {
        std::vector<Feature> v = library_list(EG2D_LIST_TOPOLOGIES);
        eg2d_grid *g = nullptr;
        if (eg2d_create(9, 9, &g) == EG2D_OK)
            for (auto &f : v) f.available = eg2d_set_topology(g, f.id) == EG2D_OK;
        eg2d_destroy(g);
        return v;
    }();
    return t;
}

const std::vector<Feature> &initializers() { return listed<EG2D_LIST_INITIALIZERS>(); }

std::vector<std::string> names(const std::vector<Feature> &table) {
    std::vector<std::string> v;
    for (const auto &f : table) v.push_back(f.name);
    return v;
}

}  // namespace eg2dtool
