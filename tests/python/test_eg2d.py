"""The Python package eg2d: every Grid method and module function on its good
and bad path (exceptions carry the status and the library's message), the
context manager, the monitor, and grids equal to the C library's."""
import gc
import os

import numpy as np
import pytest

import eg2d


def swan_sides(ni, nj):
    s = np.arange(ni) / (ni - 1)  # as tests/support/domains.c: i / (n - 1)
    t = np.arange(nj) / (nj - 1)
    return {
        eg2d.SIDE_JMIN: (s, 0 * s),
        eg2d.SIDE_IMAX: (1 + 2 * t - 2 * t * t, t),
        eg2d.SIDE_JMAX: (s, 1 - 2 * s + 2 * s * s),
        eg2d.SIDE_IMIN: (0 * t, t),
    }


def swan(ni, nj=None):
    g = eg2d.Grid(ni, nj or ni)
    for side, (x, y) in swan_sides(ni, nj or ni).items():
        g.set_side(side, x, y)
    return g


# ---- module functions
def test_version_and_names():
    assert eg2d.version() == (eg2d.VERSION_MAJOR, eg2d.VERSION_MINOR, eg2d.VERSION_PATCH)
    assert eg2d.__version__ == "1.0.0"
    assert eg2d.status_string(eg2d.ERR_BOUNDARY).startswith("EG2D_ERR_BOUNDARY:")
    assert eg2d.status_string(999) == "unknown eg2d status"
    assert eg2d.solver_name(eg2d.SOLVER_PSOR) == "psor"
    assert eg2d.solver_name(99) is None


def test_parameter_bounds():
    assert eg2d.parameter_bounds(eg2d.PARAM_TOLERANCE) == (0.0, 1.0, 1e-8)
    with pytest.raises(eg2d.ArgumentError, match="parameter 999") as e:
        eg2d.parameter_bounds(999)
    assert e.value.status == eg2d.ERR_ARGUMENT
    assert "parameter 999" in eg2d.last_error()


# ---- lifetime
def test_create_bad_size_raises_with_message():
    with pytest.raises(eg2d.ArgumentError, match="eg2d_create") as e:
        eg2d.Grid(2, 9)
    assert e.value.status == eg2d.ERR_ARGUMENT and e.value.message == str(e.value)


def test_context_manager_closes_and_closed_grid_raises():
    with eg2d.Grid(5, 7) as g:
        assert g.get_size() == (5, 7) and g.shape == (5, 7) and not g.closed
    assert g.closed
    with pytest.raises(eg2d.StateError, match="closed"):
        g.solve()
    g.close()  # idempotent
    assert g.last_error == ""


def test_exception_in_with_block_still_closes():
    with pytest.raises(RuntimeError):
        with eg2d.Grid(5, 5) as g:
            raise RuntimeError("boom")
    assert g.closed


def test_collection_frees_without_error():
    g = eg2d.Grid(5, 5)
    del g
    gc.collect()


# ---- topology
def test_topology():
    with eg2d.Grid(9, 5) as g:
        assert g.get_topology() == eg2d.TOPO_SINGLE
        g.set_topology(eg2d.TOPO_O)
        assert g.get_topology() == eg2d.TOPO_O
        with pytest.raises(eg2d.ArgumentError, match="topology = 7"):
            g.set_topology(7)
        assert g.get_topology() == eg2d.TOPO_O  # a failed call changes nothing


# ---- boundary and initial grid
def test_set_side_checks():
    with eg2d.Grid(17, 9) as g:
        with pytest.raises(eg2d.ArgumentError, match=r"x has shape \(10,\): the side has 17 points"):
            g.set_side(eg2d.SIDE_JMIN, np.zeros(10), np.zeros(10))
        with pytest.raises(eg2d.ArgumentError, match="eg2d_set_side"):
            g.set_side(7, np.zeros(17), np.zeros(17))
        with pytest.raises(eg2d.StateError):
            g.initialize()
    with swan(17) as g:
        with pytest.raises(eg2d.BoundaryError, match="eg2d_set_side") as e:
            g.set_side(eg2d.SIDE_JMIN, np.full(17, 5.0), np.full(17, 5.0))
        assert e.value.status == eg2d.ERR_BOUNDARY
        g.initialize(eg2d.INIT_TFI)  # the failed call left the boundary usable
        with pytest.raises(eg2d.ArgumentError):
            g.initialize(5)


