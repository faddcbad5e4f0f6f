#!/usr/bin/env python3
"""`eg2d airfoil`'s grid from Python: the NACA 0012 C-grid at y+ 1 for a chord Reynolds
number of 6e6, written as Plot3D, node for node the command's file
(tests/examples_match_command.sh compares them):
    eg2d airfoil 0012 --size NIxNJ --yplus 1 --reynolds 6e6 --format plot3d
Usage: command_grid.py NI NJ FILE.xyz (PYTHONPATH at the package and, outside an
install, EG2D_LIBRARY=path/to/libeg2d.so.1)."""
import math
import sys

import eg2d

ni, nj, path = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
re = 6e6
cf = (2 * math.log10(re) - 0.65) ** -2.3  # turbulent flat plate (Schlichting 1979), as the command
with eg2d.Grid(ni, nj) as g:
    # the section (with an airfoil grid's run: tolerance, cycle) and the wall's first cell, as the command
    g.set_airfoil(eg2d.Curve.naca4("0012"), eg2d.TOPO_C)
    g.set_wall_spacing(eg2d.SIDE_JMIN, 1 / (re * math.sqrt(cf / 2)))
    g.solve()                                    # raises eg2d.Error with the message
    g.write(path, eg2d.FORMAT_PLOT3D)
    print(f"NACA 0012 C-grid {ni}x{nj}, {g.get_cut()} cut nodes a side, written to {path}")
