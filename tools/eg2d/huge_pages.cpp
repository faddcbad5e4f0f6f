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
    if (force && !std::strcmp(force, "0")) return;
    if (!(force && !std::strcmp(force, "1")) && nodes < kHugePageNodes) return;
    const char *tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) return;  // the user's choice, or this is the rerun
    const std::string value =
        (tunables && *tunables ? std::string(tunables) + ":" : std::string()) + "glibc.malloc.hugetlb=1";
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
    if (!quiet)
        std::printf("note: running again with GLIBC_TUNABLES=%s: transparent huge pages for the grid's arrays "
                    "(%.3g M nodes; EG2D_HUGE_PAGES=0 runs without)\n", value.c_str(), nodes / 1e6);
    std::fflush(stdout);
    std::fflush(stderr);
    execv("/proc/self/exe", argv);
    // The exec failed (no /proc): go on in this process, the tunable unused.
    if (tunables) setenv("GLIBC_TUNABLES", tunables, 1);
    else unsetenv("GLIBC_TUNABLES");
    if (!quiet) std::printf("note: could not run again (%s); going on without huge pages\n", std::strerror(errno));
#else
    (void)argv;
    (void)nodes;
    (void)quiet;
#endif
}

}  // namespace eg2dtool
