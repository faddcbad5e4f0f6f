#include "base/c_locale.hpp"

#include <cstdlib>

namespace eg2d {

namespace {
// glibc gives "C" as a static object (nothing to free); made once, shared by
// all threads (a locale_t is read-only).
locale_t c_locale() {
    static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(0));
    return c;
}
}  // namespace

// Should newlocale fail, uselocale(0) only queries: the thread's locale stays.
CLocaleScope::CLocaleScope() : previous_(uselocale(c_locale())) {}

CLocaleScope::~CLocaleScope() {
    if (previous_) uselocale(previous_);
}

double strtod_c(const char *s, char **end) {
    const CLocaleScope c;
    return std::strtod(s, end);
}

}  // namespace eg2d
