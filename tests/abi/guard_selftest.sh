#!/usr/bin/env bash
# The ABI guard's own test: the built library against doctored baselines, so
# that both verdicts are seen to happen. A function missing from the baseline
# is an addition (passes); a parameter type, a constant's value or a constant
# that differ from the baseline are breaks (fail).
# Usage: guard_selftest.sh ABI_SH LIB HEADER
set -uo pipefail
abi_sh=$1 lib=$2 header=$3
base=$(dirname "$abi_sh")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect NAME pass|fail PATTERN: runs the check against $work/NAME.
expect() {
    local out rc
    out=$(EG2D_ABI_BASELINE_DIR=$work/$1 bash "$abi_sh" check "$lib" "$header" 2>&1)
    rc=$?
    if { [ "$2" = pass ] && [ $rc -ne 0 ]; } || { [ "$2" = fail ] && [ $rc -eq 0 ]; } ||
       ! grep -q -- "$3" <<< "$out"; then
        echo "FAIL $1: expected $2 with \"$3\", got exit $rc:"
        echo "$out"
        failures=$((failures + 1))
    else
        echo "ok   $1: $2 ($3)"
    fi
}
variant() { mkdir -p "$work/$1" && cp "$base/libeg2d.so.1.abi" "$base/constants.txt" "$work/$1/"; }

variant same
expect same pass "OK:"

# eg2d_get_iterations absent from the baseline: the library adds it.
variant added
sed -i "/<function-decl name='eg2d_get_iterations'/,/<\/function-decl>/d; /<elf-symbol name='eg2d_get_iterations'/d" \
    "$work/added/libeg2d.so.1.abi"
expect added pass "eg2d_get_iterations"

# eg2d_set_tolerance(eg2d_grid*, int) in the baseline: the library has double.
variant signature
int_id=$(sed -n "s/.*<type-decl name='int' [^>]*id='\([^']*\)'.*/\1/p" "$work/signature/libeg2d.so.1.abi" | head -n 1)
dbl_id=$(sed -n "s/.*<type-decl name='double' [^>]*id='\([^']*\)'.*/\1/p" "$work/signature/libeg2d.so.1.abi" | head -n 1)
sed -i "/<function-decl name='eg2d_set_tolerance'/,/<\/function-decl>/s/type-id='$dbl_id'/type-id='$int_id'/" \
    "$work/signature/libeg2d.so.1.abi"
expect signature fail "eg2d_set_tolerance(eg2d_grid\*, int)' has some indirect sub-type changes"

variant value
sed -i 's/^EG2D_SOLVER_AF .*/EG2D_SOLVER_AF 7/' "$work/value/constants.txt"
expect value fail "EG2D_SOLVER_AF changed from 7 to 2"

variant removed
echo "EG2D_ERR_GONE 99" >> "$work/removed/constants.txt"
expect removed fail "EG2D_ERR_GONE (= 99) was removed"

echo "guard self-test: $failures failed"
[ "$failures" -eq 0 ]
