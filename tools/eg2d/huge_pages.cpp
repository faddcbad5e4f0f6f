#include "huge_pages.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#if defined(__linux__)
#include <unistd.h>
#endif

namespace eg2dtool {

// Why a new process: glibc reads GLIBC_TUNABLES once, at start-up, and has no
// call that turns huge pages on later. Why at all: the machines this runs on
// take some 30 microseconds per first touch of a 4 kB page, and a grid's
// arrays are touched fresh many times over (copies, multigrid levels, ILU
// factors): 7169x2049 spent 16-27 s of its 100-145 s in page faults.
void rerun_with_huge_pages(char **argv, double nodes, bool quiet) {
#if defined(__linux__) && defined(__GLIBC__)
    const char *force = std::getenv("EG2D_HUGE_PAGES");
    if (force && !std::strcmp(force, "0")) return;  // asked, or this is the rerun
    if (!(force && !std::strcmp(force, "1")) && nodes < kHugePageNodes) return;
    const char *given = std::getenv("GLIBC_TUNABLES");
    if (given && std::strstr(given, "glibc.malloc.hugetlb")) return;  // the user's choice
    const bool had = given != nullptr;
    const std::string tunables = had ? given : "", forced = force ? force : "";
    const std::string value = (tunables.empty() ? std::string() : tunables + ":") + "glibc.malloc.hugetlb=1";
    // The rerun is told not to run again: setuid programs lose GLIBC_TUNABLES.
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0 || setenv("EG2D_HUGE_PAGES", "0", 1) != 0) return;
    if (!quiet)
        std::printf("note: running again with GLIBC_TUNABLES=%s: transparent huge pages for the grid's arrays "
                    "(%.3g M nodes; EG2D_HUGE_PAGES=0 runs without)\n", value.c_str(), nodes / 1e6);
    std::fflush(stdout);
    std::fflush(stderr);
    execv("/proc/self/exe", argv);
    const int err = errno;
    // The exec failed (no /proc): go on in this process, the tunable unused.
    if (had) setenv("GLIBC_TUNABLES", tunables.c_str(), 1);
    else unsetenv("GLIBC_TUNABLES");
    if (force) setenv("EG2D_HUGE_PAGES", forced.c_str(), 1);
    else unsetenv("EG2D_HUGE_PAGES");
    std::fprintf(stderr, "eg2d: could not run again with huge pages (%s); going on without them\n", std::strerror(err));
#else
    (void)argv;
    (void)nodes;
    (void)quiet;
#endif
}

}  // namespace eg2dtool
