"""Hermite TFI at chosen sides and interior lines from Python, as
tests/c/test_hermite_sides.c and test_interior_lines.c do in C."""
import numpy as np
import pytest

import eg2d


def annulus(n=33, r0=1.0, r1=3.0):
    t = 2 * np.pi * np.arange(n) / (n - 1)
    g = eg2d.Grid(n, n)
    g.set_topology(eg2d.TOPO_O)
    for side, r in ((eg2d.SIDE_JMIN, r0), (eg2d.SIDE_JMAX, r1)):
        x, y = r * np.cos(t), r * np.sin(t)
        x[-1], y[-1] = x[0], y[0]
        g.set_side(side, x, y)
    return g


def test_hermite_sides_annulus():
    n, h0, h1 = 33, 0.02, 0.05
    g = annulus(n)
    g.set_parameter(eg2d.PARAM_HERMITE_SIDES, (1 << eg2d.SIDE_JMIN) | (1 << eg2d.SIDE_JMAX))
    g.set_parameter(eg2d.PARAM_HERMITE_HEIGHT_JMIN, h0)
    g.set_parameter(eg2d.PARAM_HERMITE_HEIGHT_JMAX, h1)
    g.initialize(eg2d.INIT_HERMITE)
    x, y = g.get_coordinates()
    r, t = np.hypot(x, y), np.arctan2(y, x)
    assert g.get_quality(eg2d.QUALITY_FOLDED_CELLS) == 0
    assert np.allclose(r[:, 1], 1 + h0, rtol=0, atol=1e-12)      # the first cells as set
    assert np.allclose(r[:, -2], 3 - h1, rtol=0, atol=1e-12)
    assert np.allclose(np.sin(t[:, 1] - t[:, 0]), 0, atol=1e-12)  # on the radial normals
    assert g.get_quality(eg2d.QUALITY_ORTHO_MAX_JMIN) < 1e-9
    g.set_parameter(eg2d.PARAM_HERMITE_SIDES, 1 << eg2d.SIDE_IMIN)  # an O-grid has no IMIN
    with pytest.raises(eg2d.Error) as e:
        g.initialize(eg2d.INIT_HERMITE)
    assert e.value.status == eg2d.ERR_ARGUMENT


def square_with_row(n=33, row=10):
    s = np.linspace(0.0, 1.0, n)
    g = eg2d.Grid(n, n)
    zero, one = np.zeros(n), np.ones(n)
    g.set_side(eg2d.SIDE_JMIN, s, zero)
    g.set_side(eg2d.SIDE_IMAX, one, s)
    g.set_side(eg2d.SIDE_JMAX, s, one)
    g.set_side(eg2d.SIDE_IMIN, zero, s)
    cx, cy = s, s[row] + 0.1 * np.sin(np.pi * s)
    g.set_interior_line(eg2d.ETA, row, cx, cy)
    return g, cx, cy


def test_interior_line():
    row = 10
    g, cx, cy = square_with_row(row=row)
    g.initialize(eg2d.INIT_TFI)
    x, y = g.get_coordinates()
    assert np.array_equal(x[:, row], cx) and np.array_equal(y[:, row], cy)
    start = (x.copy(), y.copy())
    g.set_tolerance(1e-10)
    g.solve()
    x, y = g.get_coordinates()
    assert np.array_equal(x[:, row], cx) and np.array_equal(y[:, row], cy)  # held by the solve
    assert g.get_quality(eg2d.QUALITY_FOLDED_CELLS) == 0
    g.clear_interior_lines()
    g.set_coordinates(*start)
    g.solve()
    x, y = g.get_coordinates()
    assert np.max(np.abs(y[:, row] - cy)) > 1e-2  # without the line the solve moves it
    with pytest.raises(eg2d.Error) as e:
        g.set_interior_line(eg2d.ETA, 0, cx, cy)
    assert e.value.status == eg2d.ERR_ARGUMENT