def test_coordinates_fortran_order_and_shape_checks():
    with swan(17, 13) as g:
        with pytest.raises(eg2d.StateError):
            g.get_coordinates()
        g.initialize()
        x, y = g.get_coordinates()
        assert x.shape == (17, 13) and x.flags["F_CONTIGUOUS"] and x.dtype == np.float64
        s = np.arange(17) / 16
        assert x[16, 12] == 1.0 and x[0, 6] == 0.0
        np.testing.assert_array_equal(x[:, 0], s)  # x[i, j] is node (i, j): the bottom side
        np.testing.assert_array_equal(y[:, 0], 0 * s)
        assert y[0, 12] == 1.0 and x[16, 0] == 1.0
        with pytest.raises(eg2d.ArgumentError, match=r"must be \(ni, nj\) = \(17, 13\)"):
            g.set_coordinates(x[:, :12], y[:, :12])
        with pytest.raises(eg2d.ArgumentError):
            g.set_boundary(x.T, y.T)
        g.set_boundary(np.ascontiguousarray(x), y)  # C-ordered input is converted
        g.set_coordinates(x, y)
        x2, y2 = g.get_coordinates()
        np.testing.assert_array_equal(x2, x)


# ---- settings
def test_settings_good_and_bad():
    with eg2d.Grid(9, 9) as g:
        g.set_system(eg2d.SYSTEM_LAPLACE)
        with pytest.raises(eg2d.ArgumentError):
            g.set_system(9)
        g.set_solver(eg2d.SOLVER_PSOR)
        assert g.get_solver() == eg2d.SOLVER_PSOR
        with pytest.raises(eg2d.ArgumentError, match="no such solver"):
            g.set_solver(-1)
        g.set_relaxation(1.5)
        assert g.get_parameter(eg2d.PARAM_RELAXATION) == 1.5
        with pytest.raises(eg2d.ArgumentError):
            g.set_relaxation(2.5)
        g.set_tolerance(1e-9)
        assert g.get_parameter(eg2d.PARAM_TOLERANCE) == 1e-9
        with pytest.raises(eg2d.ArgumentError, match="tolerance = 0"):
            g.set_tolerance(0)
        g.set_max_iterations(77)
        assert g.get_parameter(eg2d.PARAM_MAX_ITERATIONS) == 77
        with pytest.raises(eg2d.ArgumentError):
            g.set_max_iterations(0)
        g.set_parameter(eg2d.PARAM_FOLD_CHECK, 0)
        assert g.get_parameter(eg2d.PARAM_FOLD_CHECK) == 0
        with pytest.raises(eg2d.ArgumentError):
            g.set_parameter(999, 1)
        with pytest.raises(eg2d.ArgumentError):
            g.get_parameter(999)


# ---- running
def test_monitor_stops_and_exceptions_propagate():
    with swan(17) as g:
        g.set_tolerance(1e-15)  # multigrid reaches the default 1e-8 in 2 cycles
        seen = []
        g.set_monitor(lambda it, r: seen.append((it, r)) or it >= 3)
        with pytest.raises(eg2d.StoppedByMonitor, match="monitor") as e:
            g.solve()
        assert e.value.status == eg2d.ERR_INTERRUPTED
        assert [it for it, _ in seen] == [1, 2, 3] and g.get_iterations() == 3

        def broken(it, r):
            raise KeyError("from the monitor")
        g.set_monitor(broken)
        with pytest.raises(KeyError, match="from the monitor"):
            g.iterate(5)
        assert g.get_iterations() == 4  # stopped after its first call
        g.set_monitor(None)
        with pytest.raises(eg2d.ArgumentError):
            g.iterate(-1)
        r = g.iterate(2)
        assert r == g.get_residual() and g.get_iterations() == 6


