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


def graded_c_grid(ni, nj, wake, radius, le, te):
    """NACA 0012 C-grid boundary as tests/support's domain_set_airfoil_c_graded."""
    g = eg2d.Grid(ni, nj)
    g.set_topology(eg2d.TOPO_C)
    na = ni - 2 * wake
    half = na // 2
    with eg2d.Curve.naca4("0012", eg2d.NACA_CLOSED_TE) as foil:
        length = foil.length()
        s = np.linspace(0, 1, 2001)
        s_le = s[np.argmin([foil.evaluate(v)[0] for v in s])]
        lower = s_le * eg2d.distribution(eg2d.DIST_VINOKUR, half + 1, te / (s_le * length), le / (s_le * length))
        upper = s_le + (1 - s_le) * eg2d.distribution(
            eg2d.DIST_VINOKUR, half + 1, le / ((1 - s_le) * length), te / ((1 - s_le) * length))
        body = np.array([foil.evaluate(v) for v in np.concatenate([lower, upper[1:]])])
    body[0] = body[-1] = (1.0, 0.0)
    ds = np.hypot(*(body[1] - body[0]))
    lo_r, hi_r = 1.0, 2.0  # the cut's ratio: wake cells from ds adding up to radius
    for _ in range(200):
        r = 0.5 * (lo_r + hi_r)
        lo_r, hi_r = (r, hi_r) if ds * (r ** wake - 1) / (r - 1) < radius else (lo_r, r)
    cut = 1 + np.cumsum(ds * r ** np.arange(wake))[::-1]
    cut[0] = 1 + radius
    x = np.concatenate([cut, body[:, 0], cut[::-1]])
    y = np.concatenate([np.zeros(wake), body[:, 1], np.zeros(wake)])
    g.set_side(eg2d.SIDE_JMIN, x, y)
    f = eg2d.distribution(eg2d.DIST_VINOKUR, na, te / (np.pi * radius), te / (np.pi * radius))
    a = -np.pi / 2 - np.pi * f
    xf = np.concatenate([cut, [1.0], 1 + radius * np.cos(a[1:-1]), [1.0], cut[::-1]])
    yf = np.concatenate([-radius * np.ones(wake), [-radius], radius * np.sin(a[1:-1]), [radius], radius * np.ones(wake)])
    g.set_side(eg2d.SIDE_JMAX, xf, yf)
    yo = -radius * np.linspace(0, 1, nj)
    g.set_side(eg2d.SIDE_IMIN, np.full(nj, 1 + radius), yo)
    g.set_side(eg2d.SIDE_IMAX, np.full(nj, 1 + radius), -yo)
    return g


def test_hybrid_c_grid_by_default():
    """A C-grid with only a first-cell height set (y+ 1 at Re 6e6, far field
    100 chords): the default takes the hybrid layer; first cell as asked on
    the whole body, graded at most 1.2, no folds, wake cells within 45
    degrees, the cut's spacing growing downstream, a few cycles."""
    ni, nj, wake = 385, 97, 80
    h = eg2d.first_cell_height(1.0, 6e6)
    g = graded_c_grid(ni, nj, wake, 100.0, 1e-3, 2e-3)
    g.set_wall_spacing(eg2d.SIDE_JMIN, h)
    g.set_orthogonality(eg2d.ORTHO_WALL)
    g.set_tolerance(1e-10)
    g.solve()
    assert g.get_iterations() <= 10
    assert g.get_quality(eg2d.QUALITY_FOLDED_CELLS) == 0
    events = [text for _, text in g.get_run_events()]
    assert events[0].startswith("wall layer (hybrid): 64 rows of the hyperbolic march held")
    x, y = g.get_coordinates()
    body = slice(wake, ni - wake)
    first = np.hypot(x[body, 1] - x[body, 0], y[body, 1] - y[body, 0])
    assert np.allclose(first, h, rtol=1e-3)
    heights = np.hypot(np.diff(x, axis=1), np.diff(y, axis=1))[body, :30]
    ratio = heights[:, 1:] / heights[:, :-1]
    assert ratio.min() >= 1.0 and ratio.max() <= 1.2
    skew = g.get_cell_quality(eg2d.QUALITY_SKEWNESS)
    assert max(skew[:wake, :].max(), skew[ni - 1 - wake:, :].max()) <= 45.0
    cut = np.hypot(x[1:wake, 1] - x[1:wake, 0], y[1:wake, 1] - y[1:wake, 0])  # outflow -> trailing edge
    # growing downstream, then level in the far wake (within 1%: the layer's thickness there)
    assert np.all(cut[:-1] >= cut[1:] * (1 - 1e-2)) and cut[0] > 10 * h
