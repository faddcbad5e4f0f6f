#!/usr/bin/env bash
# The layering check must be able to fail: a copy of src/ with one upward
# include (base -> solvers) must be refused, naming the file and the arrow.
set -euo pipefail
python=$1 check=$2 src=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -r "$src" "$tmp/src"
mkdir "$tmp/docs" && cp "$src/../docs/DESIGN.md" "$tmp/docs/"
echo '#include "solvers/solver.hpp"' >> "$tmp/src/base/grid.cpp"
if out=$("$python" "$check" "$tmp/src"); then
    echo "layers.py accepted an upward include:"; echo "$out"; exit 1
fi
echo "$out"
grep -q 'base/grid.cpp:.*base (layer 0) includes solvers/solver.hpp from solvers' <<<"$out"
# and an include from a lower layer that the file's row of DESIGN.md does
# not name (io may use base and quality, not controls)
cp "$src/base/grid.cpp" "$tmp/src/base/grid.cpp"
echo '#include "controls/control.hpp"' >> "$tmp/src/io/report.cpp"
if out=$("$python" "$check" "$tmp/src"); then
    echo "layers.py accepted an include its row does not allow:"; echo "$out"; exit 1
fi
echo "$out"
grep -q "io/report.cpp:.*io includes controls/control.hpp from controls, which its row of DESIGN.md does not allow" <<<"$out"
