"""A program embedding eg2d makes `eg2d airfoil`'s grid: NACA 0012 C-grid
385x97 at y+ 1, Re 6e6, through the calls docs/airfoil.md gives (the
section, the wall's first cell, the tolerance and the cycle the command
uses), node for node against the command's Plot3D file. The cut's count is
the library's automatic one in both (eg2d_get_cut)."""
import math
import os
import subprocess

import numpy as np
import pytest

import eg2d

COMMAND = os.environ.get("EG2D_COMMAND")


def first_cell(yplus, reynolds):
    cf = (2 * math.log10(reynolds) - 0.65) ** -2.3  # Schlichting (1979), as the command
    return yplus / (reynolds * math.sqrt(cf / 2))


def recipe(ni, nj):
    g = eg2d.Grid(ni, nj)
    g.set_airfoil(eg2d.Curve.naca4("0012"), eg2d.TOPO_C)
    g.set_wall_spacing(eg2d.SIDE_JMIN, first_cell(1.0, 6e6))
    g.set_tolerance(1e-10)
    g.set_parameter(eg2d.PARAM_MG_CYCLE, 1)  # V(1, 2), the command's cycle on C-grids
    g.set_parameter(eg2d.PARAM_MG_PRE_SMOOTH, 1)
    g.set_parameter(eg2d.PARAM_MG_POST_SMOOTH, 2)
    g.solve()
    return g


@pytest.mark.skipif(not COMMAND, reason="EG2D_COMMAND (the eg2d command) not given")
def test_recipe_is_the_commands_grid(tmp_path):
    g = recipe(385, 97)
    assert g.get_cut() == 80
    subprocess.run([COMMAND, "airfoil", "0012", "--size", "385x97", "--yplus", "1", "--reynolds", "6e6",
                    "--levels", "3", "--format", "plot3d", "-o", str(tmp_path), "--quiet"], check=True)
    x, y, _, _ = eg2d.read_plot3d(str(tmp_path / "naca0012-385x97.xyz"))
    gx, gy = g.get_coordinates()
    assert np.array_equal(gx, x) and np.array_equal(gy, y)


def test_cut_of_other_topologies():
    g = eg2d.Grid(65, 33)
    assert g.get_cut() == 0
    g.set_airfoil(eg2d.Curve.naca4("0012"), eg2d.TOPO_O)
    assert g.get_cut() == 0
    g.set_airfoil(eg2d.Curve.naca4("0012"), eg2d.TOPO_C)
    assert g.get_cut() == 14  # 0.21 x 64 = 13.4: a multiple of 2 within 1.28 of it
