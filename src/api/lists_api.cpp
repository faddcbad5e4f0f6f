// The library's tables by name (eg2d.h, "Lists"): each list is read from its
// registry, so there is no copy here; a new registry is one line in kLists.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "api/handle.hpp"
#include "base/connectivity.hpp"
#include "base/parameters.hpp"
#include "controls/registry.hpp"
#include "geometry/distribution.hpp"
#include "grid/initializers.hpp"
#include "io/formats.hpp"
#include "operator/system.hpp"
#include "quality/quality.hpp"
#include "solvers/solver.hpp"

using namespace eg2d;
using namespace eg2d::api;

namespace {

struct Entry {
    int id;
    const char *name;
};
using Entries = std::vector<Entry>;

template <class Row>
Entries entries(Table<Row> table) {
    Entries e;
    for (const Row &r : table) e.push_back({r.id, r.name});
    std::sort(e.begin(), e.end(), [](const Entry &a, const Entry &b) { return a.id < b.id; });
    return e;
}

struct List {
    int id;
    const char *name;  // for messages
    Entries (*read)();
};

// Indexed by EG2D_LIST_*.
const List kLists[] = {
    {EG2D_LIST_SOLVERS, "EG2D_LIST_SOLVERS", [] { return entries(solver_table()); }},
    {EG2D_LIST_PARAMETERS, "EG2D_LIST_PARAMETERS", [] { return entries(parameter_table()); }},
    {EG2D_LIST_FORMATS, "EG2D_LIST_FORMATS", [] { return entries(format_table()); }},
    {EG2D_LIST_QUALITY, "EG2D_LIST_QUALITY", [] { return entries(quality_table()); }},
    {EG2D_LIST_SYSTEMS, "EG2D_LIST_SYSTEMS", [] { return entries(system_table()); }},
    {EG2D_LIST_INITIALIZERS, "EG2D_LIST_INITIALIZERS", [] { return entries(init_method_table()); }},
    {EG2D_LIST_ORTHOGONALITY, "EG2D_LIST_ORTHOGONALITY", [] { return entries(orthogonality_table()); }},
    {EG2D_LIST_TOPOLOGIES, "EG2D_LIST_TOPOLOGIES", [] { return entries(topology_table()); }},
    {EG2D_LIST_DISTRIBUTIONS, "EG2D_LIST_DISTRIBUTIONS", [] { return entries(distribution_table()); }},
    {EG2D_LIST_SET_FORMATS, "EG2D_LIST_SET_FORMATS", [] {
         const std::vector<FileFormat> f = set_formats();
         return entries(Table<FileFormat>{f.data(), f.size()});
     }},
};
constexpr int kListCount = sizeof kLists / sizeof kLists[0];

// Built once, on first use (thread-safe static initialisation); the rows are
// static, so the names live as long as the process.
const Entries *list(int id) {
    static const std::vector<Entries> all = [] {
        std::vector<Entries> v;
        for (const List &l : kLists) v.push_back(l.read());
        return v;
    }();
    return id >= 0 && id < kListCount ? &all[static_cast<std::size_t>(id)] : nullptr;
}

const Entries &checked_list(int id) {
    const Entries *e = list(id);
    if (!e) fail(Failure::Argument, format("list = %d: not one of EG2D_LIST_SOLVERS (0) .. EG2D_LIST_SET_FORMATS (%d)",
                                           id, kListCount - 1));
    return *e;
}

}  // namespace

extern "C" {

EG2D_API int eg2d_list_count(int list_id, int *count) {
    return guard_without_grid("eg2d_list_count", [&] {
        require_ptr(count, "count");
        *count = static_cast<int>(checked_list(list_id).size());
    });
}

EG2D_API int eg2d_list_entry(int list_id, int index, int *id, const char **name) {
    return guard_without_grid("eg2d_list_entry", [&] {
        const Entries &e = checked_list(list_id);
        require(index >= 0 && static_cast<std::size_t>(index) < e.size(),
                format("index = %d: %s has %zu entries (0 .. %zu)", index, kLists[list_id].name, e.size(),
                       e.size() - 1));
        if (id) *id = e[static_cast<std::size_t>(index)].id;
        if (name) *name = e[static_cast<std::size_t>(index)].name;
    });
}

EG2D_API const char *eg2d_list_name(int list_id, int id) {
    const Entries *e = list(list_id);
    if (!e) return nullptr;
    for (const Entry &x : *e)
        if (x.id == id) return x.name;
    return nullptr;
}

EG2D_API int eg2d_list_find(int list_id, const char *name, int *id) {
    return guard_without_grid("eg2d_list_find", [&] {
        require_ptr(name, "name");
        require_ptr(id, "id");
        const Entries &e = checked_list(list_id);
        std::string valid;
        for (const Entry &x : e) {
            if (!std::strcmp(x.name, name)) {
                *id = x.id;
                return;
            }
            valid += std::string(valid.empty() ? "" : ", ") + x.name;
        }
        fail(Failure::Argument, format("\"%.64s\": not in %s (one of: %s)", name, kLists[list_id].name, valid.c_str()));
    });
}

EG2D_API const char *eg2d_solver_name(int solver) { return eg2d_list_name(EG2D_LIST_SOLVERS, solver); }

EG2D_API int eg2d_parameter_bounds(int param, double *lower, double *upper, double *default_value) {
    return guard_without_grid("eg2d_parameter_bounds", [&] {
        const ParameterInfo *p = find_parameter(param);
        require(p != nullptr, format("parameter %d: no such parameter", param));
        const Settings defaults;
        if (lower) *lower = p->range.lower;
        if (upper) *upper = p->range.upper;
        if (default_value) *default_value = defaults.*(p->field);
    });
}

EG2D_API int eg2d_parameter_info(int param, int *kind, const char **unit, const char **summary) {
    return guard_without_grid("eg2d_parameter_info", [&] {
        const ParameterInfo *p = find_parameter(param);
        require(p != nullptr, format("parameter %d: no such parameter", param));
        if (kind)
            *kind = p->kind | (p->range.open_lower ? EG2D_VALUE_OPEN_LOWER : 0) |
                    (p->range.open_upper ? EG2D_VALUE_OPEN_UPPER : 0);
        if (unit) *unit = p->unit;
        if (summary) *summary = p->summary;
    });
}

EG2D_API int eg2d_format_info(int format_id, int *kind, const char **suffix) {
    return guard_without_grid("eg2d_format_info", [&] {
        const FileFormat *f = find_format(format_id);
        require(f != nullptr, format("format = %d: no such format", format_id));
        if (kind) *kind = f->write_directory ? EG2D_WRITES_DIRECTORY : EG2D_WRITES_FILE;
        if (suffix) *suffix = f->suffix;
    });
}

EG2D_API const char *eg2d_quality_cell_field(int metric) {
    const QualityMetric *m = find_quality_metric(metric);
    return m ? m->cell_field : nullptr;
}

}  // extern "C"