def test_solve_converges_and_quality():
    with swan(33) as g:
        g.set_tolerance(1e-10)
        g.solve()
        assert g.get_residual() <= 1e-10
        assert g.get_iterations() > 0
        assert g.get_quality(eg2d.QUALITY_FOLDED_CELLS) == 0
        assert g.get_quality(eg2d.QUALITY_MIN_AREA) > 0
        with pytest.raises(eg2d.ArgumentError):
            g.get_quality(99)


def test_run_report():
    with swan(33) as g:
        g.solve()
        assert g.get_run_info(eg2d.RUN_SOLVER) == eg2d.SOLVER_MULTIGRID
        assert g.get_run_info(eg2d.RUN_LEVELS) == 4  # 33, 17, 9, 5
        assert g.get_run_events() == []
        with pytest.raises(eg2d.Error) as e:
            g.get_run_info(99)
        assert "not an EG2D_RUN_* id" in str(e.value)
    with swan(4) as g:
        g.solve()
        events = g.get_run_events()
        assert len(events) == 1 and events[0][0] == 1
        assert events[0][1].startswith("multigrid: the 4x4 grid has no coarse level")


def test_not_converged_keeps_iterations():
    with swan(33) as g:
        g.set_tolerance(1e-15)  # out of reach of 3 multigrid cycles
        g.set_max_iterations(3)
        with pytest.raises(eg2d.NotConvergedError, match="eg2d_solve"):
            g.solve()
        assert g.get_iterations() == 3


def test_variational_system():
    """V = aA + bS + cO: the weights are parameters; S alone folds on the swan
    (the fold guard stops short of it, unfolded); a = 10, b = 1, c = 1 gives an
    unfolded grid with more even cells than Winslow's."""
    assert eg2d.parameter_bounds(eg2d.PARAM_VARIATIONAL_SPACING) == (0.0, 1e6, 1.0)
    with swan(33) as g:
        g.set_system(eg2d.SYSTEM_VARIATIONAL)
        with pytest.raises(eg2d.ArgumentError, match="would all be 0"):
            g.set_parameter(eg2d.PARAM_VARIATIONAL_SPACING, 0)
        with pytest.raises(eg2d.NotConvergedError, match="fold guard"):
            g.solve()
        assert g.get_quality(eg2d.QUALITY_FOLDED_CELLS) == 0
    ratios = []
    for system in (eg2d.SYSTEM_WINSLOW, eg2d.SYSTEM_VARIATIONAL):
        with swan(33) as g:
            g.set_system(system)
            g.set_parameter(eg2d.PARAM_VARIATIONAL_AREA, 10)
            g.set_parameter(eg2d.PARAM_VARIATIONAL_ORTHOGONALITY, 1)
            g.solve()
            assert g.get_residual() <= 1e-8
            assert g.get_quality(eg2d.QUALITY_FOLDED_CELLS) == 0
            ratios.append(g.get_quality(eg2d.QUALITY_MAX_AREA) / g.get_quality(eg2d.QUALITY_MIN_AREA))
    assert ratios[1] < ratios[0]


# ---- the grids are the C library's
def test_swan_equals_c():
    """The file written by swan_write_c (C, tests/support/domains.c): 33 x 33,
    Winslow, point SOR, tolerance 1e-12."""
    path = os.environ.get("EG2D_SWAN_C_FILE")
    if not path:
        pytest.skip("EG2D_SWAN_C_FILE not set (run through ctest)")
    data = np.loadtxt(path, skiprows=1)
    ni, nj = map(int, open(path).readline().split())
    xc = data[:, 0].reshape((ni, nj), order="F")
    yc = data[:, 1].reshape((ni, nj), order="F")
    with swan(ni, nj) as g:
        g.set_system(eg2d.SYSTEM_WINSLOW)
        g.set_solver(eg2d.SOLVER_PSOR)
        g.set_tolerance(1e-12)
        g.solve()
        x, y = g.get_coordinates()
    assert max(abs(x - xc).max(), abs(y - yc).max()) <= 1e-14
    assert xc.max() > 1.2


