"""Curve: a plane curve r(t), t in [0, 1], with its arc length (eg2d_curve_*),
freed by close(), by the end of a `with` block, or when collected.

    with eg2d.Curve.naca4("0012", eg2d.NACA_CLOSED_TE) as c:
        x, y = c.points(129, eg2d.DIST_TANH_TWO, 4.0, 0.5)
        g.set_side_curve(eg2d.SIDE_JMIN, c, eg2d.DIST_UNIFORM)
"""
import math
import os
from ctypes import byref, c_double, c_void_p

import numpy as np

from . import constants as C
from ._capi import curve_fn, lib
from ._handle import Handle
from .errors import error_for
from .functions import _check, _dp


def _pair(x, y):
    x = np.ascontiguousarray(x, dtype=np.float64)
    y = np.ascontiguousarray(y, dtype=np.float64)
    if x.ndim != 1 or x.shape != y.shape:
        raise error_for(C.ERR_ARGUMENT, f"x has shape {x.shape}, y {y.shape}: need two equal 1-D arrays")
    return x, y


class Curve(Handle):
    def __init__(self, make, keep=None):
        """Use the class methods (polyline, spline, function, naca4, read_airfoil)."""
        super().__init__()
        self._keep = keep  # a callback the curve calls: alive as long as the curve
        self._error = None
        _check(make(byref(self._h)))

    @classmethod
    def polyline(cls, x, y):
        """Straight segments through the points."""
        x, y = _pair(x, y)
        return cls(lambda out: lib.eg2d_curve_polyline(len(x), _dp(x), _dp(y), out))

    @classmethod
    def spline(cls, x, y):
        """The cubic spline through the points (periodic when the last repeats the first)."""
        x, y = _pair(x, y)
        return cls(lambda out: lib.eg2d_curve_spline(len(x), _dp(x), _dp(y), out))

    @classmethod
    def function(cls, fn):
        """A user curve: fn(t) -> (x, y) for t in [0, 1], smooth. An exception in
        fn makes the point NaN (the library then fails the call) and is re-raised."""
        holder = {}

        def call(_user, t, x, y):
            try:
                x[0], y[0] = fn(t)
            except BaseException as e:  # cannot cross C
                holder["curve"]._error = e
                x[0] = y[0] = math.nan

        cb = curve_fn(call)
        self = cls.__new__(cls)
        self._h, self._keep, self._error = c_void_p(), cb, None
        holder["curve"] = self
        self._call(lib.eg2d_curve_function(cb, None, byref(self._h)))
        return self

    @classmethod
    def naca4(cls, digits, flags=0):
        """A NACA 4-digit section ("0012"), chord 1; flags NACA_CLOSED_TE or 0."""
        return cls(lambda out: lib.eg2d_curve_naca4(str(digits).encode(), int(flags), out))

    @classmethod
    def read_airfoil(cls, path):
        """An airfoil from a Selig or Lednicer coordinate file."""
        return cls(lambda out: lib.eg2d_curve_read_airfoil(os.fsencode(path), out))

    def _call(self, status):
        err, self._error = self._error, None
        if err is not None:
            raise err
        _check(status)

    _kind = "curve"

    def _destroy(self, h):
        lib.eg2d_curve_destroy(h)

    def length(self):
        v = c_double()
        self._call(lib.eg2d_curve_length(self._handle(), byref(v)))
        return v.value

    def evaluate(self, s):
        """The point (x, y) at normalized arc length s in [0, 1]."""
        x, y = c_double(), c_double()
        self._call(lib.eg2d_curve_evaluate(self._handle(), float(s), byref(x), byref(y)))
        return x.value, y.value

    def points(self, n, distribution=C.DIST_UNIFORM, p1=0.0, p2=0.0):
        """n points at the normalized arc lengths of a distribution: (x, y) arrays."""
        x, y = np.empty(int(n)), np.empty(int(n))
        self._call(lib.eg2d_curve_points(self._handle(), int(n), int(distribution), float(p1), float(p2),
                                         _dp(x), _dp(y)))
        return x, y
