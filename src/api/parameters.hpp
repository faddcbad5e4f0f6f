#pragma once
#include "base/settings.hpp"

namespace eg2d {
namespace api {

// A public parameter: its EG2D_PARAM_* id, bounds, whether it takes only
// whole numbers, whether 0 is allowed outside the bounds (as "automatic"),
// and the Settings field it sets.
struct ParameterInfo {
    int id;
    const char *name;
    double lower, upper;
    bool open_lower, open_upper;  // bounds excluded
    bool integer;
    bool zero_means_auto;
    double Settings::*field;
};

const ParameterInfo *find_parameter(int id);
// Throws Argument with the parameter's name and bounds when out of range.
void check_parameter(const ParameterInfo &p, double value);
// Throws Argument when settings that depend on each other disagree
// (af_dtau_min > af_dtau_max).
void check_settings(const Settings &settings);

}  // namespace api
}  // namespace eg2d