def annulus_error(n):
    """Max |r - r_i (r_o/r_i)^eta| on the Winslow O-grid of the annulus (NUMERICS.md)."""
    ri, ro, ni = 0.5, 1.5, 4 * (n - 1) + 1
    t = 2 * np.pi * np.arange(ni) / (ni - 1)
    with eg2d.Grid(ni, n) as g:
        g.set_topology(eg2d.TOPO_O)
        g.set_side(eg2d.SIDE_JMIN, ri * np.cos(t), ri * np.sin(t))
        g.set_side(eg2d.SIDE_JMAX, ro * np.cos(t), ro * np.sin(t))
        g.set_tolerance(1e-12)
        g.solve()
        x, y = g.get_coordinates()
    eta = np.arange(n) / (n - 1)
    return np.abs(np.hypot(x, y) - ri * (ro / ri) ** eta[None, :]).max()


def test_annulus_matches_the_exact_winslow_solution_at_second_order():
    e1, e2 = annulus_error(9), annulus_error(17)
    assert e2 < 1e-2
    assert np.log2(e1 / e2) > 1.9


# ---- AF settings, per-cell quality and files
def test_af_settings():
    with eg2d.Grid(9, 9) as g:
        with pytest.raises(eg2d.ArgumentError):
            g.set_af_cycle(2.0, 1.0)
        g.set_af_cycle(0.25, 8.0, 6)
        assert g.get_parameter(eg2d.PARAM_AF_DTAU_MAX) == 8.0 and g.get_parameter(eg2d.PARAM_AF_STEPS) == 6
        with pytest.raises(eg2d.ArgumentError):
            g.set_af_time_rule(0.0, 0.0)
        g.set_af_time_rule(0.0, 0.5)
        assert g.get_parameter(eg2d.PARAM_AF_B) == 0.5


def test_cell_quality():
    with swan(17, 13) as g:
        with pytest.raises(eg2d.StateError):
            g.get_cell_quality(eg2d.QUALITY_MIN_AREA)
        g.solve()
        a = g.get_cell_quality(eg2d.QUALITY_MIN_AREA)
        assert a.shape == (16, 12) and a.flags["F_CONTIGUOUS"]
        assert a.min() == pytest.approx(g.get_quality(eg2d.QUALITY_MIN_AREA), rel=1e-15)
        assert abs(a.sum() - 1.0) < 1e-2  # the swan's area is 1
        with pytest.raises(eg2d.ArgumentError, match="no per-cell values|boundary summary"):
            g.get_cell_quality(eg2d.QUALITY_ORTHO_MAX_JMIN)


def test_write_and_read_back(tmp_path):
    with swan(17, 13) as g:
        g.solve()
        x, y = g.get_coordinates()
        path = tmp_path / "swan.x"
        g.write(path, eg2d.FORMAT_PLOT3D | eg2d.PLOT3D_MULTI)
        xr, yr, fmt, nblocks = eg2d.read_plot3d(path)
        assert fmt == eg2d.FORMAT_PLOT3D | eg2d.PLOT3D_MULTI and nblocks == 1
        np.testing.assert_array_equal(xr, x)
        np.testing.assert_array_equal(yr, y)
        with pytest.raises(eg2d.FileError, match="no-such-dir"):
            g.write(tmp_path / "no-such-dir" / "g.x", eg2d.FORMAT_PLOT3D)
    with pytest.raises(eg2d.FileError, match="missing.x"):
        eg2d.read_plot3d(tmp_path / "missing.x")


def test_point_files(tmp_path):
    pts = tmp_path / "bottom.txt"
    s = np.arange(17) / 16
    pts.write_text("# bottom of the swan\n" + "".join(f"{v!r} 0\n" for v in s))
    x, y = eg2d.read_points(pts)
    np.testing.assert_array_equal(x, s)
    np.testing.assert_array_equal(y, 0 * s)
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0\n1 oops\n")
    with pytest.raises(eg2d.FileError, match=r"bad.txt:2: \"1 oops\""):
        eg2d.read_points(bad)
    with swan(17, 13) as g:
        g.set_side_from_file(eg2d.SIDE_JMIN, pts)
        with pytest.raises(eg2d.BoundaryError, match="holds 17 points"):
            g.set_side_from_file(eg2d.SIDE_IMIN, pts)


