#!/usr/bin/env bash
# OpenFOAM's checkMesh on every grid of eg2d_bench --internal (the graded
# wall layer, its default method): writes them as OpenFOAM cases into a
# temporary directory and prints one row per case with checkMesh's verdict,
# the failed checks other than the aspect ratio a wall layer must have, the
# largest non-orthogonality and skewness.
#   bench/internal_checkmesh.sh BUILD_DIR
# Needs checkMesh (Debian's openfoam package; WM_PROJECT_DIR is set to
# /usr/share/openfoam when unset).
set -euo pipefail
build=${1:?usage: internal_checkmesh.sh BUILD_DIR}
command -v checkMesh > /dev/null || { echo "checkMesh not found (Debian: apt-get install openfoam)" >&2; exit 2; }
export WM_PROJECT_DIR=${WM_PROJECT_DIR:-/usr/share/openfoam}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
EG2D_BENCH_WRITE=$dir "$build/bench/eg2d_bench" --internal > /dev/null
echo "| case | checkMesh | failed checks besides aspect ratio | non-orthogonality max (deg) | skewness max |"
echo "|---|---|---|---:|---:|"
for c in "$dir"/*/; do
    out=$(checkMesh -case "$c" 2>&1 || true)
    verdict=$(grep -q "Mesh OK." <<< "$out" && echo "OK" || grep -o "Failed [0-9]* mesh checks" <<< "$out" || echo "no verdict")
    others=$(grep -E "^ *\*\*\*" <<< "$out" | grep -v "High aspect ratio" | sed 's/^ *\*\*\*//' | tr '\n' ';' || true)
    nonorth=$(sed -n 's/.*Mesh non-orthogonality Max: \([0-9.eE+-]*\).*/\1/p' <<< "$out")
    skew=$(sed -n 's/.*Max skewness = \([0-9.eE+-]*\).*/\1/p' <<< "$out")
    echo "| $(basename "$c") | $verdict | ${others:-none} | $nonorth | $skew |"
done
