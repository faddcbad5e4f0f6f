#!/usr/bin/env bash
# docs/BAD_INPUTS.md's table is the table of tests/c/test_failures.c, which
# asserts every row. check: the page matches `test_failures --table`;
# update: rewrites the table part of the page.
# Usage: bad_inputs_doc.sh check|update TEST_FAILURES_BINARY DOC
set -euo pipefail
mode=$1 bin=$2 doc=$3
begin='<!-- BEGIN test_failures --table -->'
end='<!-- END test_failures --table -->'
generated=$("$bin" --table)
current=$(sed -n "\|^$begin\$|,\|^$end\$|p" "$doc" | sed '1d;$d')
case $mode in
check)
    if [ "$generated" != "$current" ]; then
        echo "$doc is not the table of test_failures; run: $0 update $bin $doc"
        diff <(echo "$current") <(echo "$generated") || true
        exit 1
    fi
    echo "$doc: $(grep -c '^| ' <<< "$generated") lines, same as test_failures --table"
    ;;
update)
    tmp=$(mktemp)
    # The table goes through the environment: awk -v would expand its \n.
    TABLE=$generated awk -v b="$begin" -v e="$end" '
        $0 == b { print; print ENVIRON["TABLE"]; skip = 1; next }
        $0 == e { skip = 0 }
        !skip { print }' "$doc" > "$tmp"
    mv "$tmp" "$doc"
    ;;
esac
