#!/usr/bin/env bash
# The ABI guard of libeg2d.so.1 (docs/ABI.md). Two baselines live next to this
# script and are committed:
#   libeg2d.so.1.abi  functions and the types they use, written by libabigail's abidw
#   constants.txt     every EG2D_* constant of include/eg2d.h with its value
#                     (#define values are not in DWARF, so abidw cannot see them)
#
#   abi.sh check  LIB HEADER   compare a built library and header with the baselines
#   abi.sh update LIB HEADER   rewrite the baselines (only when an addition is accepted)
#
# check passes when the only differences are additions; it fails on a removed
# or changed function, a changed type reachable from one, and a removed or
# renumbered constant.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mode=${1:?usage: abi.sh check|update LIB HEADER}
lib=${2:?library path}
header=${3:?header path}
# EG2D_ABI_BASELINE_DIR points elsewhere for the guard's own test only.
baseline=${EG2D_ABI_BASELINE_DIR:-$here}/libeg2d.so.1.abi
constants=${EG2D_ABI_BASELINE_DIR:-$here}/constants.txt

# Only what a C caller can reach: the exported functions and the types of their
# parameters as the public header defines them. eg2d_grid stays opaque (its C++
# definition in src/api is private), and locations are left out so that
# moving code does not touch the baseline.
abi_dump() {
    if ! readelf -S "$1" | grep -q '\.debug_info'; then
        echo "abi.sh: $1 has no DWARF; the API sources are built with -g for this check" >&2
        exit 1
    fi
    abidw --headers-dir "$(dirname "$header")" --drop-private-types --exported-interfaces-only \
          --no-corpus-path --no-comp-dir-path --no-show-locs --no-architecture "$1"
}

# NAME VALUE for each #define EG2D_* of the header, except the include guard
# and the version numbers (minor and patch grow in 1.x by design). A constant
# must be a plain integer literal (decimal or hex) so that this guard can read
# it; anything else is reported as UNREADABLE and fails the check.
constants_of() {
    awk '$1 == "#define" && $2 ~ /^EG2D_/ && $2 != "EG2D_H" && $2 !~ /^EG2D_VERSION_/ {
             if ($3 ~ /^-?(0[xX][0-9a-fA-F]+|[0-9]+)[uUlL]*$/) print $2, $3; else print $2, "UNREADABLE"
         }' "$1" | LC_ALL=C sort
}

case $mode in
update)
    if constants_of "$header" | grep ' UNREADABLE$'; then
        echo "abi.sh: constants above are not plain integer literals" >&2
        exit 1
    fi
    abi_dump "$lib" > "$baseline"
    constants_of "$header" > "$constants"
    echo "abi.sh: wrote $baseline ($(grep -c '<function-decl' "$baseline") functions)" \
         "and $constants ($(wc -l < "$constants") constants)"
    ;;
check)
    status=0
    # abidiff's exit code is a bit field: 1 error, 2 usage error, 4 ABI change,
    # 8 incompatible change (only removals set it). An added function is an
    # ABI change (4) too, and so is a changed parameter type, so the verdict
    # comes from a run that hides added symbols: any bit left means a change
    # that is not an addition.
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    abi_dump "$lib" > "$work/current.abi"
    rc=0
    abidiff --no-added-syms "$baseline" "$work/current.abi" > "$work/diff.txt" || rc=$?
    if [ "$rc" -ne 0 ]; then
        echo "abi.sh: FAIL: abidiff exit code $rc (bits: 1 error, 4 change, 8 incompatible):"
        cat "$work/diff.txt"
        status=1
    fi
    if [ "$rc" -eq 0 ]; then
        # What was added, for the record (additions set bit 4, so the code is ignored).
        abidiff "$baseline" "$work/current.abi" || true
    fi

    constants_of "$header" > "$work/constants.txt"
    while read -r name value; do
        now=$(awk -v n="$name" '$1 == n { print $2 }' "$work/constants.txt")
        if [ -z "$now" ]; then
            echo "abi.sh: FAIL: constant $name (= $value) was removed from $(basename "$header")"
            status=1
        elif [ "$now" != "$value" ]; then
            echo "abi.sh: FAIL: constant $name changed from $value to $now"
            status=1
        fi
    done < "$constants"
    if grep -q ' UNREADABLE$' "$work/constants.txt"; then
        echo "abi.sh: FAIL: not a plain integer literal: $(grep ' UNREADABLE$' "$work/constants.txt" | cut -d' ' -f1)"
        status=1
    fi
    added=$(LC_ALL=C comm -13 <(cut -d' ' -f1 "$constants") <(cut -d' ' -f1 "$work/constants.txt") | tr '\n' ' ')
    [ -z "$added" ] || echo "abi.sh: added constants (fine): $added"
    if [ "$status" -eq 0 ]; then
        echo "abi.sh: OK: $(grep -c '<function-decl' "$baseline") baseline functions and" \
             "$(wc -l < "$constants") constants unchanged"
    fi
    exit "$status"
    ;;
*)
    echo "usage: abi.sh check|update LIB HEADER" >&2
    exit 2
    ;;
esac