# ---- curves, distributions, y+
def test_polyline_length_evaluate_points():
    with eg2d.Curve.polyline([0, 1, 1], [0, 0, 1]) as c:
        assert c.length() == pytest.approx(2, abs=1e-14)
        assert c.evaluate(0.75) == pytest.approx((1, 0.5), abs=1e-12)
        with pytest.raises(eg2d.ArgumentError, match="s = 1.5"):
            c.evaluate(1.5)
        x, y = c.points(5)
        np.testing.assert_allclose(x, [0, 0.5, 1, 1, 1], atol=1e-12)
        np.testing.assert_allclose(y, [0, 0, 0, 0.5, 1], atol=1e-12)
    with pytest.raises(eg2d.StateError, match="closed"):
        c.length()
    with pytest.raises(eg2d.ArgumentError, match="eg2d_curve_polyline"):
        eg2d.Curve.polyline([0], [0])
    with pytest.raises(eg2d.ArgumentError, match="need two equal 1-D arrays"):
        eg2d.Curve.polyline([0, 1], [0])


def test_spline_circle_and_function_curve():
    t = 2 * np.pi * np.arange(65) / 64
    x, y = 2 * np.cos(t), 2 * np.sin(t)
    x[-1], y[-1] = x[0], y[0]
    with eg2d.Curve.spline(x, y) as c:
        assert abs(c.length() - 4 * np.pi) < 1e-5
    with eg2d.Curve.function(lambda t: (3 * np.cos(np.pi * t / 2), 3 * np.sin(np.pi * t / 2))) as c:
        assert abs(c.length() - 1.5 * np.pi) < 1e-10
        assert c.evaluate(0.5) == pytest.approx((3 / np.sqrt(2), 3 / np.sqrt(2)), abs=1e-10)

    def broken(t):
        raise ZeroDivisionError("from the curve")
    with pytest.raises(ZeroDivisionError, match="from the curve"):
        eg2d.Curve.function(broken)


def test_naca_and_airfoil_files(tmp_path):
    with eg2d.Curve.naca4("0012", eg2d.NACA_CLOSED_TE) as c:
        assert c.evaluate(0) == pytest.approx((1, 0), abs=1e-12)
        assert c.evaluate(1) == pytest.approx((1, 0), abs=1e-12)  # closed trailing edge
    with pytest.raises(eg2d.ArgumentError):
        eg2d.Curve.naca4("12")
    with pytest.raises(eg2d.FileError, match="missing.dat"):
        eg2d.Curve.read_airfoil(tmp_path / "missing.dat")


def test_distribution_and_first_cell_height():
    np.testing.assert_allclose(eg2d.distribution(eg2d.DIST_UNIFORM, 5), [0, 0.25, 0.5, 0.75, 1], atol=1e-15)
    s = eg2d.distribution(eg2d.DIST_EXPONENTIAL, 5, 2.0)
    assert s[1] == pytest.approx((np.exp(0.5) - 1) / (np.exp(2) - 1), rel=1e-13)
    with pytest.raises(eg2d.ArgumentError):
        eg2d.distribution(eg2d.DIST_EXPONENTIAL, 5, 0.0)
    cf = (2 * np.log10(1e6) - 0.65) ** -2.3
    assert eg2d.first_cell_height(1, 1e6) == pytest.approx(1 / (1e6 * np.sqrt(cf / 2)), rel=1e-12)
    with pytest.raises(eg2d.ArgumentError):
        eg2d.first_cell_height(-1, 1e6)
    assert eg2d.distribution(eg2d.DIST_TANH_ONE, 33, eg2d.distribution_parameter(eg2d.DIST_TANH_ONE, 33, 1e-4))[1] == pytest.approx(1e-4, rel=1e-12)  # noqa: E501


def test_set_side_curve():
    with eg2d.Grid(17, 13) as g, eg2d.Curve.polyline([0, 1], [0, 0]) as c:
        g.set_side_curve(eg2d.SIDE_JMIN, c)
        with pytest.raises(eg2d.ArgumentError):
            g.set_side_curve(9, c)
        g.set_side(eg2d.SIDE_IMIN, np.zeros(13), np.arange(13) / 12)
        with pytest.raises(eg2d.BoundaryError, match="eg2d_set_side_curve"):
            g.set_side_curve(eg2d.SIDE_JMIN, c, flags=eg2d.CURVE_REVERSE)
        g.set_side_curve(eg2d.SIDE_JMIN, c, flags=eg2d.CURVE_ORIENT)


