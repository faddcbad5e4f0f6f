#pragma once
// Number text in the "C" locale whatever the host's setlocale says: files
// and messages hold 0.5, never 0,5 (a GTK or Qt host runs under its user's
// locale). uselocale switches only the calling thread, and only for the
// scope's life, so the library never touches the process's locale.

#include <locale.h>

namespace eg2d {

class CLocaleScope {
public:
    CLocaleScope();
    ~CLocaleScope();
    CLocaleScope(const CLocaleScope &) = delete;
    CLocaleScope &operator=(const CLocaleScope &) = delete;

private:
    locale_t previous_;
};

// std::strtod read in the "C" locale.
double strtod_c(const char *s, char **end);

}  // namespace eg2d
