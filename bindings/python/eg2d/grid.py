"""Grid: one eg2d grid handle, freed by close(), by the end of a `with`
block, or when the object is collected.

    with eg2d.Grid(65, 65) as g:
        g.set_side(eg2d.SIDE_JMIN, xb, yb)     # ... the four sides
        g.solve()
        x, y = g.get_coordinates()             # numpy (ni, nj), Fortran order

Every failed call raises eg2d.Error (a subclass per status) with the
library's message; the grid is left as it was (runs keep their iterations,
see eg2d.h). Node (i, j) of the C manual is x[i, j].
"""
import os
from ctypes import POINTER, byref, c_double, c_int, create_string_buffer

import numpy as np

from . import constants as C
from ._capi import lib, monitor_fn
from ._handle import Handle
from .errors import Error, error_for
from .functions import _text, last_error

_double_p = POINTER(c_double)


def _vector(a, n, name):
    v = np.ascontiguousarray(a, dtype=np.float64)
    if v.shape != (n,):
        raise error_for(C.ERR_ARGUMENT, f"{name} has shape {v.shape}: the side has {n} points")
    return v


def _field(a, ni, nj, name):
    v = np.asfortranarray(a, dtype=np.float64)
    if v.shape != (ni, nj):
        raise error_for(C.ERR_ARGUMENT, f"{name} has shape {v.shape}: must be (ni, nj) = ({ni}, {nj})")
    return v


def _ptr(v):
    return v.ctypes.data_as(_double_p)