# ---- grid control
def unit_square(n=9):
    s = np.arange(n) / (n - 1)
    g = eg2d.Grid(n, n)
    g.set_side(eg2d.SIDE_JMIN, s, 0 * s)
    g.set_side(eg2d.SIDE_IMAX, 1 + 0 * s, s)
    g.set_side(eg2d.SIDE_JMAX, s, 1 + 0 * s)
    g.set_side(eg2d.SIDE_IMIN, 0 * s, s)
    g.set_tolerance(1e-12)
    return g


def test_sources_and_source_arrays():
    with unit_square() as g:
        g.solve()
        _, y0 = g.get_coordinates()
        with pytest.raises(eg2d.ArgumentError):
            g.add_line_source(5, 0, 100, 0.2)
        g.add_line_source(eg2d.ETA, 0, 1, 0.5)
        g.solve()
        assert g.get_coordinates()[1][4, 1] < y0[4, 1] - 1e-3
        with pytest.raises(eg2d.ArgumentError):
            g.add_point_source(4, 4, 1, -1)
        g.add_point_source(4, 4, 1, 0.5)
        g.clear_sources()
        g.solve()
        np.testing.assert_allclose(g.get_coordinates()[1], y0, atol=1e-9)
        with pytest.raises(eg2d.ArgumentError, match=r"Q has shape \(9, 8\)"):
            g.set_source_arrays(Q=np.zeros((9, 8)))
        g.set_source_arrays(Q=np.full((9, 9), 0.5))
        g.solve()
        np.testing.assert_allclose(g.get_controls()[1][1:-1, 1:-1], 0.5, rtol=1e-13)
        assert g.get_coordinates()[1][4, 4] > y0[4, 4] + 1e-3
        with pytest.raises(eg2d.ArgumentError):
            g.set_source_arrays(P=np.full((9, 9), np.inf))
        g.set_source_arrays()


def test_orthogonality_and_wall_spacing():
    # The swan, whose TFI start is not a Winslow solution (on the unit square it
    # is, and eg2d_solve then stops at iteration 0 before the wall control acts).
    with swan(17, 13) as g:
        with pytest.raises(eg2d.ArgumentError):
            g.set_orthogonality(7)
        with pytest.raises(eg2d.ArgumentError):
            g.set_wall_spacing(9, 0.05)
        with pytest.raises(eg2d.ArgumentError, match="n = 5: side JMIN has 17 nodes"):
            g.set_wall_spacing_nodes(eg2d.SIDE_JMIN, [0.02] * 5)
        g.set_wall_spacing_nodes(eg2d.SIDE_JMIN, [0.03] * 17)
        g.set_wall_spacing_nodes(eg2d.SIDE_JMIN, None)
        g.set_wall_spacing(eg2d.SIDE_JMIN, 0.02)
        g.set_orthogonality(eg2d.ORTHO_WALL)
        g.set_max_iterations(20000)
        g.solve()
        x, y = g.get_coordinates()
        assert abs(y[8, 1] - 0.02) < 1e-6 and abs(x[8, 1] - x[8, 0]) < 1e-6  # on the normal, at 0.02
        g.set_orthogonality(eg2d.ORTHO_NONE)


