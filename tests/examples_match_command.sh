#!/usr/bin/env bash
# The examples that make `eg2d airfoil`'s grid from a program
# (examples/c/command_grid.c, examples/fortran/command_grid.f90,
# examples/python/command_grid.py, run with $EG2D_PYTHON) give the
# command's Plot3D file byte for byte at 385x97 and 1793x513 (a
# program embedding the library gets the command's grid).
#   examples_match_command.sh EG2D_COMMAND EXAMPLE...
set -euo pipefail
command=${1:?eg2d command}
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for size in 385x97 1793x513; do
    "$command" airfoil 0012 --size "$size" --yplus 1 --reynolds 6e6 --format plot3d -o "$work/cmd-$size" --quiet
    for example in "$@"; do
        run=("$example")
        [[ $example == *.py ]] && run=("${EG2D_PYTHON:-python3}" "$example")
        "${run[@]}" "${size%x*}" "${size#*x}" "$work/example.xyz" > /dev/null
        cmp "$work/example.xyz" "$work/cmd-$size/naca0012-$size.xyz"
        echo "$size: $(basename "$example")'s grid is the command's, byte for byte"
    done
done
echo "every example's grid is the command's ($# examples, 2 sizes)"
