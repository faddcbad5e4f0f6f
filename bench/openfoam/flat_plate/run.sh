#!/bin/sh
# TMR's 2-D flat plate through OpenFOAM's simpleFoam with Spalart-Allmaras on two
# 137x97 grids: eg2d's (flat_plate.toml: TMR's boundary, eg2d's interior) and
# TMR's own (flatplate_clust2_2levelsdown_137x97.p2dfmt), both written by
# libeg2d's OpenFOAM writer. Prints Cf at x = 0.97 against TMR's grid-converged
# SA value 0.002706 (bench/RESULTS.md, "OpenFOAM: TMR flat plate").
#
#     run.sh BUILD_DIR TMR_GRID_FILE [WORK_DIR]
#
# BUILD_DIR: a build of eg2d (tools/eg2d/eg2d, src/libeg2d.so). TMR_GRID_FILE:
# NASA TMR's FlatPlate/Grids/flatplate_clust2_2levelsdown_137x97.p2dfmt (plot3d
# 2-D ASCII). WORK_DIR (default BUILD_DIR/openfoam_flat_plate) is emptied.
# Needs OpenFOAM (v1912 from Debian: simpleFoam, checkMesh), cc and python3.
# Environment: CHUNK (500) iterations between Cf checks; the run stops when Cf
# at x = 0.97 moves less than 0.1% over a chunk, after MIN_ITER (3000), or at
# MAX_ITER (30000). The two cases run at the same time.
set -eu
if [ $# -lt 2 ]; then
    echo "usage: run.sh BUILD_DIR TMR_GRID_FILE [WORK_DIR]" >&2
    exit 2
fi
BUILD=$(cd "$1" && pwd)
GRID=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
HERE=$(cd "$(dirname "$0")" && pwd)
SRC=$(cd "$HERE/../../.." && pwd)
WORK=${3:-$BUILD/openfoam_flat_plate}
CHUNK=${CHUNK:-500}
MIN_ITER=${MIN_ITER:-3000}
MAX_ITER=${MAX_ITER:-30000}
CF_TMR=0.002706
# Debian's OpenFOAM finds its etc/ through WM_PROJECT_DIR
if [ -z "${WM_PROJECT_DIR:-}" ] && [ -d /usr/share/openfoam/etc ]; then
    export WM_PROJECT_DIR=/usr/share/openfoam
fi
for tool in simpleFoam checkMesh cc python3; do
    command -v $tool >/dev/null || { echo "run.sh: $tool not found" >&2; exit 1; }
done

rm -rf "$WORK"
mkdir -p "$WORK"

# eg2d's grid: the case file's OpenFOAM writer makes WORK/eg2d/flat_plate_foam
"$BUILD/tools/eg2d/eg2d" run "$HERE/flat_plate.toml" -o "$WORK/eg2d" > "$WORK/eg2d.log" 2>&1 ||
    { cat "$WORK/eg2d.log" >&2; echo "run.sh: eg2d run failed" >&2; exit 1; }
mv "$WORK/eg2d/flat_plate_foam" "$WORK/case_eg2d"

# TMR's grid through the same writer
cc -O2 -o "$WORK/p2d_to_foam" "$HERE/p2d_to_foam.c" -I"$SRC/include" -L"$BUILD/src" -leg2d -Wl,-rpath,"$BUILD/src"
"$WORK/p2d_to_foam" "$GRID" "$WORK/case_tmr" > "$WORK/p2d_to_foam.log"

# one case: the dictionaries, checkMesh, simpleFoam CHUNK iterations at a time
run_case() {
    c=$WORK/case_$1
    cp -r "$HERE/case/0" "$HERE/case/constant" "$HERE/case/system" "$c/"
    checkMesh -case "$c" > "$c/log.checkMesh" 2>&1 || true
    start=$(date +%s)
    it=0
    prev=
    : > "$c/cf_history.txt"
    status=converged
    while :; do
        next=$((it + CHUNK))
        sed -i "s/^endTime .*/endTime         $next;/" "$c/system/controlDict"
        if ! simpleFoam -case "$c" >> "$c/log.simpleFoam" 2>&1; then
            status="simpleFoam failed after iteration $it (log.simpleFoam)"
            break
        fi
        if [ "$it" -gt 0 ]; then
            rm -rf "${c:?}/$it"            # keep 0 and the latest time
        fi
        it=$next
        cf=$(python3 "$HERE/cf.py" "$c" "$it")
        echo "$it $cf" >> "$c/cf_history.txt"
        if [ -n "$prev" ] && [ "$it" -ge "$MIN_ITER" ] &&
            python3 -c "import sys; sys.exit(abs($cf - $prev) >= 1e-3 * abs($prev))"; then
            break
        fi
        if [ "$it" -ge "$MAX_ITER" ]; then
            status="not converged: Cf moved more than 0.1% over the last $CHUNK iterations"
            break
        fi
        prev=$cf
    done
    echo "$it $(($(date +%s) - start)) $status" > "$c/run_status.txt"
    python3 "$HERE/cf.py" "$c" "$it" --profile > "$c/cf_profile.txt" || true
}

run_case eg2d &
p1=$!
run_case tmr &
p2=$!
wait $p1 || true
wait $p2 || true

printf '%-14s %-10s %-9s %-10s %-8s %-22s %s\n' grid "Cf(0.97)" "% off" iterations "time s" checkMesh status
for g in eg2d tmr; do
    c=$WORK/case_$g
    read -r it secs status < "$c/run_status.txt"
    cf=$(tail -n 1 "$c/cf_history.txt" | awk '{print $2}')
    off=$(awk -v a="$cf" -v b="$CF_TMR" 'BEGIN { if (a == "") print "-"; else printf "%+.2f", 100 * (a - b) / b }')
    # a wall-resolved grid (y+ < 1) always trips checkMesh's aspect-ratio
    # warning (threshold 1000): say so apart from the other checks
    if grep -q "^Mesh OK" "$c/log.checkMesh"; then
        verdict="Mesh OK"
    elif [ "$(grep -c '\*\*\*' "$c/log.checkMesh")" = 1 ] && grep -q "High aspect ratio" "$c/log.checkMesh"; then
        verdict="OK-but-AR:$(sed -n 's/.*Max aspect ratio: \([0-9.e+]*\).*/\1/p' "$c/log.checkMesh" | awk '{printf "%.3g", $1}')"
    else
        verdict=$(grep -o "Failed [0-9]* mesh checks" "$c/log.checkMesh" || echo "checkMesh-failed")
        verdict=$(echo "$verdict" | tr ' ' '-')
    fi
    case $g in eg2d) name="eg2d 137x97" ;; tmr) name="TMR 137x97" ;; esac
    printf '%-14s %-10s %-9s %-10s %-8s %-22s %s\n' "$name" "${cf:--}" "$off" "$it" "$secs" "$verdict" "$status"
done
