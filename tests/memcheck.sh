#!/usr/bin/env bash
# valgrind memcheck over every compiled test of a (non-sanitizer) build:
# ctest -T memcheck, suppressing only the third-party defects listed (with
# their evidence) in tests/memcheck.supp, and any error or definite/indirect
# leak makes valgrind exit 99, which fails that test. The tests are those whose
# program was built in BUILD_DIR (found from ctest's JSON): tests that run
# bash, cmake or python are left out, as what they run is either a compiled
# test covered here or not eg2d code.
# Usage: tests/memcheck.sh [BUILD_DIR]   (default: build, the default preset)
set -euo pipefail
build=${1:-build}
valgrind=$(command -v valgrind)
opts="--error-exitcode=99 --leak-check=full --show-leak-kinds=definite,indirect"
opts+=" --errors-for-leak-kinds=definite,indirect --track-origins=yes --num-callers=30"
compiled=$(ctest --test-dir "$build" --show-only=json-v1 | python3 -c '
import json, os, re, sys
build = os.path.realpath(sys.argv[1])
tests = json.load(sys.stdin)["tests"]
# bench_quick is a timing run (its 120 s limit is for native speed), not a test of memory.
print("|".join(re.escape(t["name"]) for t in tests
               if os.path.realpath(t.get("command", [""])[0]).startswith(build + os.sep)
               and t["name"] != "bench_quick"))' "$build")
rm -f "$build"/Testing/Temporary/MemoryChecker.*.log
# Two at a time by default (EG2D_MEMCHECK_JOBS): valgrind runs one thread.
ctest --test-dir "$build" -T memcheck -R "^($compiled)\$" --output-on-failure -j "${EG2D_MEMCHECK_JOBS:-2}" \
      --overwrite MemoryCheckCommand="$valgrind" \
      --overwrite MemoryCheckCommandOptions="$opts" \
      --overwrite MemoryCheckSuppressionFile="$(cd "$(dirname "$0")" && pwd)/memcheck.supp"
# ctest also counts defects it parsed from the logs; there must be none.
if grep -l "ERROR SUMMARY: [1-9]" "$build"/Testing/Temporary/MemoryChecker.*.log 2>/dev/null; then
    echo "memcheck: the logs above report errors" >&2
    exit 1
fi
echo "memcheck: clean ($(ls "$build"/Testing/Temporary/MemoryChecker.*.log | wc -l) test logs in $build/Testing/Temporary)"
