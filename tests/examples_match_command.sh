#!/usr/bin/env bash
# The C example examples/c/command_grid.c makes `eg2d airfoil`'s grid: the
# two Plot3D files, byte for byte, at 385x97 and 1793x513 (issue 35: a
# program embedding the library gets the command's grid).
#   examples_match_command.sh EXAMPLE EG2D_COMMAND
set -euo pipefail
example=${1:?example}
command=${2:?eg2d command}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for size in 385x97 1793x513; do
    "$example" "${size%x*}" "${size#*x}" "$work/example-$size.xyz"
    "$command" airfoil 0012 --size "$size" --yplus 1 --reynolds 6e6 --format plot3d -o "$work/cmd-$size" --quiet
    cmp "$work/example-$size.xyz" "$work/cmd-$size/naca0012-$size.xyz"
    echo "$size: the example's grid is the command's, byte for byte"
done
