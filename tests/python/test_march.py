"""The hyperbolic march from Python: an O-grid around a circle marched with
EG2D_INIT_HYPERBOLIC, its parameters, and its errors as exceptions."""
import numpy as np
import pytest

import eg2d


def circle_grid(ni=65, nj=33):
    t = 2 * np.pi * np.arange(ni) / (ni - 1)
    x, y = np.cos(t), np.sin(t)
    x[-1], y[-1] = x[0], y[0]
    g = eg2d.Grid(ni, nj)
    g.set_topology(eg2d.TOPO_O)
    g.set_side(eg2d.SIDE_JMIN, x, y)
    return g


def test_march_circle():
    g = circle_grid()
    g.set_parameter(eg2d.PARAM_MARCH_DISTANCE, 10.0)
    g.set_parameter(eg2d.PARAM_MARCH_FIRST_HEIGHT, 0.01)
    g.set_parameter(eg2d.PARAM_MARCH_GROWTH, 1.3)
    g.initialize(eg2d.INIT_HYPERBOLIC)
    x, y = g.get_coordinates()
    r = np.hypot(x, y)
    assert g.get_quality(eg2d.QUALITY_FOLDED_CELLS) == 0
    assert np.allclose(r[:, 1], 1.01, rtol=1e-6)            # the first cell as asked
    heights = np.diff(r[0, :])
    assert np.max(heights[1:] / heights[:-1]) <= 1.3 + 1e-9  # growth within G
    assert r[:, -1].min() - 1 >= 0.95 * 10.0                 # the far field reached
    assert np.ptp(r[:, -1]) < 1e-8                           # every layer a circle


def test_march_errors():
    g = eg2d.Grid(9, 5)
    with pytest.raises(eg2d.Error) as e:
        g.initialize(eg2d.INIT_HYPERBOLIC)
    assert e.value.status == eg2d.ERR_STATE and "JMIN" in str(e.value)
    g = circle_grid(33, 9)
    g.set_parameter(eg2d.PARAM_MARCH_DISTANCE, 100.0)
    g.set_parameter(eg2d.PARAM_MARCH_FIRST_HEIGHT, 1e-3)
    with pytest.raises(eg2d.Error) as e:
        g.initialize(eg2d.INIT_HYPERBOLIC)
    assert e.value.status == eg2d.ERR_ARGUMENT and "reach only" in str(e.value)
    with pytest.raises(eg2d.Error):
        g.set_parameter(eg2d.PARAM_MARCH_END_IMAX, 7)


def test_hybrid_wall_layer():
    """The wall control with the hybrid layer (PARAM_WALL_LAYER 2) round a
    sharp trailing edge: first cell as asked, orthogonal, graded, no folds,
    a few multigrid cycles, and the run says what it held."""
    ni, nj, h = 129, 65, 1e-5
    g = eg2d.Grid(ni, nj)
    g.set_topology(eg2d.TOPO_O)
    with eg2d.Curve.naca4("0012", eg2d.NACA_CLOSED_TE) as foil:
        g.set_side_curve(eg2d.SIDE_JMIN, foil)
    t = -2 * np.pi * np.arange(ni) / (ni - 1)  # clockwise, as the section runs
    g.set_side(eg2d.SIDE_JMAX, 0.5 + 15 * np.cos(t), 15 * np.sin(t))
    g.set_wall_spacing(eg2d.SIDE_JMIN, h)
    g.set_orthogonality(eg2d.ORTHO_WALL)
    g.set_parameter(eg2d.PARAM_WALL_LAYER, 2)
    g.set_tolerance(1e-10)
    g.solve()
    assert g.get_iterations() <= 10
    assert g.get_quality(eg2d.QUALITY_FOLDED_CELLS) == 0
    events = [text for _, text in g.get_run_events()]
    assert events[0].startswith("wall layer (hybrid): 42 rows of the hyperbolic march held")
    x, y = g.get_coordinates()
    first = np.hypot(x[:, 1] - x[:, 0], y[:, 1] - y[:, 0])
    assert np.allclose(first, h, rtol=1e-3)
    heights = np.hypot(np.diff(x, axis=1), np.diff(y, axis=1))[:, :30]
    assert np.max(heights[:, 1:] / heights[:, :-1]) <= 1.3
