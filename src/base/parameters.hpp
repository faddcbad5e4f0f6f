// The table of public parameters (EG2D_PARAM_*): the one copy of their names,
// bounds, defaults (the Settings initialisers), kinds, units and summaries.
// The API, the reports, the command and its case files read it.
#pragma once
#include "base/settings.hpp"
#include "base/table.hpp"

namespace eg2d {

// An interval of allowed values; an open end excludes its bound.
struct ValueRange {
    double lower, upper;
    bool open_lower, open_upper;
};

struct ParameterInfo {
    int id;                 // EG2D_PARAM_*
    const char *name;       // "wall_growth"
    ValueRange range;
    int kind;               // EG2D_VALUE_* bits
    const char *unit;       // "1", "length", "chords", "nodes", "iterations", "sweeps"
    const char *summary;    // one line
    double Settings::*field;
};

Table<ParameterInfo> parameter_table();  // in increasing id order
const ParameterInfo *find_parameter(int id);
// Throws Argument with the parameter's name and bounds when out of range.
void check_parameter(const ParameterInfo &p, double value);
// Throws Argument when settings that depend on each other disagree
// (af_dtau_min > af_dtau_max).
void check_settings(const Settings &settings);

}  // namespace eg2d
