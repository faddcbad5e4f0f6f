#include "features.hpp"

#include <eg2d.h>

#include "view_picture.hpp"

namespace eg2dtool {

// A feature whose constant is not in this header is listed with available = false.
#define EG2D_FEATURE(name, macro) {name, macro, true}
#define EG2D_MISSING(name) {name, -1, false}

const std::vector<Feature> &solvers() {
    // Read from the library's registry (src/solvers/registry.cpp): every
    // solver id (0-99, eg2d_set_solver) that eg2d_solver_name knows, by that
    // name, in id order. A new solver needs no line here.
    static const std::vector<Feature> t = [] {
        std::vector<Feature> v;
        for (int id = 0; id <= 99; ++id)
            if (const char *name = eg2d_solver_name(id)) v.push_back({name, id, true});
        return v;
    }();
    return t;
}

// A parameter whose id is not in this header is listed as not available.
// EG2D_FLAG: an on/off setting, written true/false in a case file (1/0 too).
#define EG2D_PARAM(name, macro, section) {name, macro, true, "", section}
#define EG2D_FLAG(name, macro, section) {name, macro, true, "", section, true}
#define EG2D_NO_PARAM(name, section) {name, -1, false, "", section}

const std::vector<Feature> &parameters() {
    static const std::vector<Feature> t = {
        EG2D_PARAM("relaxation", EG2D_PARAM_RELAXATION, "solver"),
        EG2D_PARAM("tolerance", EG2D_PARAM_TOLERANCE, "solver"),
        EG2D_PARAM("max_iterations", EG2D_PARAM_MAX_ITERATIONS, "solver"),
        EG2D_PARAM("divergence_factor", EG2D_PARAM_DIVERGENCE_FACTOR, "solver"),
        EG2D_FLAG("fold_check", EG2D_PARAM_FOLD_CHECK, "solver"),
        EG2D_PARAM("stall_iterations", EG2D_PARAM_STALL_ITERATIONS, "solver"),
        EG2D_FLAG("monitor_set_up", EG2D_PARAM_MONITOR_SET_UP, "solver"),
#ifdef EG2D_PARAM_AF_DTAU_MIN
        EG2D_PARAM("af_dtau_min", EG2D_PARAM_AF_DTAU_MIN, "solver"),
        EG2D_PARAM("af_dtau_max", EG2D_PARAM_AF_DTAU_MAX, "solver"),
        EG2D_PARAM("af_steps", EG2D_PARAM_AF_STEPS, "solver"),
        EG2D_PARAM("af_a", EG2D_PARAM_AF_A, "solver"),
        EG2D_PARAM("af_b", EG2D_PARAM_AF_B, "solver"),
        EG2D_PARAM("af_relaxation", EG2D_PARAM_AF_RELAXATION, "solver"),
#else
        EG2D_NO_PARAM("af_dtau_min", "solver"), EG2D_NO_PARAM("af_dtau_max", "solver"),
        EG2D_NO_PARAM("af_steps", "solver"), EG2D_NO_PARAM("af_a", "solver"), EG2D_NO_PARAM("af_b", "solver"),
        EG2D_NO_PARAM("af_relaxation", "solver"),
#endif
#ifdef EG2D_PARAM_MG_CYCLE
        EG2D_PARAM("mg_cycle", EG2D_PARAM_MG_CYCLE, "solver"),
        EG2D_PARAM("mg_pre_smooth", EG2D_PARAM_MG_PRE_SMOOTH, "solver"),
        EG2D_PARAM("mg_post_smooth", EG2D_PARAM_MG_POST_SMOOTH, "solver"),
        EG2D_FLAG("mg_fmg", EG2D_PARAM_MG_FMG, "solver"),
        EG2D_PARAM("mg_coarsest", EG2D_PARAM_MG_COARSEST, "solver"),
#else
        EG2D_NO_PARAM("mg_cycle", "solver"), EG2D_NO_PARAM("mg_pre_smooth", "solver"),
        EG2D_NO_PARAM("mg_post_smooth", "solver"), EG2D_NO_PARAM("mg_fmg", "solver"),
        EG2D_NO_PARAM("mg_coarsest", "solver"),
#endif
#ifdef EG2D_PARAM_WALL_DECAY
        EG2D_PARAM("wall_decay", EG2D_PARAM_WALL_DECAY, "controls"),
        EG2D_PARAM("wall_relaxation", EG2D_PARAM_WALL_RELAXATION, "controls"),
#else
        EG2D_NO_PARAM("wall_decay", "controls"), EG2D_NO_PARAM("wall_relaxation", "controls"),
#endif
#ifdef EG2D_PARAM_WALL_LAYER
        EG2D_PARAM("wall_layer", EG2D_PARAM_WALL_LAYER, "controls"),
        EG2D_PARAM("wall_growth", EG2D_PARAM_WALL_GROWTH, "controls"),
#else
        EG2D_NO_PARAM("wall_layer", "controls"), EG2D_NO_PARAM("wall_growth", "controls"),
#endif
#ifdef EG2D_PARAM_VARIATIONAL_SMOOTHNESS
        EG2D_PARAM("variational_smoothness", EG2D_PARAM_VARIATIONAL_SMOOTHNESS, "top"),
        EG2D_PARAM("variational_orthogonality_form", EG2D_PARAM_VARIATIONAL_ORTHOGONALITY_FORM, "top"),
#else
        EG2D_NO_PARAM("variational_smoothness", "top"), EG2D_NO_PARAM("variational_orthogonality_form", "top"),
#endif
#ifdef EG2D_PARAM_VARIATIONAL_AREA
        // spacing last: the only weight not 0 by default, so a case may zero it
        // (the library refuses a setting that leaves all the weights 0)
        EG2D_PARAM("variational_area", EG2D_PARAM_VARIATIONAL_AREA, "top"),
        EG2D_PARAM("variational_orthogonality", EG2D_PARAM_VARIATIONAL_ORTHOGONALITY, "top"),
        EG2D_PARAM("variational_spacing", EG2D_PARAM_VARIATIONAL_SPACING, "top"),
#else
        EG2D_NO_PARAM("variational_area", "top"), EG2D_NO_PARAM("variational_orthogonality", "top"),
        EG2D_NO_PARAM("variational_spacing", "top"),
#endif
#ifdef EG2D_PARAM_HERMITE_SPACING
        EG2D_PARAM("hermite_spacing", EG2D_PARAM_HERMITE_SPACING, "top"),
#else
        EG2D_NO_PARAM("hermite_spacing", "top"),
#endif
#ifdef EG2D_PARAM_HERMITE_SIDES
        EG2D_PARAM("hermite_sides", EG2D_PARAM_HERMITE_SIDES, "top"),
        EG2D_PARAM("hermite_height_jmin", EG2D_PARAM_HERMITE_HEIGHT_JMIN, "top"),
        EG2D_PARAM("hermite_height_imax", EG2D_PARAM_HERMITE_HEIGHT_IMAX, "top"),
        EG2D_PARAM("hermite_height_jmax", EG2D_PARAM_HERMITE_HEIGHT_JMAX, "top"),
        EG2D_PARAM("hermite_height_imin", EG2D_PARAM_HERMITE_HEIGHT_IMIN, "top"),
#else
        EG2D_NO_PARAM("hermite_sides", "top"), EG2D_NO_PARAM("hermite_height_jmin", "top"),
        EG2D_NO_PARAM("hermite_height_imax", "top"), EG2D_NO_PARAM("hermite_height_jmax", "top"),
        EG2D_NO_PARAM("hermite_height_imin", "top"),
#endif
    };
    return t;
}

const std::vector<Feature> &orthogonality() {
    static const std::vector<Feature> t = {
#ifdef EG2D_ORTHO_NONE
        EG2D_FEATURE("none", EG2D_ORTHO_NONE),
        EG2D_FEATURE("middlecoff-thomas", EG2D_ORTHO_MIDDLECOFF_THOMAS),
        EG2D_FEATURE("wall", EG2D_ORTHO_WALL),
#else
        EG2D_MISSING("none"), EG2D_MISSING("middlecoff-thomas"), EG2D_MISSING("wall"),
#endif
    };
    return t;
}

const std::vector<Feature> &controls() {
    static const std::vector<Feature> t = {
#ifdef EG2D_XI
        {"line_source", 0, true}, {"point_source", 0, true}, {"source_arrays", 0, true},
        {"parameter_grid", 0, true}, {"weight", 0, true},
#else
        {"line_source", 0, false}, {"point_source", 0, false}, {"source_arrays", 0, false},
        {"parameter_grid", 0, false}, {"weight", 0, false},
#endif
#ifdef EG2D_ORTHO_WALL
        {"wall_spacing", 0, true},
#else
        {"wall_spacing", 0, false},
#endif
    };
    return t;
}

const std::vector<Feature> &geometry() {
#ifdef EG2D_DIST_VINOKUR
    static const std::vector<Feature> t = {{"curves", 0, true}};
#else
    static const std::vector<Feature> t = {{"curves", 0, false}};
#endif
    return t;
}

const std::vector<Feature> &formats() {
    static const std::vector<Feature> t = {
        {"plot3d", EG2D_FORMAT_PLOT3D, true, ".xyz"},
        {"plot3d-ascii", EG2D_FORMAT_PLOT3D_ASCII, true, ".p3d"},
        {"vts", EG2D_FORMAT_VTS, true, ".vts"},
        {"cgns", EG2D_FORMAT_CGNS, true, ".cgns"},
        {"gmv", EG2D_FORMAT_GMV, true, ".gmv"},
        {"matlab", EG2D_FORMAT_MATLAB, true, ".m"},
        {"svg", EG2D_FORMAT_SVG, true, ".svg"},
        {"su2", EG2D_FORMAT_SU2, true, ".su2"},
        {"openfoam", EG2D_FORMAT_OPENFOAM, true, "_foam", "", false, true},
        {"report", EG2D_FORMAT_REPORT, true, ".report.txt"},
        {"report-json", EG2D_FORMAT_REPORT_JSON, true, ".report.json"},
        // written by the command (run_files.hpp): the run's history and the control functions
        {"history", -1, true, ".history.csv", "", false, false, kHistoryCsv},
        {"history-svg", -1, true, ".history.svg", "", false, false, kHistorySvg},
        {"controls", -1, true, ".controls.csv", "", false, false, kControlsCsv},
        // the whole grid as a PNG picture, drawn by the command with cairo where the build has it
        {"png", -1, png_available(), ".png", "", false, false, kGridPng},
    };
    return t;
}

const std::vector<Feature> &cell_metrics() {
    // The library's per-cell EG2D_QUALITY_* metrics, by the names of its
    // quality table (src/quality/quality.cpp, also the .vts/.gmv field names).
    static const std::vector<Feature> t = {
        {"folded", EG2D_QUALITY_FOLDED_CELLS, true},      {"area", EG2D_QUALITY_MIN_AREA, true},
        {"skewness", EG2D_QUALITY_SKEWNESS, true},         {"aspect_ratio", EG2D_QUALITY_ASPECT_RATIO, true},
        {"smoothness_i", EG2D_QUALITY_SMOOTHNESS_I, true}, {"smoothness_j", EG2D_QUALITY_SMOOTHNESS_J, true}};
    return t;
}

const std::vector<Feature> &systems() {
#ifdef EG2D_SYSTEM_VARIATIONAL
    static const std::vector<Feature> t = {EG2D_FEATURE("laplace", EG2D_SYSTEM_LAPLACE),
                                           EG2D_FEATURE("winslow", EG2D_SYSTEM_WINSLOW),
                                           EG2D_FEATURE("variational", EG2D_SYSTEM_VARIATIONAL)};
#else
    static const std::vector<Feature> t = {EG2D_FEATURE("laplace", EG2D_SYSTEM_LAPLACE),
                                           EG2D_FEATURE("winslow", EG2D_SYSTEM_WINSLOW),
                                           EG2D_MISSING("variational")};
#endif
    return t;
}

const std::vector<Feature> &topologies() {
    // Asked of the library: a topology it reserves but lacks is EG2D_ERR_UNSUPPORTED.
    static const std::vector<Feature> t = [] {
        std::vector<Feature> v = {{"single", EG2D_TOPO_SINGLE, true}, {"o", EG2D_TOPO_O, true}, {"c", EG2D_TOPO_C, true}};
        eg2d_grid *g = nullptr;
        if (eg2d_create(9, 9, &g) == EG2D_OK)
            for (auto &f : v) f.available = eg2d_set_topology(g, f.id) == EG2D_OK;
        eg2d_destroy(g);
        return v;
    }();
    return t;
}

const std::vector<Feature> &initializers() {
#ifdef EG2D_INIT_HERMITE
    static const std::vector<Feature> t = {EG2D_FEATURE("tfi", EG2D_INIT_TFI), EG2D_FEATURE("hermite", EG2D_INIT_HERMITE)};
#else
    static const std::vector<Feature> t = {EG2D_FEATURE("tfi", EG2D_INIT_TFI), EG2D_MISSING("hermite")};
#endif
    return t;
}

std::vector<std::string> names(const std::vector<Feature> &table) {
    std::vector<std::string> v;
    for (const auto &f : table) v.push_back(f.name);
    return v;
}

}  // namespace eg2dtool
