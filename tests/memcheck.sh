#!/usr/bin/env bash
# valgrind memcheck over every compiled test of a (non-sanitizer) build:
# ctest -T memcheck, no suppression file, and any error or definite/indirect
# leak makes valgrind exit 99, which fails that test. Script tests (label
# "script": bash running other programs) are left out; what they run is
# either a compiled test already covered here or not eg2d code.
# Usage: tests/memcheck.sh [BUILD_DIR]   (default: build, the default preset)
set -euo pipefail
build=${1:-build}
valgrind=$(command -v valgrind)
opts="--error-exitcode=99 --leak-check=full --show-leak-kinds=definite,indirect"
opts+=" --errors-for-leak-kinds=definite,indirect --track-origins=yes --num-callers=30"
rm -f "$build"/Testing/Temporary/MemoryChecker.*.log
ctest --test-dir "$build" -T memcheck -LE script --output-on-failure \
      --overwrite MemoryCheckCommand="$valgrind" \
      --overwrite MemoryCheckCommandOptions="$opts" \
      --overwrite MemoryCheckSuppressionFile=""
# ctest also counts defects it parsed from the logs; there must be none.
if grep -l "ERROR SUMMARY: [1-9]" "$build"/Testing/Temporary/MemoryChecker.*.log 2>/dev/null; then
    echo "memcheck: the logs above report errors" >&2
    exit 1
fi
echo "memcheck: clean ($(ls "$build"/Testing/Temporary/MemoryChecker.*.log | wc -l) test logs in $build/Testing/Temporary)"
