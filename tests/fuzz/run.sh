#!/usr/bin/env bash
# Runs every libFuzzer harness of a fuzz build for a bounded time and fails on
# any crash, sanitizer report (ASan, UBSan), leak, per-input timeout or
# out-of-memory. Seeds come from tests/fuzz/corpus/NAME (left untouched); new
# inputs go to a scratch corpus, and findings to $EG2D_FUZZ_ARTIFACTS.
#   cmake --preset fuzz && cmake --build --preset fuzz && tests/fuzz/run.sh
# Environment:
#   EG2D_FUZZ_SECONDS    time per harness (default 60)
#   EG2D_FUZZ_TIMEOUT    seconds one input may take (default 10)
#   EG2D_FUZZ_ARTIFACTS  where crash-*, leak-*, timeout-* files go (default build-fuzz/fuzz-artifacts)
#   EG2D_FUZZ_MERGE=1    afterwards merge the new coverage into the seed corpus (then commit it)
# Usage: tests/fuzz/run.sh [BUILD_DIR] [HARNESS...]   (default: build-fuzz, every harness)
set -uo pipefail
src=$(cd "$(dirname "$0")" && pwd)
build=${1:-build-fuzz}
shift || true
seconds=${EG2D_FUZZ_SECONDS:-60}
timeout=${EG2D_FUZZ_TIMEOUT:-10}
artifacts=${EG2D_FUZZ_ARTIFACTS:-$build/fuzz-artifacts}
mkdir -p "$artifacts"
if [ $# -gt 0 ]; then harnesses=("$@"); else
    harnesses=()
    for d in "$src"/corpus/*/; do harnesses+=("$(basename "$d")"); done
fi
failed=0
for name in "${harnesses[@]}"; do
    bin=$build/tests/fuzz/$name
    if [ ! -x "$bin" ]; then
        echo "fuzz: $bin is not built (cmake --preset fuzz && cmake --build --preset fuzz)"
        failed=1
        continue
    fi
    work=$(mktemp -d)
    start=$(date +%s)
    "$bin" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 -max_len=8192 -len_control=0 \
           -print_final_stats=1 -artifact_prefix="$artifacts/$name-" "$work" "$src/corpus/$name" \
           > "$artifacts/$name.log" 2>&1
    rc=$?
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$artifacts/$name.log")
    cov=$(grep -o 'cov: [0-9]*' "$artifacts/$name.log" | tail -n 1)
    if [ "$rc" -ne 0 ]; then
        echo "fuzz: FAIL $name (exit $rc after $(( $(date +%s) - start )) s); the end of its log:"
        grep -v '^#' "$artifacts/$name.log" | tail -n 40
        ls "$artifacts/$name-"* 2>/dev/null | sed 's/^/fuzz: reproduce with: '"${bin//\//\\/}"' /'
        failed=1
    else
        echo "fuzz: ok   $name: ${runs:-?} inputs in $seconds s, $cov, $(ls "$work" | wc -l) new corpus files"
        if [ "${EG2D_FUZZ_MERGE:-0}" = 1 ]; then
            # Edges only (no hit counts): a small corpus that keeps the coverage.
            "$bin" -merge=1 -use_counters=0 "$src/corpus/$name" "$work" > "$artifacts/$name-merge.log" 2>&1 &&
                echo "fuzz: merged into $src/corpus/$name ($(ls "$src/corpus/$name" | wc -l) files)"
        fi
    fi
    rm -rf "$work"
done
exit "$failed"
