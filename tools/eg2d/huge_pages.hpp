// Transparent huge pages for a large grid's arrays: the command runs itself
// again with glibc's malloc asked to back its large blocks with 2 MB pages.
#pragma once

namespace eg2dtool {

// With `nodes` at or above kHugePageNodes (or EG2D_HUGE_PAGES=1), on Linux
// with glibc, and GLIBC_TUNABLES not already naming glibc.malloc.hugetlb:
// says so on stdout (unless quiet) and replaces the process with the same
// command (argv as main got it) under GLIBC_TUNABLES=...:glibc.malloc.hugetlb=1
// and EG2D_HUGE_PAGES=0. Returns when it does nothing, or when the exec fails
// (said on stderr; the run goes on as it is). EG2D_HUGE_PAGES=0 turns it off.
void rerun_with_huge_pages(char **argv, double nodes, bool quiet);

// 2^18 nodes (513x513). Measured above it (bench/RESULTS.md): the C-grid
// 7169x2049 in 48 s with them against 85 s without; 1793x513 (0.9 M nodes)
// in 6.2-6.4 s against 7.3-8.5 s.
constexpr double kHugePageNodes = 262144.0;

}  // namespace eg2dtool