class Grid(Handle):
    """An ni x nj grid (one eg2d_grid handle).

    Threads: one call at a time on a Grid, from whatever thread (a hand-over
    between threads must be synchronised); different Grids run in parallel,
    since each ctypes call releases the GIL. The GIL does not serialise two
    threads' calls on one Grid: guard a shared Grid with a threading.Lock.
    The monitor runs on the calling thread inside iterate/solve and may only
    query this grid. See the package docstring and eg2d.h's "Threads".
    """

    def __init__(self, ni, nj):
        super().__init__()
        self._monitor = None  # keeps the ctypes callback alive while installed
        self._monitor_error = None
        status = lib.eg2d_create(int(ni), int(nj), byref(self._h))
        if status:
            raise error_for(status, last_error())

    _kind = "grid"

    def _destroy(self, h):
        lib.eg2d_destroy(h)

    def _check(self, status):
        if status:
            raise error_for(status, self.last_error)

    @property
    def last_error(self):
        """The message of the last failed call on this grid ("" if none)."""
        return _text(lib.eg2d_last_error(self._h)) if self._h else ""

    # ---- topology
    def set_topology(self, topology):
        self._check(lib.eg2d_set_topology(self._handle(), int(topology)))

    def get_topology(self):
        t = c_int()
        self._check(lib.eg2d_get_topology(self._handle(), byref(t)))
        return t.value

    def get_cut(self):
        """C-grid: the trailing edge's index w on JMIN; nodes i and ni-1-i of JMIN are one point for i <= w."""
        w = c_int()
        self._check(lib.eg2d_get_cut(self._handle(), byref(w)))
        return w.value

    # ---- boundary and initial grid
    def set_side(self, side, x, y):
        """One side from its points in increasing index (ni points for JMIN/JMAX, nj for IMIN/IMAX)."""
        ni, nj = self.get_size()
        n = {C.SIDE_JMIN: ni, C.SIDE_JMAX: ni, C.SIDE_IMIN: nj, C.SIDE_IMAX: nj}.get(side)
        if n is None:  # the library reports an unknown side
            self._check(lib.eg2d_set_side(self._handle(), int(side), None, None))
        x, y = _vector(x, n, "x"), _vector(y, n, "y")
        self._check(lib.eg2d_set_side(self._handle(), int(side), _ptr(x), _ptr(y)))

    def set_interior_line(self, direction, index, x, y):
        """Holds the column i = index (direction XI, nj points) or the row j = index (ETA, ni
        points) on the given points: TFI passes through them and every solver keeps them fixed."""
        ni, nj = self.get_size()
        n = {C.XI: nj, C.ETA: ni}.get(direction)
        if n is None:  # the library reports an unknown direction
            self._check(lib.eg2d_set_interior_line(self._handle(), int(direction), int(index), None, None))
        x, y = _vector(x, n, "x"), _vector(y, n, "y")
        self._check(lib.eg2d_set_interior_line(self._handle(), int(direction), int(index), _ptr(x), _ptr(y)))

    def clear_interior_lines(self):
        self._check(lib.eg2d_clear_interior_lines(self._handle()))

    def set_boundary(self, x, y):
        """The boundary ring from whole (ni, nj) arrays; only boundary nodes are read."""
        ni, nj = self.get_size()
        x, y = _field(x, ni, nj, "x"), _field(y, ni, nj, "y")
        self._check(lib.eg2d_set_boundary(self._handle(), _ptr(x), _ptr(y)))

    def initialize(self, method=C.INIT_TFI):
        self._check(lib.eg2d_initialize(self._handle(), int(method)))

    def set_coordinates(self, x, y):
        """A whole start grid, (ni, nj) arrays, boundary included."""
        ni, nj = self.get_size()
        x, y = _field(x, ni, nj, "x"), _field(y, ni, nj, "y")
        self._check(lib.eg2d_set_coordinates(self._handle(), _ptr(x), _ptr(y)))

    # ---- settings
    def set_system(self, system):
        self._check(lib.eg2d_set_system(self._handle(), int(system)))

    def set_solver(self, solver):
        self._check(lib.eg2d_set_solver(self._handle(), int(solver)))

    def get_solver(self):
        s = c_int()
        self._check(lib.eg2d_get_solver(self._handle(), byref(s)))
        return s.value

    def set_relaxation(self, omega):
        self._check(lib.eg2d_set_relaxation(self._handle(), float(omega)))

    def set_tolerance(self, tolerance):
        self._check(lib.eg2d_set_tolerance(self._handle(), float(tolerance)))

    def set_max_iterations(self, max_iterations):
        self._check(lib.eg2d_set_max_iterations(self._handle(), int(max_iterations)))

    def set_parameter(self, param, value):
        self._check(lib.eg2d_set_parameter(self._handle(), int(param), float(value)))

    def get_parameter(self, param):
        v = c_double()
        self._check(lib.eg2d_get_parameter(self._handle(), int(param), byref(v)))
        return v.value

    def set_af_cycle(self, dtau_min, dtau_max=0.0, steps=0):
        """The AF pseudo-time-step cycle (0 = automatic for dtau_max and steps)."""
        self._check(lib.eg2d_set_af_cycle(self._handle(), float(dtau_min), float(dtau_max), int(steps)))

    def set_af_time_rule(self, a, b):
        """The Warming-Beam time rule of AF (Ly & Norrison (2007), Table 1)."""
        self._check(lib.eg2d_set_af_time_rule(self._handle(), float(a), float(b)))

    # ---- grid control
    def add_line_source(self, direction, line, amplitude, decay):
        """Thompson's attraction of the XI or ETA lines toward `line` (index units)."""
        self._check(lib.eg2d_add_line_source(self._handle(), int(direction), float(line), float(amplitude),
                                             float(decay)))

    def add_point_source(self, xi, eta, amplitude, decay):
        self._check(lib.eg2d_add_point_source(self._handle(), float(xi), float(eta), float(amplitude),
                                              float(decay)))

    def clear_sources(self):
        self._check(lib.eg2d_clear_sources(self._handle()))

    def _optional_fields(self, **arrays):
        ni, nj = self.get_size()
        return [None if a is None else _field(a, ni, nj, name) for name, a in arrays.items()]

    def set_source_arrays(self, P=None, Q=None):
        """The user's P, Q (ni, nj); None is zero; both None remove them."""
        P, Q = self._optional_fields(P=P, Q=Q)
        self._check(lib.eg2d_set_source_arrays(self._handle(), P if P is None else _ptr(P),
                                               Q if Q is None else _ptr(Q)))

    def set_orthogonality(self, method):
        self._check(lib.eg2d_set_orthogonality(self._handle(), int(method)))

    def set_wall_spacing(self, side, height):
        self._check(lib.eg2d_set_wall_spacing(self._handle(), int(side), float(height)))

    def set_wall_spacing_nodes(self, side, heights):
        """First-cell heights node by node along `side` (one per node); None
        makes the side no wall."""
        if heights is None:
            self._check(lib.eg2d_set_wall_spacing_nodes(self._handle(), int(side), 0, None))
            return
        h = np.ascontiguousarray(heights, dtype=np.float64).ravel()
        self._check(lib.eg2d_set_wall_spacing_nodes(self._handle(), int(side), len(h), _ptr(h)))

    def set_parameter_grid(self, s=None, t=None):
        """Khattri's (2006) parameter-space grid s, t (ni, nj); both None remove it."""
        s, t = self._optional_fields(s=s, t=t)
        self._check(lib.eg2d_set_parameter_grid(self._handle(), s if s is None else _ptr(s),
                                                t if t is None else _ptr(t)))

    def set_weight(self, w):
        """Weight-function adaptivity, w (ni, nj) > 0; None removes it."""
        (w,) = self._optional_fields(w=w)
        self._check(lib.eg2d_set_weight(self._handle(), w if w is None else _ptr(w)))

    # ---- running
    def set_monitor(self, fn):
        """fn(iteration, residual) after every iteration; a true result stops
        the run (eg2d.StoppedByMonitor). An exception in fn stops the run and
        is re-raised by iterate/solve. None removes the monitor."""
        if fn is None:
            self._check(lib.eg2d_set_monitor(self._handle(), monitor_fn(), None))
            self._monitor = None
            return

        def call(_user, iteration, residual):
            try:
                return 1 if fn(iteration, residual) else 0
            except BaseException as e:  # cannot cross C: keep it for the caller
                self._monitor_error = e
                return 1

        cb = monitor_fn(call)
        self._check(lib.eg2d_set_monitor(self._handle(), cb, None))
        self._monitor = cb

    def _run(self, status):
        err, self._monitor_error = self._monitor_error, None
        if err is not None:
            raise err
        self._check(status)

    def iterate(self, iterations):
        """Exactly `iterations` iterations; returns the residual after them."""
        r = c_double()
        self._run(lib.eg2d_iterate(self._handle(), int(iterations), byref(r)))
        return r.value

    def solve(self):
        self._run(lib.eg2d_solve(self._handle()))

    # ---- queries
    def get_size(self):
        ni, nj = c_int(), c_int()
        self._check(lib.eg2d_get_size(self._handle(), byref(ni), byref(nj)))
        return ni.value, nj.value

    @property
    def shape(self):
        return self.get_size()

    def get_coordinates(self):
        """(x, y): numpy arrays (ni, nj) in Fortran order, x[i, j] at node (i, j)."""
        ni, nj = self.get_size()
        x = np.empty((ni, nj), dtype=np.float64, order="F")
        y = np.empty((ni, nj), dtype=np.float64, order="F")
        self._check(lib.eg2d_get_coordinates(self._handle(), _ptr(x), _ptr(y)))
        return x, y

    def get_residual(self):
        r = c_double()
        self._check(lib.eg2d_get_residual(self._handle(), byref(r)))
        return r.value

    def get_iterations(self):
        n = c_int()
        self._check(lib.eg2d_get_iterations(self._handle(), byref(n)))
        return n.value

    def get_run_info(self, what):
        """What the last iterate/solve ran: what is RUN_SOLVER, RUN_LEVELS, RUN_LEVELS_BUILT or RUN_EVENTS."""
        v = c_int()
        self._check(lib.eg2d_get_run_info(self._handle(), int(what), byref(v)))
        return v.value

    def get_run_events(self):
        """The last run's changes of strategy, as (iteration, message) pairs."""
        out = []
        buf = create_string_buffer(512)
        for k in range(self.get_run_info(C.RUN_EVENTS)):
            it = c_int()
            self._check(lib.eg2d_get_run_event(self._handle(), k, byref(it), buf, len(buf)))
            out.append((it.value, buf.value.decode()))
        return out

    def set_patch(self, side, first, last, type, name):
        """Names and types nodes first..last of a side (PATCH_* type) for the solver-ready formats."""
        self._check(lib.eg2d_set_patch(self._handle(), int(side), int(first), int(last), int(type), name.encode()))

    def clear_patches(self):
        """Back to the topology's default patches."""
        self._check(lib.eg2d_clear_patches(self._handle()))

    def get_patches(self):
        """The whole boundary as the writers see it: (side, first, last, type, name) per stretch."""
        n = c_int()
        self._check(lib.eg2d_get_patch_count(self._handle(), byref(n)))
        out = []
        buf = create_string_buffer(64)
        for k in range(n.value):
            v = [c_int() for _ in range(4)]
            self._check(lib.eg2d_get_patch(self._handle(), k, *(byref(x) for x in v), buf, len(buf)))
            out.append((v[0].value, v[1].value, v[2].value, v[3].value, buf.value.decode()))
        return out

    def get_quality(self, metric):
        v = c_double()
        self._check(lib.eg2d_get_quality(self._handle(), int(metric), byref(v)))
        return v.value

    def get_wall_layer(self, side, what):
        """A figure of the wall layer at a side (WALL_*: first cells, growth, angle, nodes)."""
        v = c_double()
        self._check(lib.eg2d_get_wall_layer(self._handle(), int(side), int(what), byref(v)))
        return v.value

    def get_cell_quality(self, metric):
        """Per-cell values of a metric: numpy (ni-1, nj-1), Fortran order."""
        ni, nj = self.get_size()
        v = np.empty((ni - 1, nj - 1), dtype=np.float64, order="F")
        self._check(lib.eg2d_get_cell_quality(self._handle(), int(metric), _ptr(v)))
        return v

    def get_controls(self):
        """The control terms as Thompson's (P, Q) per node: numpy (ni, nj), Fortran order."""
        ni, nj = self.get_size()
        P = np.empty((ni, nj), dtype=np.float64, order="F")
        Q = np.empty_like(P, order="F")
        self._check(lib.eg2d_get_controls(self._handle(), _ptr(P), _ptr(Q)))
        return P, Q

    def set_side_curve(self, side, curve, distribution=C.DIST_UNIFORM, p1=0.0, p2=0.0, flags=0):
        """The side's points on an eg2d.Curve with a distribution and CURVE_* flags."""
        self._check(lib.eg2d_set_side_curve(self._handle(), int(side), curve._handle(), int(distribution),
                                            float(p1), float(p2), int(flags)))

    def set_airfoil(self, section, topology=C.TOPO_C):
        """Topology (TOPO_O or TOPO_C) and the whole boundary of an airfoil grid
        round the eg2d.Curve `section` (PARAM_AIRFOIL_* set the far field,
        spacings, cut nodes and trailing edge)."""
        self._check(lib.eg2d_set_airfoil(self._handle(), section._handle(), int(topology)))

    # ---- files
    def write(self, path, format):
        """Writes the grid to path as FORMAT_* (| PLOT3D_* flags)."""
        self._check(lib.eg2d_write(self._handle(), os.fsencode(path), int(format)))

    def set_side_from_file(self, side, path):
        """A side from a point file of exactly ni or nj points."""
        self._check(lib.eg2d_set_side_from_file(self._handle(), int(side), os.fsencode(path)))


__all__ = ["Grid", "Error"]
