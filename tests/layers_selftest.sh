#!/usr/bin/env bash
# The layering check must be able to fail: a copy of src/ with one upward
# include (base -> solvers) must be refused, naming the file and the arrow.
set -euo pipefail
python=$1 check=$2 src=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -r "$src" "$tmp/src"
echo '#include "solvers/solver.hpp"' >> "$tmp/src/base/grid.cpp"
if out=$("$python" "$check" "$tmp/src"); then
    echo "layers.py accepted an upward include:"; echo "$out"; exit 1
fi
echo "$out"
grep -q 'base/grid.cpp:.*base (layer 0) includes solvers/solver.hpp from solvers' <<<"$out"