def test_wall_layer_figures():
    """A straight channel walled top and bottom: the graded layer's figures through get_wall_layer."""
    with eg2d.Grid(33, 65) as g:
        s, t = np.arange(33) / 32, np.arange(65) / 64
        g.set_side(eg2d.SIDE_JMIN, 4 * s, 0 * s)
        g.set_side(eg2d.SIDE_JMAX, 4 * s, 0 * s + 1)
        g.set_side(eg2d.SIDE_IMIN, 0 * t, t)
        g.set_side(eg2d.SIDE_IMAX, 0 * t + 4, t)
        with pytest.raises(eg2d.StateError):
            g.get_wall_layer(eg2d.SIDE_JMIN, eg2d.WALL_GROWTH)
        for side in (eg2d.SIDE_JMIN, eg2d.SIDE_JMAX):
            g.set_wall_spacing(side, 1e-3)
        g.set_orthogonality(eg2d.ORTHO_WALL)
        g.solve()
        for side in (eg2d.SIDE_JMIN, eg2d.SIDE_JMAX):
            assert abs(g.get_wall_layer(side, eg2d.WALL_FIRST_MEDIAN) / 1e-3 - 1) < 1e-9
            assert g.get_wall_layer(side, eg2d.WALL_GROWTH) <= 1.2
            assert g.get_wall_layer(side, eg2d.WALL_ANGLE) < 1e-6
            assert g.get_wall_layer(side, eg2d.WALL_NODES) == 31
            assert g.get_wall_layer(side, eg2d.WALL_NODES_NEEDED) == 0
        with pytest.raises(eg2d.ArgumentError, match="what = 7"):
            g.get_wall_layer(eg2d.SIDE_JMIN, 7)


def test_parameter_grid_clustering_and_weights():
    with pytest.raises(eg2d.ArgumentError):
        eg2d.clustering_map(eg2d.CLUSTER_LINE, 1.5, 9)
    u = eg2d.clustering_map(eg2d.CLUSTER_BOUNDARIES, 0.5, 9)
    assert u[0] == 0 and u[-1] == 1 and np.all(np.diff(u) > 0)
    assert u[1] - u[0] < 0.125 < u[4] - u[3]
    s, t = eg2d.tensor_parameter_grid(np.arange(9) / 8, u)
    assert s.shape == (9, 9) and s.flags["F_CONTIGUOUS"] and s[3, 6] == 3 / 8 and t[3, 6] == u[6]
    with unit_square() as g:
        g.solve()
        x0, y0 = g.get_coordinates()
        with pytest.raises(eg2d.ArgumentError, match=r"t has shape"):
            g.set_parameter_grid(s, t[:, :8])
        g.set_parameter_grid(s, t)
        g.solve()
        y = g.get_coordinates()[1]
        assert y[4, 1] < y0[4, 1] - 1e-3 and y[4, 7] > y0[4, 7] + 1e-3
        g.set_parameter_grid()
        g.set_weight(np.ones((9, 9)))
        g.solve()
        x, y = g.get_coordinates()
        assert abs(x - x0).max() + abs(y - y0).max() < 1e-9
        w = np.ones((9, 9))
        w[3, 3] = 0
        with pytest.raises(eg2d.ArgumentError):
            g.set_weight(w)
        g.set_weight(None)


def test_patches_and_su2(tmp_path):
    """Patches through the Python wrapper; the SU2 file carries them (read with
    the file's own MARKER_TAG lines, meshio's check is tests/io)."""
    with swan(9, 7) as g:
        assert g.get_patches() == [(eg2d.SIDE_JMIN, 0, 8, eg2d.PATCH_WALL, "jmin"),
                                   (eg2d.SIDE_IMAX, 0, 6, eg2d.PATCH_WALL, "imax"),
                                   (eg2d.SIDE_JMAX, 0, 8, eg2d.PATCH_WALL, "jmax"),
                                   (eg2d.SIDE_IMIN, 0, 6, eg2d.PATCH_WALL, "imin")]
        g.set_patch(eg2d.SIDE_IMIN, 0, 6, eg2d.PATCH_INFLOW, "inlet")
        with pytest.raises(eg2d.ArgumentError, match="overlap patch \"inlet\""):
            g.set_patch(eg2d.SIDE_IMIN, 3, 5, eg2d.PATCH_WALL, "x")
        assert g.get_patches()[-1] == (eg2d.SIDE_IMIN, 0, 6, eg2d.PATCH_INFLOW, "inlet")
        g.solve()
        g.write(str(tmp_path / "g.su2"), eg2d.FORMAT_SU2)
        text = (tmp_path / "g.su2").read_text()
        assert "NELEM= 48\n" in text and "NPOIN= 63\n" in text
        assert "MARKER_TAG= inlet\nMARKER_ELEMS= 6\n" in text
        g.clear_patches()
        assert len(g.get_patches()) == 4
