#!/usr/bin/env bash
# The link check must be able to fail: a page with a link to nothing.
set -euo pipefail
python=$1 check=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/docs" "$tmp/include" "$tmp/examples"
echo 'See [the manual](docs/missing.md).' > "$tmp/README.md"
echo '/* see bench/NOWHERE.md; the swan of seed 003 */' > "$tmp/include/eg2d.h"
if out=$("$python" "$check" "$tmp"); then echo "accepted broken links: $out"; exit 1; fi
echo "$out"
grep -q "README.md: link to docs/missing.md does not resolve" <<<"$out"
grep -q "include/eg2d.h: names bench/NOWHERE.md, which does not exist" <<<"$out"
grep -q "include/eg2d.h:1: an internal label" <<<"$out"
